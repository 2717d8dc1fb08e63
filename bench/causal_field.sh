#!/usr/bin/env bash
# The causal model as the instrument runs it, in the field (docs/compensation.md, "Causal rates
# that hold in the field"): per seed, the recommended calibration protocol (docs/field.md),
# `fogdrift train --differentiator causal` with its defaults, then the share of the removable
# north-finding error it removes under the four start-up conditions (guard on, as `stream` and
# the C header run it: a causal model's batch drift is the streamed drift, bit for bit), on the
# RMSEs and, in brackets, finding by finding (docs/field.md, "Finding by finding"), and the
# largest novelty_reduced_share on the calibration's test repetition.
# Usage: bench/causal_field.sh [BUILD_DIR] [SEEDS] [TRAIN_FLAGS...]
#   (default build/, 5 seeds); extra flags go to `fogdrift train`, e.g. --rate-degree 2.
#   $CAUSAL_FIELD_JOBS seeds run at a time (default 1; each trains on one thread).
# Prints a Markdown table; 6 to 16 minutes a seed on one core with train's default search.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
seeds=${2:-5}
shift $(($# < 2 ? $# : 2))
jobs=${CAUSAL_FIELD_JOBS:-1}
if ! [[ $jobs =~ ^[1-9][0-9]*$ ]]; then
  echo "causal_field.sh: CAUSAL_FIELD_JOBS: '$jobs' is not a whole number ≥ 1" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

one() { # one seed: $1; writes its table row to $work/$1.row
  set -euo pipefail
  local seed=$1 d="$work/$1" start train_s row a
  mkdir -p "$d"
  "$fd" simulate calibration --out "$d/cal" --seed "$seed" --repetitions 5 \
    --approach calibration,soaked,warm,ramping >/dev/null
  start=$SECONDS
  "$fd" train "$d/cal" --differentiator causal --seed "$seed" --threads 1 -q \
    -o "$d/model.json" "${TRAIN_FLAGS[@]}"
  train_s=$((SECONDS - start))
  row="| $seed"
  for a in calibration soaked warm ramping; do
    "$fd" simulate northfind --out "$d/nf_$a" --seed "$seed" --approach "$a" >/dev/null
    "$fd" northfind "$d/nf_$a" --model "$d/model.json" --json >"$d/nf_$a.json"
    row+=$(python3 -c 'import json, sys
t = json.load(open(sys.argv[1]))["table3"]
print(" | {:.1f} % ({:.1f} %)".format(100 * t["removable_error_removed"], 100 * t["drift_error_removed"]))' \
      "$d/nf_$a.json")
  done
  "$fd" evaluate "$d/model.json" "$d/cal" --json >"$d/eval.json"
  row+=$(python3 -c 'import json, sys
print(" | {:.4f}".format(max(r["novelty_reduced_share"] for r in json.load(open(sys.argv[1]))["recordings"])))' \
    "$d/eval.json")
  echo "$row | $train_s |" >"$d.row"
}
export -f one
export fd work
export TRAIN_FLAGS_STR="${*:-}"
seq "$seeds" | xargs -P "$jobs" -I{} bash -c 'TRAIN_FLAGS=($TRAIN_FLAGS_STR); one {}'

echo "| seed | calibration | soaked | warm | ramping | novelty_reduced_share (test repetition, largest) | train, s |"
echo "|---|---|---|---|---|---|---|"
for seed in $(seq "$seeds"); do cat "$work/$seed.row"; done
