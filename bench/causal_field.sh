#!/usr/bin/env bash
# The causal model as the instrument runs it, in the field (docs/compensation.md, "Causal rates
# that hold in the field"): per seed, the recommended calibration protocol (docs/field.md),
# `fogdrift train --differentiator causal` with its defaults, then the share of the removable
# north-finding error it removes under the four start-up conditions (guard on, as `stream` and
# the C header run it: a causal model's batch drift is the streamed drift, bit for bit), and the
# largest novelty_reduced_share on the calibration's test repetition.
# Usage: bench/causal_field.sh [BUILD_DIR] [SEEDS] [TRAIN_FLAGS...]
#   (default build/, 5 seeds); extra flags go to `fogdrift train`, e.g. --rate-degree 2.
# Prints a Markdown table; 6 to 16 minutes a seed on one core with train's default search.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
seeds=${2:-5}
shift $(($# < 2 ? $# : 2))
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
approaches=(calibration soaked warm ramping)

echo "| seed | calibration | soaked | warm | ramping | novelty_reduced_share (test repetition, largest) | train, s |"
echo "|---|---|---|---|---|---|---|"
for seed in $(seq "$seeds"); do
  d="$work/$seed"
  mkdir -p "$d"
  "$fd" simulate calibration --out "$d/cal" --seed "$seed" --repetitions 5 \
    --approach calibration,soaked,warm,ramping >/dev/null
  start=$SECONDS
  "$fd" train "$d/cal" --differentiator causal --seed "$seed" -q -o "$d/model.json" "$@"
  train_s=$((SECONDS - start))
  row="| $seed"
  for a in "${approaches[@]}"; do
    "$fd" simulate northfind --out "$d/nf_$a" --seed "$seed" --approach "$a" >/dev/null
    "$fd" northfind "$d/nf_$a" --model "$d/model.json" --json >"$d/nf_$a.json"
    row+=$(python3 -c 'import json, sys
print(" | {:.1f} %".format(100 * json.load(open(sys.argv[1]))["table3"]["removable_error_removed"]))' \
      "$d/nf_$a.json")
  done
  "$fd" evaluate "$d/model.json" "$d/cal" --json >"$d/eval.json"
  row+=$(python3 -c 'import json, sys
print(" | {:.4f}".format(max(r["novelty_reduced_share"] for r in json.load(open(sys.argv[1]))["recordings"])))' \
    "$d/eval.json")
  echo "$row | $train_s |"
done
