#!/usr/bin/env bash
# Defaults on a population of instruments (docs/field.md, "Instruments unlike ours"): draws N
# instruments (fogdrift simulate population), and for each one runs a field calibration (by
# default the five-sweep protocol: calibration, soaked, warm, ramping start-ups, then the
# test), trains with train's defaults, batch (centred rates) and causal, and measures on four
# north-finding campaigns, one per start-up condition, the share of the removable
# north-finding error removed, guard on and off, on the RMSEs and finding by finding, and
# train's own held-out expectation. Prints one Markdown row per instrument and the
# distribution (median, 10th percentile, worst) per condition, path and guard.
# Usage: bench/population_study.sh [BUILD_DIR] [N] [SEED] [JOBS] [TRAIN_FLAGS...]
#   (default build/, 20 instruments, seed 1, 2 instruments at a time); extra flags go to
#   `fogdrift train` (the study in docs/field.md passed a smaller search budget,
#   --population 10 --iterations 15, to fit a 2-core session: say so when quoting it).
# Each instrument's rows also land in $POPULATION_OUT (default: a temporary folder) as JSON.
# $POPULATION_WORK, if set, keeps the instruments, campaigns and models there for a later look.
# $POPULATION_UNITS, if set, runs only those instruments (numbers 1..N, separated by spaces or
# commas), replacing what an earlier run left of them in $POPULATION_WORK and $POPULATION_OUT;
# the summary covers every instrument with a row in $POPULATION_OUT.
# $POPULATION_CAL_APPROACHES and $POPULATION_CAL_REPETITIONS, if set, replace the calibration
# protocol (default calibration,soaked,warm,ramping over 5 repetitions; docs/field.md, "Three
# warm sweeps", ran calibration,soaked,warm,ramping,warm,warm,calibration over 7);
# $POPULATION_CAL_TEMPS, if set, replaces its set points (°C, comma-separated; default the
# paper's eleven, -40 to 60 by 10), and $POPULATION_CAL_START_UP_TEMPS those of its soaked, warm
# and ramping sweeps alone (default: the same; docs/field.md, "Protocols worth their hours").
# $POPULATION_SEARCH_SEED_OFFSET, if set, trains instrument k with `--seed k + offset` instead
# of `--seed k`: the same campaigns, other search seeds (how much of a study is the search's
# luck; docs/field.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
count=${2:-20}
seed=${3:-1}
jobs=${4:-2}
shift $(($# < 4 ? $# : 4))
search_seed_offset=${POPULATION_SEARCH_SEED_OFFSET:-0}
if ! [[ $search_seed_offset =~ ^[0-9]+$ ]]; then
  echo "population_study.sh: POPULATION_SEARCH_SEED_OFFSET: '$search_seed_offset' is not a whole number ≥ 0" >&2
  exit 2
fi
if [[ -n ${POPULATION_WORK:-} ]]; then
  work=$POPULATION_WORK
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
out=${POPULATION_OUT:-$work/results}
# North-finding start-ups per condition: 18 temperatures across the range, 5 findings each, 90
# findings a condition (docs/field.md, "Ninety findings a condition"). The share of a small
# removable error is a ratio of two small numbers, and a mean over 35 findings (the paper's 7
# temperatures, POPULATION_NF_TEMPS=-32,-16,-5,17,28,43,54, as before 2026-11-26) scatters 1.6
# times as much as one over 90.
nf_temps=${POPULATION_NF_TEMPS:--38,-32,-27,-21,-16,-10,-5,1,6,12,17,23,28,34,39,45,50,56}
cal_approaches=${POPULATION_CAL_APPROACHES:-calibration,soaked,warm,ramping}
cal_repetitions=${POPULATION_CAL_REPETITIONS:-5}
cal_temps=${POPULATION_CAL_TEMPS:--40,-30,-20,-10,0,10,20,30,40,50,60}
cal_start_up_temps=${POPULATION_CAL_START_UP_TEMPS:-$cal_temps}
if ! [[ $cal_repetitions =~ ^[0-9]+$ ]] || ((cal_repetitions < 2)); then
  echo "population_study.sh: POPULATION_CAL_REPETITIONS: '$cal_repetitions' is not a whole number ≥ 2" >&2
  exit 2
fi
mkdir -p "$out"
"$fd" simulate population --force --out "$work/units" --count "$count" --seed "$seed" >/dev/null

one() { # one instrument: $1 = its number; a failed step fails the instrument, not silently
  set -euo pipefail
  local k=$1 unit d
  unit=$(printf 'unit_%02d' "$k")
  d="$work/$unit"
  mkdir -p "$d"
  local inst="$work/units/$unit.json" start=$SECONDS
  "$fd" simulate calibration --force --out "$d/cal" --seed "$k" --repetitions "$cal_repetitions" \
    --approach "$cal_approaches" --temps="$cal_temps" \
    --start-up-temps="$cal_start_up_temps" --instrument "$inst" >/dev/null
  for a in calibration soaked warm ramping; do
    "$fd" simulate northfind --force --out "$d/nf_$a" --seed "$k" --approach "$a" \
      --temps "$nf_temps" --instrument "$inst" >/dev/null
  done
  local sim_s=$((SECONDS - start))
  for path in centred causal; do
    start=$SECONDS
    "$fd" train "$d/cal" --differentiator "$path" --seed "$((k + search_seed_offset))" --threads 1 --json \
      -o "$d/$path.json" "${TRAIN_FLAGS[@]}" >"$d/$path.train.json"
    echo $((SECONDS - start)) >"$d/$path.seconds"
    for a in calibration soaked warm ramping; do
      "$fd" northfind "$d/nf_$a" --model "$d/$path.json" --json >"$d/$path.$a.on.json"
      "$fd" northfind "$d/nf_$a" --model "$d/$path.json" --json --no-guard \
        >"$d/$path.$a.off.json"
    done
  done
  rm -f "$out/$unit.json"  # no row from an earlier run survives a failed one
  python3 - "$d" "$k" "$sim_s" >"$out/$unit.json.part" <<'PY'
import json, sys
d, k, sim_s = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
row = {"unit": k, "simulate_s": sim_s}
for path in ("centred", "causal"):
    t = json.load(open(f"{d}/{path}.train.json"))
    row[f"{path}.train_s"] = int(open(f"{d}/{path}.seconds").read())
    row[f"{path}.expected"] = t["held_out"].get("expected_share")
    row[f"{path}.expected_startup"] = t["held_out"].get("expected_startup_share")
    row[f"{path}.startup_warning"] = any("within a start-up" in w
                                         for w in t["held_out"].get("warnings", []))
    for a in ("calibration", "soaked", "warm", "ramping"):
        for g in ("on", "off"):
            n = json.load(open(f"{d}/{path}.{a}.{g}.json"))
            row[f"{path}.{a}.{g}"] = n["table3"].get("removable_error_removed")
            row[f"{path}.{a}.{g}.paired"] = n["table3"].get("drift_error_removed")
        # How much of the raw error the drift makes: (raw² − floor²) / raw², pooled as the
        # share is. Near 0 the share removed is a ratio of two small numbers.
        t3 = n["table3"]
        raw = sum(t3["raw_rmse_deg"]) / len(t3["raw_rmse_deg"])
        floor = sum(t3["true_drift_subtracted_rmse_deg"]) / len(t3["raw_rmse_deg"])
        row[f"{path}.{a}.drift_part"] = (raw * raw - floor * floor) / (raw * raw)
print(json.dumps(row))
PY
  mv "$out/$unit.json.part" "$out/$unit.json"
  echo "unit $k done" >&2
}
export -f one
export fd work out nf_temps cal_approaches cal_repetitions cal_temps cal_start_up_temps search_seed_offset
TRAIN_FLAGS=("$@")
export TRAIN_FLAGS_STR="${*:-}"
units=${POPULATION_UNITS:-$(seq -s ' ' "$count")}
for k in ${units//,/ }; do
  if ! [[ $k =~ ^[0-9]+$ ]] || ((k < 1 || k > count)); then
    echo "population_study.sh: POPULATION_UNITS: '$k' is not an instrument number in 1..$count" >&2
    exit 2
  fi
done
status=0
echo ${units//,/ } | tr ' ' '\n' |
  xargs -P "$jobs" -I{} bash -c 'TRAIN_FLAGS=($TRAIN_FLAGS_STR); one {}' || status=$?

python3 - "$out" <<'PY' || { ((status)) || status=1; }
import glob, json, math, sys
rows = sorted((json.load(open(f)) for f in glob.glob(sys.argv[1] + "/unit_*.json")),
              key=lambda r: r["unit"])
if not rows:
    sys.exit("no instrument finished; nothing to summarise")
conds = ("calibration", "soaked", "warm", "ramping")
def pct(v):
    return "n/a" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{100 * v:.0f}"
print("| unit | path | expected (start-up) | "
      + " | ".join(f"{c} on / off, paired on (drift part)" for c in conds)
      + " | train, s |")
print("|---|---|---|" + "---|" * len(conds) + "---|")
for r in rows:
    for path in ("centred", "causal"):
        cells = [f"{pct(r[f'{path}.{c}.on'])} / {pct(r[f'{path}.{c}.off'])}, "
                 f"{pct(r.get(f'{path}.{c}.on.paired'))} ({pct(r[f'{path}.{c}.drift_part'])})"
                 for c in conds]
        print(f"| {r['unit']} | {path} | {pct(r[f'{path}.expected'])} ({pct(r[f'{path}.expected_startup'])}) | "
              + " | ".join(cells) + f" | {r[f'{path}.train_s']} |")
print()
def quantile(v, q):  # linear interpolation between order statistics
    v = sorted(v)
    x = q * (len(v) - 1)
    i = int(math.floor(x))
    return v[i] if i + 1 >= len(v) else v[i] + (x - i) * (v[i + 1] - v[i])
def table(title, keep, measure=""):
    print(title)
    print()
    print("| path | guard | " + " | ".join(conds) + " | worse than raw |")
    print("|---|---|" + "---|" * len(conds) + "---|")
    for path in ("centred", "causal"):
        for g in ("on", "off"):
            cells, worse = [], 0
            for c in conds:
                key = f"{path}.{c}.{g}{measure}"
                v = [r[key] for r in rows if r.get(key) is not None and keep(r, path, c)]
                worse += sum(x < 0 for x in v)
                cells.append(f"{pct(quantile(v, .5))} / {pct(quantile(v, .1))} / {pct(min(v))} (n = {len(v)})"
                             if v else "n/a")
            print(f"| {path} | {g} | " + " | ".join(cells) + f" | {worse} |")
    print()
table(f"Share of the removable north-finding error removed over {len(rows)} instruments, %"
      " (median / 10th percentile / worst):", lambda r, p, c: True)
table("The share of the drift's own error removed, finding by finding (1 − Σ(comp − floor)² /"
      " Σ(raw − floor)², docs/field.md \"Finding by finding\"), %:", lambda r, p, c: True, ".paired")
table("The same where the drift makes at least a quarter of the raw error's square"
      " ((raw² − floor²) / raw² ≥ 0.25):", lambda r, p, c: r[f"{p}.{c}.drift_part"] >= 0.25)
table("The same where train does not warn that the model may not help the north-finder"
      " (its expected share within a start-up is high enough):",
      lambda r, p, c: not r[f"{p}.startup_warning"])
t = [r[f"{p}.train_s"] for r in rows for p in ("centred", "causal")]
print(f"train: median {quantile(t, .5):.0f} s, longest {max(t)} s (one thread); simulate: median "
      f"{quantile([r['simulate_s'] for r in rows], .5):.0f} s per instrument")
PY
if ((status != 0)); then
  echo "population_study.sh: some instruments failed (their errors are above); the summary leaves them out" >&2
  exit "$status"
fi
