#!/usr/bin/env bash
# Runs fogdrift paper and fogdrift demo as a user would: outputs, the change indicator, errors.
# Usage: paper_test.sh PATH/TO/fogdrift PATH/TO/tests/data
set -u
fd=$1
data=$2
source "$(dirname "$0")/common.sh"

# --- paper: the experiment end to end on a small campaign; its JSON is the change indicator --
# Two calibration temperatures: the default temperature folds need --folds 2.
tiny=(--seeds 1 --cal-temps 0,40 --folds 2 --nf-temps 10,30 --findings 2 --population 5 --iterations 2)
check "paper" run 0 "$fd" paper "${tiny[@]}" --out "$work/paper" --json
check "paper json parses" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["seeds"] == 1 and len(d["table3"]["ssa-svr"]["rmse_deg"]) == 2' "$work/out"
python3 "$(dirname "$0")/round_json.py" <"$work/out" >"$work/paper_small.json"
if ! diff -u "$data/change_indicator/paper_small.json" "$work/paper_small.json" >"$work/paper.diff"; then
  echo "  fogdrift paper's results changed; if intended, update tests/data/change_indicator/paper_small.json:" >&2
  sed 's/^/    /' "$work/paper.diff" | head -60 >&2
  failed=$((failed + 1))
else
  passed=$((passed + 1))
fi
for f in report.md paper.json fig1_startup.json fig2_output_vs_temperature.json fig3_features_25C.json fig8_compensation.json fig_northfind.json; do
  check "paper wrote $f" test -s "$work/paper/$f"
done
if command -v gnuplot >/dev/null; then
  check "paper drew PNGs" test "$(ls "$work/paper"/*.png | wc -l)" -eq 5
  check "paper kept the gnuplot scripts" test "$(ls "$work/paper"/*.gp | wc -l)" -eq 5
  check "paper left no gnuplot logs" test "$(ls "$work/paper" | grep -c '\.log$')" -eq 0
fi
check "paper report has Table 3" grep -qF "## Table 3" "$work/paper/report.md"
check "paper json file equals stdout" cmp -s "$work/out" "$work/paper/paper.json"
check "paper refuses to replace" run 1 "$fd" paper "${tiny[@]}" --out "$work/paper"
check "paper replace message" err_has "option --out: $work/paper exists and is not empty; use --force"
check "paper left the old output" test -s "$work/paper/report.md"
check "paper tables on stdout" run 0 "$fd" paper --seeds 1 --cal-temps 0,40 --nf-temps 20 --findings 1 --population 5 --iterations 1 --no-studies --cv repetition
check "paper stdout has Table 2" out_has "## Table 2 — compensation on the test repetition"
check "paper repetition folds in the header" out_has "fitness \`cv\` (leave one repetition out)"
check "paper without studies" bash -c "! grep -qF 'Leave one temperature out' '$work/out'"
check "paper bad seeds" run 1 "$fd" paper --seeds 0
check "paper bad seeds message" err_has "option --seeds: 0 must be between 1 and 1000"
check "paper bad fitness" run 1 "$fd" paper --fitness best
check "paper bad fitness message" err_has "option --fitness"
check "paper bad approach" run 1 "$fd" paper --approach lukewarm
check "paper bad approach message" err_has "option --approach: 'lukewarm' is not an approach (calibration, soaked, warm, ramping, sweep)"
check "paper sweep calibration" run 1 "$fd" paper --cal-approaches calibration,sweep
check "paper sweep calibration message" err_has "option --cal-approaches: sweep is not a calibration approach"
check "paper bad start-up" run 1 "$fd" paper --start-ups soaked,lukewarm
check "paper bad start-up message" err_has "option --start-ups: 'lukewarm' is not an approach (calibration, soaked, warm, ramping, sweep)"
check "paper bad nf temps" run 1 "$fd" paper --nf-temps 10,200
check "paper bad nf temps message" err_has "option --nf-temps: 200 °C must be between -70 and 100"
check "paper bad population" run 1 "$fd" paper --population 3
check "paper bad population message" err_has "option --population"
check "paper bad cv" run 1 "$fd" paper --cv temperatures
check "paper bad cv message" err_has "option --cv: 'temperatures' is not a cross-validation scheme"
check "paper too many temperature folds" run 1 "$fd" paper --cv temperature --folds 12
check "paper temperature folds message" err_has "option --folds: 12 folds of whole calibration temperatures need 12 calibration temperatures, and there are 11; ask for 2 to 11 folds"
check "paper temperature folds on stdout" run 0 "$fd" paper --seeds 1 --cal-temps 0,20,40 --nf-temps 20 --findings 1 --population 5 --iterations 1 --no-studies --cv temperature --folds 3
check "paper temperature folds in the header" out_has "fitness \`cv\` (3 temperature folds)"
check "paper default folds need three temperatures" run 1 "$fd" paper --cal-temps 0,40
check "paper default folds message" err_has "option --folds: 3 folds of whole calibration temperatures need 3 calibration temperatures, and there are 2; ask for 2 folds, or --cv repetition"
check "demo help" run 0 "$fd" demo --help
check "demo help says what it runs" out_has "fogdrift paper"

echo "cli_paper: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
