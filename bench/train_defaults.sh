#!/usr/bin/env bash
# What `fogdrift train` with its defaults costs where users meet it (issue 60; docs/tuning.md, "A
# search that stops when it stops learning", "A search on fewer rows"), beside the search it
# replaced (the whole 20 × 50 budget on every row: --stall-iterations 0 --search-rows 0), on
# two threads:
#   - the default campaign (`simulate calibration --seed 3`, the paper's 3 + 1 sweeps);
#   - the seven-sweep campaign docs/field.md recommends (same seed);
#   - the paper's protocol on each of the first N instruments of `simulate population --seed 2`
#     (new defaults only, one run each).
# Prints a Markdown row per run: wall seconds (median of RUNS), iterations, status, stride,
# fits, C, σ and the cv RMSE of the chosen model on all rows.
# Usage: bench/train_defaults.sh [BUILD_DIR] [RUNS] [N] [OLD_RUNS] [OLD_SEVEN_RUNS]
#   (default build/, 3 runs, 10 instruments, 1 run of the old search on the default campaign and
#   none on the seven-sweep one, where it takes 7 minutes; 0 skips either)
# Environment: TRAIN_DEFAULTS_UNIT_RUNS, the runs on each instrument (1); TRAIN_DEFAULTS_COMPARE,
#   train flags of a second search run once on every campaign right after its defaults', e.g.
#   "--smo-iterations-per-row 0" for the search without the cap on its fits (none).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
runs=${2:-3}
count=${3:-10}
old_runs=${4:-1}
old_seven_runs=${5:-0}
unit_runs=${TRAIN_DEFAULTS_UNIT_RUNS:-1}
read -r -a compare <<<"${TRAIN_DEFAULTS_COMPARE:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$fd" simulate calibration --force --out "$work/paper" --seed 3 >/dev/null
"$fd" simulate calibration --force --out "$work/seven" --seed 3 --repetitions 7 \
  --approach calibration,soaked,warm,ramping,warm,warm,calibration >/dev/null
"$fd" simulate population --force --out "$work/units" --count "$count" --seed 2 >/dev/null
for k in $(seq 1 "$count"); do
  unit=$(printf 'unit_%02d' "$k")
  "$fd" simulate calibration --force --out "$work/$unit" --seed "$k" \
    --instrument "$work/units/$unit.json" >/dev/null
done

# One campaign, one search: RUNS timed trains, the median's row.
measure() { # $1 label, $2 campaign, $3 runs, then extra train flags
  local label=$1 camp=$2 n=$3
  shift 3
  local i
  for i in $(seq 1 "$n"); do
    "$fd" train "$camp" --threads 2 --json -o "$work/m.json" "$@" >"$work/t$i.json"
  done
  python3 - "$label" "$work" "$n" <<'PY'
import json, statistics, sys
label, work, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
runs = [json.load(open(f"{work}/t{i}.json")) for i in range(1, n + 1)]
seconds = [r["seconds"] for r in runs]
r = runs[0]
s, h = r["search"], r["hyperparameters"]
print(f"| {label} | {r['training_rows']} | {statistics.median(seconds):.1f} "
      f"({', '.join(f'{x:.1f}' for x in seconds)}) | {s['iterations']} | {s.get('status', '')} | "
      f"{s.get('row_stride', 1)} | {s['fits']} | {h['C']:.4g} | {h['sigma']:.3g} | "
      f"{r['fitness_rmse']:.5f} |")
PY
}

echo "| campaign and search | training rows | wall s, median (runs) | iterations | status | stride | fits | C | σ | cv RMSE |"
echo "|---|---|---|---|---|---|---|---|---|---|"
# measure, then once with TRAIN_DEFAULTS_COMPARE's flags when there are any.
measure_and_compare() { # $1 label, $2 campaign, $3 runs
  measure "$1, defaults" "$2" "$3"
  if ((${#compare[@]} > 0)); then
    measure "$1, ${compare[*]}" "$2" 1 "${compare[@]}"
  fi
}

measure_and_compare "default campaign" "$work/paper" "$runs"
if ((old_runs > 0)); then
  measure "default campaign, whole budget on every row" "$work/paper" "$old_runs" \
    --stall-iterations 0 --search-rows 0
fi
measure_and_compare "seven sweeps" "$work/seven" "$runs"
if ((old_seven_runs > 0)); then
  measure "seven sweeps, whole budget on every row" "$work/seven" "$old_seven_runs" \
    --stall-iterations 0 --search-rows 0
fi
for k in $(seq 1 "$count"); do
  unit=$(printf 'unit_%02d' "$k")
  measure_and_compare "population seed 2, $unit, paper's protocol" "$work/$unit" "$unit_runs"
done
