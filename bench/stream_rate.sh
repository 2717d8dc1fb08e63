#!/usr/bin/env bash
# Streaming and batch compensation at a logger's rate (docs/compensation.md, "Any sample rate"):
# a 1 Hz causal SSA-SVR (fogdrift train's defaults, guard on) on 30-minute start-ups logged at
# 1, 10, 100, 1000 and 2000 Hz; wall time of `fogdrift stream` and `fogdrift compensate`, median
# of RUNS. Beside them the floor: reading the file once at the speed of memory (`cat` from the
# page cache to /dev/null, which every command that reads the file pays at least).
# The peer is the same model without its recorded interval (the model file before it), which runs
# its filters at the data's own rate: at 10 Hz only (at 100 Hz its set-up alone takes hours).
# Usage: bench/stream_rate.sh [BUILD_DIR] [RUNS]   (default build/, 3); prints a Markdown table.
set -euo pipefail
shopt -s inherit_errexit
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
runs=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$fd" simulate calibration --out "$work/cal" --seed 1 >/dev/null
"$fd" train "$work/cal" --differentiator causal -q -o "$work/model.json"
# The same model as a file written before models recorded their interval.
python3 - "$work/model.json" "$work/legacy.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
del m["features"]["sample_interval_s"]
json.dump(m, open(sys.argv[2], "w"), indent=1)
PY
"$fd" simulate --print-instrument >"$work/inst.json"
python3 - "$work/inst.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["fog"]["fine_step_s"] = 0.0005  # the simulator's step must divide the logger's interval
json.dump(d, open(sys.argv[1], "w"))
PY

median() { sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
timed() {  # timed CMD...: median wall time in seconds over $runs runs; a failed run stops all
  local start
  for _ in $(seq "$runs"); do
    start=$EPOCHREALTIME
    "$@" >/dev/null || { echo "failed: $*" >&2; exit 1; }
    awk -v a="$start" -v b="$EPOCHREALTIME" 'BEGIN {print b - a}'
  done | median
}

echo "| logger | samples | file, MB | read the file (floor), s | model | stream, s | stream / floor | samples/s | compensate, s | compensate / floor |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for hz in 1 10 100 1000 2000; do
  "$fd" simulate northfind --out "$work/nf$hz" --temps 17 --findings 5 --rate-hz "$hz" \
    --instrument "$work/inst.json" >/dev/null
  rec=$work/nf$hz/nf_17C.csv
  n=$(($(wc -l <"$rec") - 1))
  mb=$(awk -v b="$(stat -c %s "$rec")" 'BEGIN {printf "%.1f", b / 1e6}')
  floor=$(timed cat "$rec")
  models=(model)
  [ "$hz" = 10 ] && models+=(legacy)
  for m in "${models[@]}"; do
    # --allow-edited: the legacy file is the model with one field taken out.
    s=$(timed "$fd" stream "$work/$m.json" "$rec" --rate-hz "$hz" --allow-edited)
    c=$(timed "$fd" compensate "$work/$m.json" "$rec" -o "$work/out.csv" -q --allow-edited)
    label=$([ "$m" = model ] && echo "1 Hz, blocks of $hz" || echo "no interval recorded: filters at $hz Hz")
    awk -v hz="$hz" -v n="$n" -v mb="$mb" -v f="$floor" -v l="$label" -v s="$s" -v c="$c" \
      'BEGIN {printf "| %d Hz | %d | %s | %.4f | %s | %.3f | %.0f× | %.0f | %.3f | %.0f× |\n",
              hz, n, mb, f, l, s, s / f, n / s, c, c / f}'
  done
done
