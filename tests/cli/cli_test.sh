#!/usr/bin/env bash
# Runs the fogdrift tool as a user would and checks exit codes, messages and outputs.
# Usage: cli_test.sh PATH/TO/fogdrift PATH/TO/tests/data
set -u
fd=$1
data=$2
source "$(dirname "$0")/common.sh"

# --- help teaches ---------------------------------------------------------------------------
check "help" run 0 "$fd" --help
check "help lists simulate" out_has "simulate"
check "simulate help has examples" run 0 "$fd" simulate --help
check "simulate help example" out_has "fogdrift simulate calibration --out cal --seed 1"
check "no subcommand is a usage error" run 106 "$fd"

# --- simulate + inspect ---------------------------------------------------------------------
check "simulate calibration" run 0 "$fd" simulate calibration --out "$work/cal" --seed 1

# --- plan: a protocol's chamber hours (docs/field.md, "Chamber hours") -------------------------
check "plan the seven-sweep protocol" run 0 "$fd" plan --repetitions 7 --approach calibration,soaked,warm,ramping,warm,warm,calibration
check "plan says the hours" out_has "chamber hours: 222.7 (9.3 days)"
check "plan chains the first warm sweep" out_has "11 warm start-ups chained to soaked ones"
check "plan --json --schedule" run 0 "$fd" plan --json --schedule --temps 0,10
check "plan's steps add up" python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
steps = sum(s["seconds"] for s in d["steps"]) / 3600
parts = d["move_hours"] + sum(r["hours"] for r in d["repetitions"])
assert abs(steps - d["hours"]) < 1e-9 and abs(parts - d["hours"]) < 1e-9, d
assert [r["role"] for r in d["repetitions"]] == ["train", "train", "train", "test"], d
assert sum(s["action"] == "powered (recorded)" for s in d["steps"]) == 8, d' "$work/out"
check "plan refuses a chamber that does not move" run 1 "$fd" plan --chamber-ramp-degc-per-min 0
check "plan names the chamber's flag" err_has "option --chamber-ramp-degc-per-min: 0 °C/min must be > 0, ≤ 100"
check "plan refuses a protocol simulate refuses" run 1 "$fd" plan --repetitions 0
check "plan names the protocol's flag" err_has "option --repetitions: 0 must be between 1 and 100"
check "plan refuses a missing instrument" run 1 "$fd" plan --instrument "$work/no_such_unit.json"
check "plan names the missing file" err_has "$work/no_such_unit.json"
printf '{"thermal": {"capacity_j_per_k": {"housing": 1e7}}}' >"$work/slow_unit.json"
check "plan refuses a unit that never settles" run 1 "$fd" plan --instrument "$work/slow_unit.json"
check "plan says why" err_has "option --settled-within-degc: the instrument comes no closer than"
rm -f "$work/slow_unit.json"
# --- plan --hours: a protocol for a chamber budget (docs/field.md, "Protocols worth their hours")
check "plan --hours 60" run 0 "$fd" plan --hours 60 --json
check "plan --hours keeps to the budget and its command runs" python3 -c '
import json, shlex, subprocess, sys
d = json.load(open(sys.argv[1]))
c = d["chosen"]
assert c["service_hours"] <= 60 and c["worst_median_pct"] >= 85, c
assert c["instruments"] == 20 and c["on_front"], c
# Its claim is the worst over every set of search seeds it was studied with.
studies = [c] + c["reruns"]
assert len(studies) >= 2 and all(r["search_seed_offset"] > 0 for r in c["reruns"]), c
cells = [s[path][k] for s in studies for path in ("batch", "causal") for k in s[path]]
p10 = min(x["p10_pct"] for x in cells)
median = min(x["median_pct"] for x in cells)
worst = min(x["worst_pct"] for x in cells)
worse = max(s["worse_than_raw"] for s in studies)
assert c["worst_p10_pct"] == p10 and c["worst_pct"] == worst, c
assert c["most_worse_than_raw"] == worse, c
# The goal: every median >= 85 %, every 10th percentile >= 60 %, none worse than raw.
assert c["meets_goal"] == (median >= 85 and p10 >= 60 and worst >= 0 and worse == 0), c
# The protocol it names as meeting the goal leaves no instrument worse than raw.
goal = [p for p in d["studied"] if p["meets_goal"]]
assert goal and d["goal_needs_hours"] == goal[0]["service_hours"], d["goal_needs_hours"]
assert all(s["worse_than_raw"] == 0 for s in [goal[0]] + goal[0]["reruns"]), goal[0]
assert goal[0]["worst_pct"] >= 0, goal[0]
assert abs(d["protocol"]["hours"] - c["hours"]) < 1e-9, d["protocol"]
args = shlex.split(c["simulate"])
assert args[:3] == ["fogdrift", "simulate", "calibration"], args
out = sys.argv[3]
subprocess.run([sys.argv[2]] + args[1:] + ["--out", out], check=True, stdout=subprocess.DEVNULL)
m = json.load(open(out + "/campaign.json"))
reps = d["protocol"]["repetitions"]
assert max(r["repetition"] for r in m["recordings"]) == len(reps), m["recordings"][-1]
' "$work/out" "$fd" "$work/planned"
rm -rf "$work/planned"
check "plan --hours prints its command" run 0 "$fd" plan --hours 60
check "plan --hours names its choice" out_has "run it (the last sweep is the test"
check "plan shows the study with other search seeds" out_has "| batch, search seeds k + 100 | 97 / 85 / 81 | 96 / 56 / 44 |"
check "plan claims the worst over both" out_has "and 2 sets of search seeds (train --seed k, k + 100 for instrument k): median 92 %, 10th percentile 56 %"
check "plan says 60 hours miss the goal" out_has "note: this protocol misses the goal on the population"
check "plan --hours 30" run 0 "$fd" plan --hours 30
check "plan says a cheap choice misses the goal" out_has "note: this protocol misses the goal on the population"
check "plan says what meets it" out_has "the cheapest that meets it, seven sweeps, needs 207.3 h here"
check "plan --hours 110" run 0 "$fd" plan --hours 110
check "plan buys five sweeps for 110 hours" out_has "buy: five sweeps, 105.1 h"
check "plan says five sweeps leave instruments worse than raw" out_has "of 20 instruments × 4 conditions × 2 paths, 2 worse than raw"
check "plan says five sweeps miss the goal" out_has "note: this protocol misses the goal on the population (every median ≥ 85 %, every 10th percentile ≥ 60 %, none worse than raw)"
check "plan --service alone is refused" run 1 "$fd" plan --service soaked
check "plan says --service needs --hours" err_has "option --service: names the conditions --hours chooses for"
check "plan --figures alone is refused" run 1 "$fd" plan --figures "$work/front"
check "plan says --figures needs --hours" err_has "option --figures: draws the protocols --hours chooses among"
"$fd" simulate --print-instrument >"$work/unit.json"
check "plan --figures will not replace its instrument" run 1 "$fd" plan --hours 60 --instrument "$work/unit.json" --figures "$work/unit.json" --force
check "plan names the instrument it would destroy" err_has "option --figures: '$work/unit.json' is the input"
check "the instrument is still there" python3 -c 'import json, sys; json.load(open(sys.argv[1]))' "$work/unit.json"
check "plan --figures writes the front" run 0 "$fd" plan --hours 60 --figures "$work/front" --json
check "the front as JSON" python3 -c 'import json, sys; f = json.load(open(sys.argv[1])); assert f["name"] == "protocol_front", f' "$work/front/protocol_front.json"
check "plan --figures will not replace a folder unasked" run 1 "$fd" plan --hours 60 --figures "$work/front"
rm -rf "$work/front" "$work/unit.json"
check "plan refuses a budget nothing fits" run 1 "$fd" plan --hours 5
check "plan says what it would take" err_has "option --hours: 5 h buys no studied protocol: the cheapest"
check "plan refuses a protocol and a budget" run 1 "$fd" plan --hours 60 --approach soaked
check "plan says which to drop" err_has "option --hours: chooses the protocol, and --approach gives one"
check "plan refuses a service condition that is not one" run 1 "$fd" plan --hours 60 --service warm,sweep
check "plan names --service" err_has "option --service: sweep is not a start-up condition"
check "simulate refuses a start-up set point out of range" run 1 "$fd" simulate calibration --out "$work/bad_cal" --start-up-temps=0,150
check "simulate names --start-up-temps" err_has "option --start-up-temps: 150 °C must be between -70 and 100"
check "44 recordings" test "$(ls "$work/cal"/*.csv | wc -l)" -eq 44
check "manifest written" test -f "$work/cal/campaign.json"
check "inspect accepts the campaign" run 0 "$fd" inspect "$work/cal"
check "inspect says valid" out_has "campaign is valid"
check "inspect json" run 0 "$fd" inspect --json "$work/cal"
check "inspect json valid" out_has '"valid": true'
check "inspect one recording" run 0 "$fd" inspect "$work/cal/cal_r4_20C.csv"
check "same seed again" run 0 "$fd" simulate calibration --out "$work/cal_again" --seed 1
check "same seed, same files" diff -r "$work/cal" "$work/cal_again"
check "refuses a non-empty --out" run 1 "$fd" simulate calibration --out "$work/cal" --seed 2
check "non-empty message" err_has "folder exists and is not empty"
check "old campaign untouched" diff -r "$work/cal" "$work/cal_again"
check "impossible rate" run 1 "$fd" simulate calibration --out "$work/bad_rate" --rate-hz 3
check "rate message names option" err_has "--rate-hz"
check "nothing left behind" test -z "$(ls -A "$work" | grep -v -e '^cal$' -e '^cal_again$' -e '^out$' -e '^err$')"
check "northfind" run 0 "$fd" simulate northfind --out "$work/nf" --temps -32,17 --findings 2
check "northfind inspect" run 0 "$fd" inspect "$work/nf"
check "stable" run 0 "$fd" simulate stable --out "$work/st" --findings 3
check "bad temps list" run 1 "$fd" simulate northfind --out "$work/x" --temps -32,warm
check "bad temps message" err_has "option --temps: 'warm'"
check "stable's own defaults in help" run 0 "$fd" simulate stable --help
check "stable's defaults shown" out_has "--findings UINT=20"
check "options of a command fogdrift does not describe" run 1 "$fd" options simulate-storm
check "options names the commands it describes" err_has "'simulate-storm' is not one of train, simulate-calibration"
check "options of stream" run 0 "$fd" options stream --json
check "stream's options listed" out_has '"keyword": "bridge_s"'

# --- instrument files -----------------------------------------------------------------------
check "print instrument" run 0 "$fd" simulate --print-instrument
cp "$work/out" "$work/unit.json"
check "instrument round trip" run 0 "$fd" simulate stable --out "$work/st2" --findings 3 --instrument "$work/unit.json"
check "default file = defaults" diff -r "$work/st" "$work/st2"
printf '{"fog": {"arw": 0.1}}' >"$work/typo.json"
check "unknown instrument key" run 1 "$fd" simulate stable --out "$work/x" --instrument "$work/typo.json"
check "unknown key message" err_has "typo.json: fog.arw: unknown parameter"

check "missing instrument file" run 1 "$fd" simulate stable --out "$work/x" --instrument "$work/none.json"
check "missing instrument message" err_has "none.json: cannot open"
check "several imports need a folder" run 1 "$fd" import "$work/typo.json" "$work/unit.json" -o "$work/nofolder"
check "several imports message" err_has "must be an existing folder"
check "parameter table" run 0 "$fd" simulate --print-parameter-table
contains_file() { [[ "$(cat "$1")" == *"$(cat "$2")"* ]]; }
check "docs/simulator.md holds the current parameter table" contains_file "$data/../../docs/simulator.md" "$work/out"
check "population table" run 0 "$fd" simulate --print-population-table
check "docs/simulator.md holds the current population table" contains_file "$data/../../docs/simulator.md" "$work/out"
check "population of three" run 0 "$fd" simulate population --out "$work/units" --count 3 --seed 4
check "three instrument files" test "$(ls "$work/units"/unit_0*.json | wc -l)" -eq 3
check "population again" run 0 "$fd" simulate population --out "$work/units2" --count 2 --seed 4
check "unit k does not depend on the count" cmp "$work/units/unit_02.json" "$work/units2/unit_02.json"
check "a drawn unit simulates" run 0 "$fd" simulate stable --out "$work/st3" --findings 2 --instrument "$work/units/unit_03.json"
check "a drawn unit is another instrument" bash -c "! diff -rq '$work/st' '$work/st3' >/dev/null"
check "population of none" run 1 "$fd" simulate population --out "$work/x" --count 0
check "population count message" err_has "option --count: 0 must be between 1 and 999"

# --- malformed inputs: every case in the corpus --------------------------------------------
while IFS=$'\t' read -r name expected; do
  case "$name" in "#"* | "") continue ;; esac
  check "inspect rejects $name" run 1 "$fd" inspect "$data/malformed/$name"
  check "message for $name" err_has "$expected"
done <"$data/malformed/EXPECTED.tsv"

# --- import ---------------------------------------------------------------------------------
printf 'Zeit [ms];Rate X [rad/s];T0;T1;T2;Status\n5000;0,0001;1000;1010;990;OK\n6000;0,0002;1001;1011;991;OK\n' >"$work/logger.csv"
imp=(import "$work/logger.csv" --delimiter ';' --decimal-comma --time-from-zero
  --map "time_s=Zeit [ms]" --unit time_s=ms --map "gyro_dph=Rate X [rad/s]" --unit gyro_dph=rad/s
  --map temp_fog_degc=T0 --map temp_acc1_degc=T1 --map temp_acc2_degc=T2
  --unit temp_fog_degc=counts:0.0625:-40 --unit temp_acc1_degc=counts:0.0625:-40
  --unit temp_acc2_degc=counts:0.0625:-40)
check "import" run 0 "$fd" "${imp[@]}" -o "$work/imported.csv"
check "imported recording is valid" run 0 "$fd" inspect "$work/imported.csv"
check "imported header" grep -q '^time_s,gyro_dph,temp_fog_degc,temp_acc1_degc,temp_acc2_degc,Status$' "$work/imported.csv"
check "imported values" grep -q '^0,20.626480624709636,22.5,23.125,21.875,OK$' "$work/imported.csv"
check "import with a bad unit" run 1 "$fd" "${imp[@]/gyro_dph=rad\/s/gyro_dph=rpm}" -o "$work/bad_unit.csv"
check "bad unit message" err_has "--unit gyro_dph=rpm: unknown unit 'rpm'"
check "a unit given twice" run 1 "$fd" "${imp[@]}" --unit gyro_dph=deg/s -o "$work/bad_unit.csv"
check "twice message" err_has "option --unit: gyro_dph is given twice"
check "bad unit leaves no file" test ! -e "$work/bad_unit.csv"
check "import of a missing column" run 1 "$fd" import "$work/logger.csv" --delimiter ';' -o "$work/x.csv"
check "missing column message" err_has "say which column holds it"

# --- denoise: one column replaced, the rest byte for byte; checked against PyWavelets ------------
rec="$work/cal/cal_r1_m10C.csv"
check "denoise help explains the rules" run 0 "$fd" denoise --help
check "denoise help lists bayes" out_has "sigma^2 / sigma_signal (BayesShrink)"
check "denoise with defaults" run 0 "$fd" denoise "$rec" -o "$work/den.csv"
cp "$work/den.csv" "$work/den.csv.default"
check "denoise summary" out_has "denoised gyro_dph (1800 samples) with sym4"
cut -d, -f1,3- "$rec" >"$work/rest_in.txt"
cut -d, -f1,3- "$work/den.csv" >"$work/rest_out.txt"
check "every other column unchanged" diff "$work/rest_in.txt" "$work/rest_out.txt"
check "gyro column changed" bash -c "! cmp -s '$rec' '$work/den.csv'"
python=/usr/bin/python3
if "$python" -c 'import pywt, numpy' 2>/dev/null; then
  for setting in "db4 6 universal hard periodization" "coif2 max level soft zero" \
                 "sym6 5 sure soft periodic" "haar 3 bayes hard symmetric"; do
    set -- $setting
    check "denoise $setting" run 0 "$fd" denoise "$rec" -o "$work/den_$1.csv" --wavelet "$1" \
      --level "$2" --threshold "$3" --mode "$4" --extension "$5" -q
    check "denoise $setting matches PyWavelets" "$python" - "$rec" "$work/den_$1.csv" "$@" <<'PY'
import sys
import numpy as np
import pywt
src, out, name, level, rule, shrink, mode = sys.argv[1:]
x = np.genfromtxt(src, delimiter=",", names=True)["gyro_dph"]
y = np.genfromtxt(out, delimiter=",", names=True)["gyro_dph"]
c = pywt.wavedec(x, "db1" if name == "haar" else name, mode=mode,
                 level=None if level == "max" else int(level))
mad = lambda d: np.median(np.abs(d)) / 0.6745
s = mad(c[-1])
res = [c[0]]
for d in c[1:]:
    if rule == "universal":
        lam = s * np.sqrt(2 * np.log(len(x)))
    elif rule == "level":
        lam = mad(d) * np.sqrt(2 * np.log(len(x)))
    elif rule == "sure":
        w2 = np.sort((d / s) ** 2); n = len(w2); k = np.arange(1, n + 1)
        r = n - 2 * k + np.cumsum(w2) + (n - k) * w2
        lam = s * np.sqrt(w2[np.argmin(r)]) if r.min() < n else 0.0
    else:
        v = np.mean(d ** 2) - s * s
        lam = s * s / np.sqrt(v) if v > 0 else np.nextafter(np.abs(d).max(), np.inf)
    res.append(pywt.threshold(d, lam, mode=shrink))
ref = pywt.waverec(res, "db1" if name == "haar" else name, mode=mode)[: len(x)]
err = np.abs(ref - y).max() / np.abs(ref).max()
sys.exit(0 if err < 1e-10 else f"relative error {err}")
PY
  done
fi
check "denoise json" run 0 "$fd" denoise "$rec" -o "$work/den.csv" --json --threshold universal
check "denoise json bands" out_has '"threshold": "universal"'
check "denoise missing column" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --column gyro
check "missing column message" err_has "cal_r1_m10C.csv:1: no column 'gyro' to denoise; the columns are time_s, gyro_dph"
check "no output on error" test ! -e "$work/x.csv"
check "denoise level too high" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --level 12
check "level message" err_has "option --level: 12 is too high for 1800 samples with sym4: the maximum is 8"
check "denoise bad level text" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --level deep
check "bad level message" err_has "option --level: 'deep' is neither auto nor a whole number"
check "denoise level max" run 0 "$fd" denoise "$rec" -o "$work/den_max.csv" --level max -q
check "level max is the default" cmp -s "$work/den.csv.default" "$work/den_max.csv"
check "denoise level auto" run 0 "$fd" denoise "$rec" -o "$work/den_auto.csv" --level auto -q
check "level auto is the default" cmp -s "$work/den.csv.default" "$work/den_auto.csv"
check "denoise's options described once" run 0 "$fd" options denoise
check "denoise's table lists the rules" out_has "| \`threshold\` | \`--threshold\` | choice |  | \`bayes\` | universal, level, sure, bayes |"
check "denoise bad wavelet" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --wavelet db42
check "bad wavelet message" err_has "option --wavelet: 'db42' is not a known wavelet"
check "denoise bad mode" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --mode medium
check "bad mode message" err_has "option --mode: 'medium' is not a shrinkage mode (soft, hard)"
check "denoise bad extension" run 1 "$fd" denoise "$rec" -o "$work/x.csv" --extension reflect
check "bad extension message" err_has "option --extension: 'reflect' is not an extension mode"
sed '5s/^\([^,]*\),[^,]*,/\1,NaN,/' "$rec" >"$work/nan.csv"
check "denoise NaN cell" run 1 "$fd" denoise "$work/nan.csv" -o "$work/x.csv"
check "NaN message names line and column" err_has "nan.csv:5:2: 'NaN' in column gyro_dph is not a finite number"
head -5 "$rec" >"$work/short.csv"
check "denoise too short" run 1 "$fd" denoise "$work/short.csv" -o "$work/x.csv"
check "too short message" err_has "too short to denoise with sym4"
check "no output after any error" test ! -e "$work/x.csv"

# --- svr train / predict, side by side with LIBSVM's svm-train / svm-predict ----------------
dia="$data/svr/diabetes.libsvm"
# The default solver (pairs) reaches svm-train's optimum by another path: its objective to 1e-3
# relative. --solver libsvm follows svm-train step for step: the same printed lines.
check "svr train" run 0 "$fd" svr train -c 100 -g 2 -p 5 "$dia" "$work/dia_pairs.model"
obj_pairs=$(sed -n 's/^obj = \([^,]*\),.*/\1/p' "$work/out")
check "svr train --solver libsvm" run 0 "$fd" svr train --solver libsvm -c 100 -g 2 -p 5 "$dia" "$work/dia.model"
grep -E '^(obj|nSV)' "$work/out" >"$work/ours.txt"
if command -v svm-train >/dev/null; then
  svm-train -s 3 -t 2 -c 100 -g 2 -p 5 "$dia" "$work/dia_libsvm.model" | grep -E '^(obj|nSV)' >"$work/theirs.txt"
  check "--solver libsvm prints svm-train's obj, rho, nSV, nBSV" diff "$work/ours.txt" "$work/theirs.txt"
  obj_libsvm=$(sed -n 's/^obj = \([^,]*\),.*/\1/p' "$work/theirs.txt")
  check "default solver: svm-train's objective to 1e-3" awk -v a="$obj_pairs" -v b="$obj_libsvm" 'BEGIN{d=a-b; if(d<0)d=-d; m=b<0?-b:b; exit !(a != "" && d <= 1e-3*m)}'
  svm-predict "$dia" "$work/dia.model" "$work/libsvm_pred.txt" >/dev/null
  check "svm-predict reads fogdrift's model" test -s "$work/libsvm_pred.txt"
  svm-predict "$dia" "$work/dia_pairs.model" "$work/libsvm_pred_pairs.txt" >/dev/null
  check "svm-predict reads the default solver's model" test -s "$work/libsvm_pred_pairs.txt"
fi
check "svr predict" run 0 "$fd" svr predict "$dia" "$work/dia.model" "$work/pred.txt"
check "svr predict prints the regression summary" out_has "Squared correlation coefficient = "
check "one prediction a line" test "$(wc -l <"$work/pred.txt")" -eq 442
if [ -f "$work/libsvm_pred.txt" ]; then
  check "same predictions as svm-predict" awk 'NR==FNR{a[FNR]=$1;next}{d=a[FNR]-$1; if(d<0)d=-d; if(d>1e-9*(1+($1<0?-$1:$1))) bad=1} END{exit bad}' "$work/pred.txt" "$work/libsvm_pred.txt"
fi
check "unknown solver rejected" run 1 "$fd" svr train --solver fast "$dia" "$work/x.model"
check "solver message names --solver" err_has "option --solver: must be libsvm or pairs (got 'fast')"
check "svr train --json" run 0 "$fd" svr train --json --sigma 0.5 -c 10 -p 5 "$dia" "$work/dia.json"
check "json summary" out_has '"status": "optimal"'
check "json model predicts" run 0 "$fd" svr predict -q "$dia" "$work/dia.json" "$work/pred_json.txt"
check "C <= 0 rejected" run 1 "$fd" svr train -c 0 "$dia" "$work/x.model"
check "C message names -c" err_has "option -c: 0 must be > 0"
check "negative epsilon rejected" run 1 "$fd" svr train -p -1 "$dia" "$work/x.model"
check "epsilon message names -p" err_has "option -p:"
check "sigma <= 0 rejected" run 1 "$fd" svr train --sigma -2 "$dia" "$work/x.model"
check "sigma message" err_has "option --sigma: -2 must be > 0"
check "other svm types rejected" run 1 "$fd" svr train -s 0 "$dia" "$work/x.model"
check "svm type message" err_has "option -s: svm_type 0 (C-SVC) is not supported"
check "no model written on error" test ! -e "$work/x.model"
# svm-train's -v: the cross-validated error instead of a model, from the parser the MATLAB
# interface's option string goes through.
check "svr train -v" run 0 "$fd" svr train -v 5 -c 10 -p 5 "$dia" "$work/cv.model"
check "cross-validation summary" out_has "Cross Validation Mean squared error = "
check "no model from -v" test ! -e "$work/cv.model"
check "svr train -v 1 refused" run 1 "$fd" svr train -v 1 "$dia" "$work/x.model"
check "-v message" err_has "option -v: 1 must be ≥ 2"
check "options after the files refused" run 1 "$fd" svr train "$dia" "$work/x.model" -c 10
check "usage message" err_has "svr train takes [options] DATA [MODEL]"
check "a flag without its value refused" run 1 "$fd" svr train -c
check "no value message" err_has "option -c: needs a value after it"
# A trailing flag is not MODEL: 'svr train DATA -c' wrote a model file named '-c' with exit 0.
(cd "$work" && "$fd" svr train "$dia" -c >"$work/out" 2>"$work/err"; echo $? >"$work/rc")
check "a flag after DATA refused" test "$(cat "$work/rc")" = 1
check "a flag after DATA: no model named after it" test ! -e "$work/-c"
check "a flag after DATA: what to do" err_has "move -c before DATA"
check "-g with --sigma refused" run 1 "$fd" svr train -g 1 --sigma 1 "$dia" "$work/x.model"
check "gamma or sigma message" err_has "option --sigma: give either -g or --sigma"
check "svr train --help after options" run 0 "$fd" svr train -c 10 --help
check "help lists svm-train's options" out_has "  -p       The half-width ε of the insensitive tube"
printf '1 2:1 1:3\n' >"$work/unsorted.txt"
check "unsorted indices rejected" run 1 "$fd" svr train "$work/unsorted.txt" "$work/x.model"
check "unsorted message names line and column" err_has "unsorted.txt:1:7: feature index 1 is not above the previous index 2"
printf '1 1:nan\n' >"$work/nan.txt"
check "NaN rejected" run 1 "$fd" svr train "$work/nan.txt" "$work/x.model"
check "NaN message" err_has "nan.txt:1:3: feature value 'nan' is not finite"
printf '{"format": "fogdrift-svr", "version": 9}' >"$work/future.json"
check "newer model version rejected" run 1 "$fd" svr predict "$dia" "$work/future.json" "$work/p.txt"
check "version message" err_has "model format version 9 is not supported"

# --- size limits ------------------------------------------------------------------------------
# A job larger than the memory left is refused before it starts, naming the need and the limit
# (docs/reliability.md, "Size limits"). Builds that cannot run under ulimit -v at all (the
# sanitizers reserve terabytes of address space) skip it.
awk 'BEGIN { srand(1); for (i = 0; i < 6000; i++) { printf "%.6f", rand();
  for (j = 1; j <= 9; j++) printf " %d:%.6f", j, rand(); print "" } }' >"$work/big.txt"
if (ulimit -v 1000000 && "$fd" --version) >/dev/null 2>&1; then
  check "a fit larger than ulimit -v refused" run 1 bash -c \
    "ulimit -v 150000 && '$fd' svr train -m 2000 '$work/big.txt' '$work/big.model'"
  check "memory message" err_has "an SVR fit of 6000 rows with a 2000 MB kernel cache needs about"
  check "memory message names the limit" err_has "the address-space limit (ulimit -v) leaves"
  check "nothing written" test ! -e "$work/big.model"
  # A campaign is checked from its file sizes before a recording is read (a sparse 60 MB file).
  "$fd" simulate calibration --out "$work/huge" --temps 20 --repetitions 2 >/dev/null
  truncate -s 60M "$work/huge/cal_r1_20C.csv"
  check "a campaign larger than ulimit -v refused" run 1 bash -c \
    "ulimit -v 150000 && '$fd' train '$work/huge' --method svr -o '$work/huge.json'"
  check "campaign memory message" err_has "campaign.json: 1 calibration recording (60 MiB of CSV) needs about 240 MiB of memory"
else
  echo "note: size-limit checks skipped (this build cannot run under ulimit -v)"
fi

# --- train ------------------------------------------------------------------------------------
# A small campaign (3 temperatures × 4 repetitions) keeps these runs short under the sanitizers.
check "small campaign" run 0 "$fd" simulate calibration --out "$work/small" --temps -20,20,60 --seed 3
check "train help teaches" run 0 "$fd" train --help
# Found by attack (issue 36, "memory limits"): the memory advice named a kernel cache train had
# no option for.
check "train has the kernel cache the memory advice names" out_has "--cache-mb"
check "train help lists methods" out_has "ssa-svr an ε-SVR with C and σ tuned by sparrow search"
check "train help lists every registered method" out_has "Methods: ssa-svr, pso-svr, gwo-svr, svr, bp, poly, gp"
check "a negative kernel cache" run 1 "$fd" train "$work/small" --cache-mb -1 -o "$work/x.json"
check "kernel cache message" err_has "option --cache-mb: -1 MB must be ≥ 0"
check "train ssa-svr" run 0 "$fd" train "$work/small" --population 5 --iterations 2 --c-max 10 \
  --threads 1 -o "$work/m1.json"
check "train prints the fitness" out_has "cv RMSE"
check "train names the folds" out_has "whole initial temperatures (3 folds)"
check "train says what it expects to remove" out_has "expected to remove"
check "train scores the baselines" out_has "mean "
check "train scores a line in each thermometer" out_has "line in T_acc2_degc "
# A gyro whose drift has no temperature signal (issue 32): train must say so.
printf '{"fog": {"static_d1_dph_per_k": 0, "static_d2_dph_per_k2": 0, "static_d3_dph_per_k3": 0, "rate_r0_dph_per_kps": 0, "shupe_s0_dph_per_kps": 0}}' >"$work/flat.json"
check "a unit without thermal drift" run 0 "$fd" simulate calibration --out "$work/flat" --temps -20,0,20,40 \
  --repetitions 2 --seed 3 --instrument "$work/flat.json"
check "train on it" run 0 "$fd" train "$work/flat" --population 5 --iterations 2 --threads 1 \
  -o "$work/flat_model.json"
check "train says the model removes little" out_has "it would remove"
check "train says there is no temperature signal" out_has "the data show no temperature signal"
check "train again on two threads" run 0 "$fd" train "$work/small" --population 5 --iterations 2 \
  --c-max 10 --threads 2 -q -o "$work/m2.json"
check "one seed, one model file" cmp "$work/m1.json" "$work/m2.json"
check "train again on eight threads" run 0 "$fd" train "$work/small" --population 5 --iterations 2 \
  --c-max 10 --threads 8 -q -o "$work/m8.json"
check "eight threads, the same model file" cmp "$work/m1.json" "$work/m8.json"
# Every instruction set gives the same model, byte for byte (FOGDRIFT_ISA, docs/reliability.md):
# the tuned SVR above on the pair solver, and LIBSVM's own working sets at a large C.
for isa in portable avx2 avx512; do
  if ! FOGDRIFT_ISA=$isa "$fd" svr train -q -c 1 "$dia" "$work/isa.model" 2>"$work/err"; then
    check "FOGDRIFT_ISA=$isa missing on this processor, said so" err_has "this processor cannot run '$isa'"
    continue
  fi
  check "train with FOGDRIFT_ISA=$isa" env FOGDRIFT_ISA=$isa "$fd" train "$work/small" --population 5 \
    --iterations 2 --c-max 10 --threads 2 -q -o "$work/m_$isa.json"
  check "FOGDRIFT_ISA=$isa, the same model file" cmp "$work/m1.json" "$work/m_$isa.json"
  check "svr train --solver libsvm with FOGDRIFT_ISA=$isa" env FOGDRIFT_ISA=$isa "$fd" svr train -q \
    -c 100 -g 0.5 --solver libsvm "$dia" "$work/libsvm_$isa.model"
  check "FOGDRIFT_ISA=$isa, the same LIBSVM-path model" cmp "$work/libsvm_portable.model" \
    "$work/libsvm_$isa.model"
done
check "unknown FOGDRIFT_ISA" run 1 env FOGDRIFT_ISA=sse4 "$fd" train "$work/small" -o "$work/x.json"
check "FOGDRIFT_ISA message" err_has "option FOGDRIFT_ISA: 'sse4' is not an instruction set (portable, avx2, avx512)"
check "help works whatever FOGDRIFT_ISA says" run 0 env FOGDRIFT_ISA=sse4 "$fd" train --help
check "another seed" run 0 "$fd" train "$work/small" --population 5 --iterations 2 --c-max 10 \
  --seed 2 -q -o "$work/m3.json"
check "another seed, another search" bash -c "! cmp -s '$work/m1.json' '$work/m3.json'"
check "model format" grep -q '"format": "fogdrift-compensation-model"' "$work/m1.json"
sum=$(sha256sum "$work/small/cal_r1_20C.csv" | cut -d' ' -f1)
check "provenance checksum matches sha256sum" grep -q "$sum" "$work/m1.json"
check "train --json" run 0 "$fd" train "$work/small" --method svr --json -o "$work/svr.json"
check "json summary method" out_has '"method": "svr"'
check "json default gamma" out_has '"gamma": 0.08333333333333333'
check "train bp" run 0 "$fd" train "$work/small" --method bp --hidden 4 -q -o "$work/bp.json"
check "bp weights in the model" grep -q '"type": "mlp"' "$work/bp.json"
check "train poly" run 0 "$fd" train "$work/small" --method poly --max-degree 2 --json -o "$work/poly.json"
check "poly degree chosen by cv" out_has '"poly_cv_rmse_by_degree"'
check "train gp" run 0 "$fd" train "$work/small" --method gp --gp-points 120 --population 5 \
  --iterations 2 --json -o "$work/gp.json"
check "gp summary" out_has '"log_likelihood"'
check "gp in the model" grep -q '"type": "gp"' "$work/gp.json"
check "gp header written" run 0 "$fd" export-c "$work/gp.json" -q -o "$work/gp.h"
check "gp header predicts" grep -q "fogdrift_model_gp_coef" "$work/gp.h"
check "ard needs the likelihood" run 1 "$fd" train "$work/small" --method gp --gp-kernel ard \
  -o "$work/x.json"
check "ard message" err_has "option --gp-kernel: ard (one length scale per feature) needs"
check "gp points range" run 1 "$fd" train "$work/small" --method gp --gp-points 5 -o "$work/x.json"
check "gp points message" err_has "option --gp-points: 5 must be between 10 and 4000"
check "train fitness" run 0 "$fd" train "$work/small" --method gwo-svr --fitness train --population 3 \
  --iterations 1 --c-max 10 -o "$work/gwo.json"
check "training fitness named" out_has "train RMSE"
check "unknown method" run 1 "$fd" train "$work/small" --method rf -o "$work/x.json"
check "method message" err_has "option --method: 'rf' is not a method"
check "population too small" run 1 "$fd" train "$work/small" --population 3 -o "$work/x.json"
check "population message" err_has "option --population: 3 is too small: at least 5"
check "bad C range" run 1 "$fd" train "$work/small" --c-min 0 -o "$work/x.json"
check "C range message" err_has "option --c-min: 0 must be > 0"
check "bad feature spec" run 1 "$fd" train "$work/small" --features "T,bogus" -o "$work/x.json"
check "feature spec message" err_has "--features"
check "bad lag" run 1 "$fd" train "$work/small" --features "T,dT@0" -o "$work/x.json"
check "lag message" err_has "option --features: 'T,dT@0': 'dT@0': the lag after '@' must be a number of seconds"
check "train with a lagged rate" run 0 "$fd" train "$work/small" --method poly \
  --features "T,dT,dT@300(fog)" -q -o "$work/lagged.json"
check "lagged rate in the model" grep -q '"dT300s_fog_degc_per_s"' "$work/lagged.json"
check "train with causal rates" run 0 "$fd" train "$work/small" --method poly --differentiator causal \
  -q -o "$work/causal.json"
check "causal rates in the model" grep -q '"causality": "causal"' "$work/causal.json"
check "bad differentiator" run 1 "$fd" train "$work/small" --differentiator future -o "$work/x.json"
check "differentiator message" err_has "option --differentiator: 'future' is not a differentiator"
check "a search that contradicts the method, before any campaign is read" run 1 "$fd" train "$work/no-such-campaign" --method ssa-svr --search pso -o "$work/x.json"
check "search message" err_has "option --search: 'pso' contradicts --method ssa-svr, which is svr searched by ssa; give --method svr with --search pso"
check "bad rate degree" run 1 "$fd" train "$work/small" --rate-degree 5 -o "$work/x.json"
check "rate degree message" err_has "option --rate-degree: 5 is outside 1 … 4"
check "causal rates fit a line by default" grep -q '"poly_order": 1' "$work/causal.json"
check "over 61 s by default" grep -q '"window_s": 61' "$work/causal.json"
check "train with a causal parabola fit" run 0 "$fd" train "$work/small" --method poly --differentiator causal --rate-degree 2 -q -o "$work/parabola.json"
check "the degree in the model" grep -q '"poly_order": 2' "$work/parabola.json"
check "bad fitness" run 1 "$fd" train "$work/small" --fitness loo -o "$work/x.json"
check "fitness message" err_has "option --fitness: 'loo' is not a fitness (cv, train)"
check "one fold is impossible" run 1 "$fd" train "$work/small" --cv recording --folds 1 \
  --method svr -o "$work/x.json"
check "folds message" err_has "option --folds: 1 must be ≥ 2"
check "train with temperature folds" run 0 "$fd" train "$work/small" --method svr --cv temperature \
  --folds 3 -o "$work/tcv.json"
check "temperature folds in the model" grep -q '"cv": "whole initial temperatures (3 folds)"' "$work/tcv.json"
check "more temperature folds than temperatures" run 1 "$fd" train "$work/small" --method svr \
  --cv temperature --folds 4 -o "$work/x.json"
check "temperature folds message" err_has "option --folds: 4 folds of whole initial temperatures need 4 training temperatures, and there are 3; ask for 2 to 3 folds"
check "missing campaign" run 1 "$fd" train "$work/nowhere" -o "$work/x.json"
check "no model written on error" test ! -e "$work/x.json"

# --- evaluate ---------------------------------------------------------------------------------
check "evaluate on the test repetition" run 0 "$fd" evaluate "$work/svr.json" "$work/small"
check "evaluate prints the Table 2 view" out_has "Table 2 view: denoised STD"
check "evaluate has a row per test recording in each of its four tables" test "$(grep -c '^| cal_r4_' "$work/out")" -eq 12
check "evaluate shows the model beside its baselines" out_has "| recording | raw | recording mean | line in T_fog_degc | model | STD raw / line / model | judged |"
check "evaluate gives its verdict" out_has "verdict: beats raw, the recording mean and the line in T_fog_degc on every recording"
check "evaluate shows what a finding sees" out_has "| recording | first 5 min residual | opposite positions 180 s apart | guard |"
check "evaluate without the guard" run 0 "$fd" evaluate "$work/svr.json" "$work/small" --no-guard --json
check "evaluate json has the finding metrics" out_has '"opposite_difference_after_dph"'
check "evaluate json says the guard is off" out_has '"guard": false'
check "evaluate --json" run 0 "$fd" evaluate --json "$work/svr.json" "$work/small"
check "evaluate json overall" out_has '"std_compensated_dph"'
check "evaluate --allan" run 0 "$fd" evaluate --allan "$work/svr.json" "$work/small"
check "evaluate allan table" out_has "| recording | ARW (°/√h) | bias instability (°/h) | RRW (°/h/√h) |"
check "evaluate allan row per recording" test "$(grep -c '^| cal_r4_.* → .* → .* → ' "$work/out")" -eq 3
check "evaluate --allan --json" run 0 "$fd" evaluate --allan --json "$work/svr.json" "$work/small"
check "evaluate allan json" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); r=d["recordings"][0]["allan"]; assert 0.0003 < r["raw"]["arw_deg_per_rt_h"] < 0.0008 and r["compensated"]["bias_instability_dph"] < r["raw"]["bias_instability_dph"]' "$work/out"
check "evaluate files" run 0 "$fd" evaluate "$work/poly.json" "$work/small/cal_r4_20C.csv"
check "files without a manifest warn about the target" out_has "warning:"
printf '{"format": "fogdrift-compensation-model", "version": 7}' >"$work/future_model.json"
check "newer model version rejected" run 1 "$fd" evaluate "$work/future_model.json" "$work/small"
check "model version message" err_has "future_model.json: version: model format version 7 is not supported"
check "model version says upgrade" err_has "written by a newer fogdrift"
sed 's/"block_s": 10.0/"block_s": 10.5/' "$work/svr.json" >"$work/edited.json"
check "an edited model is refused" run 1 "$fd" evaluate "$work/edited.json" "$work/small"
check "edited model message" err_has "edited.json: checksum: the content does not match its checksum"
check "the edited model, on purpose" run 1 "$fd" evaluate "$work/edited.json" "$work/small" --allow-edited
check "its fields are still checked" err_has "block_s"
# Found by an attack (issue 36): a corrupted feature name was blamed on the recording.
sed '0,/"T_fog_degc"/s//"T_fg_degc"/' "$work/svr.json" >"$work/renamed.json"
check "a corrupted feature name" run 1 "$fd" compensate "$work/renamed.json" \
  "$work/small/cal_r4_20C.csv" -o "$work/x.csv" --allow-edited
check "is the model's fault, found on load" err_has "features.names: 'T_fg_degc,"
check "not the recording's" bash -c "! grep -q 'cal_r4_20C.csv' '$work/err'"
sed 's/"version": 3/"version": 2/; s/"rho": \(-*\)0/"rho": \19/' "$work/svr.json" >"$work/lowered.json"
check "a lowered version does not bypass the checksum" run 1 "$fd" compensate "$work/lowered.json" \
  "$work/small/cal_r4_20C.csv" -o "$work/x.csv" --allow-old-format
check "lowered version message" err_has "lowered.json: checksum: the content does not match"
check "a version-2 model needs its flag" run 1 "$fd" compensate "$data/models/bp_v2.json" \
  "$work/small/cal_r4_20C.csv" -o "$work/x.csv"
check "version-2 message names the flag" err_has "bp_v2.json: version: format version 2 carries no checksum"
check "version-2 model with its flag" run 0 "$fd" compensate "$data/models/bp_v2.json" \
  "$work/small/cal_r4_20C.csv" -o "$work/x.csv" --allow-old-format -q
check "the model's checksum in one line of Python" python3 -c 'import hashlib,json,sys; t=open(sys.argv[1]).read(); i=t.rindex("\"checksum\""); p=t[:i].rstrip()[:-1]; assert json.loads(t)["checksum"] == "sha256:" + hashlib.sha256(p.replace("\r", "").encode()).hexdigest()' "$work/svr.json"
check "svr model is not a compensation model" run 1 "$fd" evaluate "$work/dia.json" "$work/small"
check "format message" err_has 'format: must be "fogdrift-compensation-model"'
check "campaign and files mixed" run 1 "$fd" evaluate "$work/svr.json" "$work/small" "$work/small/cal_r4_20C.csv"
check "mixed message" err_has "is a campaign"

# --- compensate -------------------------------------------------------------------------------
check "compensate" run 0 "$fd" compensate "$work/svr.json" "$work/small/cal_r4_20C.csv" -o "$work/comp.csv"
check "compensate summary" out_has "samples compensated with"
check "one output row per input row" test "$(wc -l <"$work/comp.csv")" -eq "$(wc -l <"$work/small/cal_r4_20C.csv")"
check "drift columns appended" bash -c "head -1 '$work/comp.csv' | grep -q ',drift_dph,gyro_comp_dph,novelty,guard_weight\$'"
check "gyro_comp = gyro - drift" awk -F, 'NR>1{d=$2-$(NF-3)-$(NF-2); if(d<0)d=-d; if(d>1e-9) bad=1} END{exit bad}' "$work/comp.csv"
check "guard weights within [0, 1]" awk -F, 'NR>1{if($NF<0||$NF>1||$(NF-1)<0) bad=1} END{exit bad}' "$work/comp.csv"
check "compensate names the novelty" out_has "novelty: "
check "compensate without the guard" run 0 "$fd" compensate "$work/svr.json" "$work/small/cal_r4_20C.csv" -o "$work/comp_ng.csv" --no-guard
check "unguarded weights are 1" awk -F, 'NR>1{if($NF!=1) bad=1} END{exit bad}' "$work/comp_ng.csv"
check "input columns kept as read" bash -c "cut -d, -f1-10 '$work/comp.csv' | diff -q - '$work/small/cal_r4_20C.csv'"
check "compensating a compensated file" run 1 "$fd" compensate "$work/svr.json" "$work/comp.csv" -o "$work/comp2.csv"
check "already-compensated message" err_has "comp.csv:1:11: already has a drift_dph column"
check "no output on error" test ! -e "$work/comp2.csv"
head -100 "$work/small/cal_r4_20C.csv" >"$work/short.csv"
check "recording shorter than the differentiator" run 1 "$fd" compensate "$work/svr.json" "$work/short.csv" -o "$work/comp3.csv"
check "short message names the file" err_has "short.csv"

# --- stream: line in, line out; for a causal model, what compensate writes -------------------
rec20="$work/small/cal_r4_20C.csv"
check "compensate with the causal model" run 0 "$fd" compensate "$work/causal.json" "$rec20" -o "$work/comp_causal.csv" -q
check "stream from stdin" bash -c "'$fd' stream '$work/causal.json' --rate-hz 1 <'$rec20' >'$work/streamed.csv'"
# The first 14 columns are compensate's; fault_flags is 0 on every line of a clean recording.
check "stream equals compensate" bash -c "cut -d, -f1-14 '$work/streamed.csv' | cmp -s - '$work/comp_causal.csv'"
check "stream flags column" bash -c "head -1 '$work/streamed.csv' | grep -q ',guard_weight,fault_flags\$'"
check "stream clean recording unflagged" bash -c "awk -F, 'NR>1 && \$15!=0{bad=1} END{exit bad}' '$work/streamed.csv'"
check "stream from a file" run 0 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 1
# Found by attack (issue 36, "silent truncation"): a failed write to standard output exited 0.
if [ -w /dev/full ]; then
  for c in "stream $work/causal.json $rec20 --rate-hz 1" "inspect --json $rec20" \
    "evaluate $work/causal.json $work/small" "simulate --print-instrument"; do
    check "$c > /dev/full fails" bash -c "'$fd' $c >/dev/full 2>'$work/full.err'; [ \$? = 1 ]"
    check "$c > /dev/full says so" grep -q "fogdrift: error: standard output: write failed (No space left on device)" "$work/full.err"
  done
fi
check "stream file output equals stdin's" cmp -s "$work/out" "$work/streamed.csv"
# A logger's lines come out as they arrive, though stream no longer flushes after every line: the
# three lines sent before a 5 s pause are out (with the header) well before it ends, from a pipe
# and from a FIFO named as the input.
check "stream answers a pipe at once" bash -c "[ \"\$( (head -4 '$rec20'; sleep 5; sed -n 5,6p '$rec20') | (timeout 2.5 '$fd' stream '$work/causal.json' - --rate-hz 1 2>/dev/null | wc -l) )\" -eq 4 ]"
mkfifo "$work/fifo"
check "stream answers a FIFO at once" bash -c "(head -4 '$rec20'; sleep 5; sed -n 5,6p '$rec20') >'$work/fifo' & [ \"\$(timeout 2.5 '$fd' stream '$work/causal.json' '$work/fifo' --rate-hz 1 2>/dev/null | wc -l)\" -eq 4 ]; s=\$?; wait; exit \$s"
check "stream clean: nothing on stderr" test ! -s "$work/err"
# Found by attack (issue 36, "stream input"): CRLF came out as "…\r,drift_dph", a BOM was
# refused, CR-only lines and a header alone exited 0 with nothing written.
printf '\xEF\xBB\xBF' >"$work/crlf.csv"
sed 's/$/\r/' "$rec20" >>"$work/crlf.csv"
tr '\n' '\r' <"$rec20" >"$work/cr.csv"
for f in crlf cr; do
  check "stream $f lines" run 0 "$fd" stream "$work/causal.json" "$work/$f.csv" --rate-hz 1
  check "stream $f lines as LF's" cmp -s "$work/out" "$work/streamed.csv"
done
head -1 "$rec20" >"$work/header_only.csv"
check "stream a header alone" run 1 "$fd" stream "$work/causal.json" "$work/header_only.csv" --rate-hz 1
check "header alone message" err_has "header_only.csv:1: has no sample after its header"
# A model trained on centred rates streams, with a warning.
check "stream a centred model" run 0 "$fd" stream "$work/svr.json" "$rec20" --rate-hz 1
check "stream centred warning" err_has "svr.json was trained with centred temperature rates"
# A wrong rate makes every step a gap: bridged and flagged, or with --strict an error.
check "stream wrong rate" run 0 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 2
check "stream wrong rate summary" err_has "samples flagged (gap"
check "stream wrong rate strict" run 1 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 2 --strict
check "stream wrong rate message" err_has "cal_r4_20C.csv:3:1: time_s steps by 1 s, not the 0.5 s of --rate-hz 2"
awk -F, 'BEGIN{OFS=","} NR==6{$3="warm"} NR==9{$2="nan"} {print}' "$rec20" >"$work/bad_temp.csv"
check "stream bad temperature" run 0 "$fd" stream "$work/causal.json" "$work/bad_temp.csv" --rate-hz 1
check "stream bad temperature bridged (temp_bad|bridged)" bash -c "sed -n 6p '$work/out' | grep -q ',129\$'"
check "stream bad gyro kept finite (gyro_bad)" bash -c "sed -n 9p '$work/out' | grep -q ',4\$'"
check "stream no non-finite output" bash -c "cut -d, -f11-15 '$work/out' | grep -qv nan"
check "stream every line out" test "$(wc -l <"$work/out")" -eq "$(wc -l <"$rec20")"
check "stream fault summary" err_has "stream: 2 of $(($(wc -l <"$rec20") - 1)) samples flagged (temp_bad 1, gyro_bad 1, bridged 1)"
check "stream bad temperature strict" run 1 "$fd" stream "$work/causal.json" "$work/bad_temp.csv" --rate-hz 1 --strict
check "stream bad temperature message" err_has "bad_temp.csv:6:3: temp_fog_degc 'warm' is not a number"
check "stream wrote the good lines before it" test "$(wc -l <"$work/out")" -eq 5
awk -F, 'BEGIN{OFS=","} NR==8{$3="300"} {print}' "$rec20" >"$work/hot.csv"
check "stream out of range strict" run 1 "$fd" stream "$work/causal.json" "$work/hot.csv" --rate-hz 1 --strict
check "stream out of range message" err_has "hot.csv:8:3: temp_fog_degc 300 is outside [-60, 125] °C (--temp-min-degc, --temp-max-degc)"
awk -F, 'BEGIN{OFS=","} NR==7{$2="1e9"} {print}' "$rec20" >"$work/spin.csv"
check "stream gyro beyond its limit strict" run 1 "$fd" stream "$work/causal.json" "$work/spin.csv" --rate-hz 1 --strict
check "stream gyro limit message" err_has "spin.csv:7:2: gyro_dph 1e+09 is beyond ±3600000 °/h (--gyro-limit-dph)"
check "stream range option" run 0 "$fd" stream "$work/causal.json" "$work/hot.csv" --rate-hz 1 --temp-max-degc 400 --temp-jump-degc 0
check "stream range option: nothing flagged" test ! -s "$work/err"
# Found by an attack (issue 36): a one-sample glitch inside the range is a jump.
check "stream a jump inside the range" run 0 "$fd" stream "$work/causal.json" "$work/hot.csv" --rate-hz 1 --temp-max-degc 400
check "the jump is flagged" err_has "stream: 1 of"
check "the jump's flag" err_has "temp_jump 1"
check "stream a jump strict" run 1 "$fd" stream "$work/causal.json" "$work/hot.csv" --rate-hz 1 --temp-max-degc 400 --strict
check "stream jump strict message" err_has "hot.csv:8: is a faulty sample (bridged|temp_jump); --strict stops at the first"
# Any sample rate (docs/compensation.md, "Any sample rate"): a 1 Hz model on a 10 Hz logger runs
# on blocks of 10 samples; stream and compensate agree byte for byte; a rate the model cannot run
# at is refused naming the option and the fix.
check "the model records its interval" grep -q '"sample_interval_s": 1.0' "$work/causal.json"
check "simulate at 10 Hz" run 0 "$fd" simulate northfind --out "$work/nf10" --temps 20 --findings 1 --rate-hz 10
check "compensate at 10 Hz" run 0 "$fd" compensate "$work/causal.json" "$work/nf10/nf_20C.csv" -o "$work/comp10.csv" -q
check "evaluate at 10 Hz" run 0 "$fd" evaluate "$work/causal.json" "$work/nf10/nf_20C.csv" --json
check "evaluate at 10 Hz: rows at the model's rate" python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["overall"]["rows"] == 36, d["overall"]["rows"]' "$work/out"
check "stream at 10 Hz" run 0 "$fd" stream "$work/causal.json" "$work/nf10/nf_20C.csv" --rate-hz 10
check "stream at 10 Hz equals compensate" bash -c "cut -d, -f1-14 '$work/out' | cmp -s - '$work/comp10.csv'"
check "stream at 10 Hz unflagged" bash -c "awk -F, 'NR>1 && \$15!=0{bad=1} END{exit bad}' '$work/out'"
# A model recording an interval finer than a stream runs at (edited here; 50 kHz) needs the
# logger's rate from the user, not 50 kHz taken as given.
sed 's/"sample_interval_s": 1.0/"sample_interval_s": 2e-05/' "$work/causal.json" >"$work/fast.json"
check "stream a model above 10 kHz" run 1 "$fd" stream "$work/fast.json" "$work/nf10/nf_20C.csv" --allow-edited
check "stream a model above 10 kHz: why" err_has "option --rate-hz: is needed: $work/fast.json was trained at 50000 Hz, above the 10000 Hz a stream runs at"
check "stream a model above 10 kHz: nothing written" test ! -s "$work/out"
# A kilohertz logger from the default instrument: its 0.1 s step is finer than asked no more, so
# the simulator integrates at the interval; 2 kHz is the highest rate.
check "simulate at 2 kHz" run 0 "$fd" simulate northfind --out "$work/nf2k" --temps 20 --findings 1 --rate-hz 2000 --position-s 20
check "2 kHz rows" python3 -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
t = [float(r[0]) for r in rows[1:]]
assert len(t) == 2000 * 80, len(t)
assert all(abs(b - a - 0.0005) < 1e-9 for a, b in zip(t, t[1:])), "not every 0.5 ms"' "$work/nf2k/nf_20C.csv"
check "simulate above 2 kHz" run 1 "$fd" simulate northfind --out "$work/nf3k" --temps 20 --findings 1 --rate-hz 3000
check "above 2 kHz message" err_has "option --rate-hz: 3000 Hz must be > 0, ≤ 2000"
check "stream slower than the model" run 1 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 0.5
check "stream slower message" err_has "option --rate-hz: the data come every 2 s (0.5 Hz), slower than the model's 1 s (1 Hz)"
check "stream not a whole fraction" run 1 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 1.5
check "stream whole fraction message" err_has "is not a whole fraction of the model's 1 s (1 Hz): put the data on the model's grid (fogdrift import ... --step-s 1)"
check "simulate at 2.5 Hz" run 0 "$fd" simulate northfind --out "$work/nf25" --temps 20 --findings 1 --rate-hz 2.5
check "compensate not a whole fraction" run 1 "$fd" compensate "$work/causal.json" "$work/nf25/nf_20C.csv" -o "$work/never.csv"
check "compensate whole fraction message" err_has "nf_20C.csv: the data's interval 0.4 s (2.5 Hz) is not a whole fraction of the model's 1 s"
check "compensate wrote nothing" test ! -e "$work/never.csv"
check "export-c at 10 Hz" run 0 "$fd" export-c "$work/causal.json" -o "$work/u10.h" --stream-rate-hz 10
check "export-c at 10 Hz: blocks of 10" grep -qF "#define FOGDRIFT_MODEL_BLOCK 10 " "$work/u10.h"
check "export-c slower than the model" run 1 "$fd" export-c "$work/causal.json" -o "$work/never.h" --stream-rate-hz 0.5
check "export-c slower message" err_has "option --stream-rate-hz: the data come every 2 s"
# Fault timings follow the model's interval unless given: a model of 10 s samples bridges 20 s.
check "simulate at 0.1 Hz" run 0 "$fd" simulate calibration --out "$work/slow" --temps 0,20,40 --repetitions 3 --rate-hz 0.1
check "train at 0.1 Hz" run 0 "$fd" train "$work/slow" --method poly --differentiator causal -q -o "$work/slow.json"
check "export-c timings from the model" run 0 "$fd" export-c "$work/slow.json" -o "$work/slow.h" --stream-rate-hz 1
check "export-c prints them" out_has "(--bridge-s 20, --hold-s 300)"
check "export-c blocks of 10" out_has "(the model once per 10 samples, its 10 s interval)"
check "the header has them" grep -qF "#define FOGDRIFT_MODEL_BRIDGE_S (20)" "$work/slow.h"
check "export-c timings given win" run 0 "$fd" export-c "$work/slow.json" -o "$work/slow.h" --stream-rate-hz 1 --bridge-s 7
check "export-c prints the given one" out_has "(--bridge-s 7, --hold-s 300)"
check "stream bad policy" run 1 "$fd" stream "$work/causal.json" "$rec20" --rate-hz 1 --hold-s 2
check "stream bad policy message" err_has "option --hold-s: 2 s must be finite and no shorter than the bridge (5 s)"
cut -d, -f1,2,3,4 "$rec20" >"$work/no_acc2.csv"
check "stream missing column" run 1 "$fd" stream "$work/causal.json" "$work/no_acc2.csv" --rate-hz 1
check "stream missing column message" err_has "no_acc2.csv:1: has no temp_acc2_degc column"
check "stream a compensated file" run 1 "$fd" stream "$work/causal.json" "$work/comp_causal.csv" --rate-hz 1
check "stream compensated message" err_has "already has a drift_dph column"
awk 'NR==4{print $0 ",extra"; next} {print}' "$rec20" >"$work/ragged.csv"
check "stream ragged line skipped" run 0 "$fd" stream "$work/causal.json" "$work/ragged.csv" --rate-hz 1
check "stream ragged note" err_has "ragged.csv:4: skipped: has 11 fields, the header 10"
check "stream ragged gap flagged" bash -c "sed -n 4p '$work/out' | grep -q ',16\$'"
check "stream ragged strict" run 1 "$fd" stream "$work/causal.json" "$work/ragged.csv" --rate-hz 1 --strict
check "stream ragged message" err_has "ragged.csv:4: has 11 fields, the header 10"
: >"$work/empty_stdin"  # not /dev/null: on some CI machines it is a plain file that fills up
check "stream empty input" run 1 "$fd" stream "$work/causal.json" - --rate-hz 1 <"$work/empty_stdin"
check "stream empty message" err_has "<stdin>:1: is empty; a header line is needed"
check "stream missing file" run 1 "$fd" stream "$work/causal.json" "$work/nonexistent.csv" --rate-hz 1
check "stream missing file message" err_has "nonexistent.csv: cannot be opened for reading"
check "stream at the model's own rate without --rate-hz" run 0 "$fd" stream "$work/causal.json" "$rec20"
check "  the same lines as --rate-hz 1" bash -c "'$fd' stream '$work/causal.json' '$rec20' --rate-hz 1 2>/dev/null | cmp -s - '$work/out'"

# --- export-c ---------------------------------------------------------------------------------
check "export-c" run 0 "$fd" export-c "$work/bp.json" -o "$work/unit.h" --prefix unit42
check "export-c summary" out_has "unit42_predict_dph(features[12])"
check "export-c streaming" run 0 "$fd" export-c "$work/bp.json" -o "$work/unit_stream.h" --prefix u --stream-rate-hz 1
check "export-c streaming summary" out_has "u_update(&state, time_s, temp_fog, temp_acc1, temp_acc2) at 1 Hz"
check "export-c warns of centred rates" out_has "train with --differentiator causal for firmware"
check "streaming header has the update" grep -qF "static inline u_real u_update(u_state* s" "$work/unit_stream.h"
if command -v cc >/dev/null; then
  check "streaming header compiles as C99" cc -std=c99 -Wall -Wextra -pedantic -Werror -fsyntax-only -x c "$work/unit_stream.h"
fi
check "streaming header has the fault policy" grep -qF "#define U_BRIDGE_S (5)" "$work/unit_stream.h"
check "export-c fault settings" run 0 "$fd" export-c "$work/bp.json" -o "$work/unit_hot.h" --prefix u --stream-rate-hz 1 --temp-max-degc 90
check "export-c fault settings in the header" grep -qF "#define U_TEMP_MAX_DEGC (90)" "$work/unit_hot.h"
check "export-c bad fault setting" run 1 "$fd" export-c "$work/bp.json" -o "$work/bad.h" --stream-rate-hz 1 --bridge-s -1
check "export-c bad fault setting message" err_has "option --bridge-s: -1 s must be ≥ 0"
check "export-c bad stream rate" run 1 "$fd" export-c "$work/bp.json" -o "$work/bad.h" --stream-rate-hz -1
check "export-c bad stream rate message" err_has "option --stream-rate-hz: -1 Hz must be between 0 and 10000"
check "export-c window too short for the rate" run 1 "$fd" export-c "$work/bp.json" -o "$work/bad.h" --stream-rate-hz 0.001
check "export-c window message names the option" err_has "option --stream-rate-hz"
check "header has the function" grep -q "static inline unit42_real unit42_predict_dph" "$work/unit.h"
check "bad prefix" run 1 "$fd" export-c "$work/bp.json" -o "$work/bad.h" --prefix 4unit
check "prefix message" err_has "option --prefix: '4unit' is not a C identifier"
check "no header on error" test ! -e "$work/bad.h"

# --- start-up approaches ------------------------------------------------------------------------
check "calibration under mixed start-ups" run 0 "$fd" simulate calibration --out "$work/mixed" \
  --temps 0,30 --repetitions 3 --approach soaked,ramping --seed 4
check "mixed campaign's manifest names the approaches" python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["generator"]["approaches"] == ["soaked", "ramping"]' "$work/mixed/campaign.json"
check "sweep is no calibration approach" run 1 "$fd" simulate calibration --out "$work/nope" --approach calibration,sweep
check "sweep message" err_has "option --approach: sweep is not a calibration approach"
check "no campaign on error" test ! -e "$work/nope"
check "bad approach name" run 1 "$fd" simulate northfind --out "$work/nope" --approach lukewarm
check "bad approach message" err_has "option --approach: 'lukewarm' is not an approach (calibration, soaked, warm, ramping, sweep)"
check "bad warm-off" run 1 "$fd" simulate northfind --out "$work/nope" --approach warm --warm-off-s -5
check "bad warm-off message" err_has "option --warm-off-s: -5 s must be between 0 and 1e6"
check "warm restarts" run 0 "$fd" simulate northfind --out "$work/nfw" --approach warm --temps 10 --findings 1
check "warm manifest" python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["generator"]["approach"] == "warm"' "$work/nfw/campaign.json"

# Found by attack (issue 36, "reader leniency"): a 10 MB number was echoed whole in its error.
python3 -c 'import sys; open(sys.argv[1], "w").write("time_s,gyro_dph,temp_fog_degc\n1,2," + "3" * 10**7 + "x\n2,3,4\n")' "$work/big_cell.csv"
check "a 10 MB cell" run 1 "$fd" inspect "$work/big_cell.csv"
check "a 10 MB cell: its start and length" err_has "big_cell.csv:2:3: column 'temp_fog_degc': value '3333333333333333333333333333333333333333…(10000001 characters)' is not a number"
check "a 10 MB cell: a short message" test "$(wc -c <"$work/err")" -lt 300

# Found by attack (issue 36, "reader leniency"): a recording that is not a file was said not to
# exist.
cp -r "$work/nfw" "$work/folder_rec"
first=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["recordings"][0]["file"])' "$work/folder_rec/campaign.json")
rm "$work/folder_rec/$first" && mkdir "$work/folder_rec/$first"
check "a recording that is a folder" run 1 "$fd" inspect "$work/folder_rec"
check "a folder is not a regular file" err_has "$first\" is not a regular file (a folder, a pipe, a device)"

# Found by attack (issue 36, "crash"): notes nested 100,000 deep overflowed the stack.
cp -r "$work/nfw" "$work/nested"
python3 - "$work/nested/campaign.json" <<'PY'
import json, sys
text = open(sys.argv[1]).read().rstrip().rstrip("}")
open(sys.argv[1], "w").write(text + ', "notes": ' + "[" * 100000 + "]" * 100000 + "}\n")
PY
for c in "inspect" "train -o $work/x.json"; do
  check "$c: a manifest nested 100,000 deep" run 1 "$fd" $c "$work/nested"
  check "$c: nesting message" err_has "nested/campaign.json:"
  check "$c: nesting rule" err_has "arrays and objects nested deeper than 64 levels"
done

# --- northfind --------------------------------------------------------------------------------
check "simulate northfind" run 0 "$fd" simulate northfind --out "$work/nf2" --temps -16,28 --seed 2
check "northfind raw" run 0 "$fd" northfind "$work/nf2"
check "northfind Table 3 view" out_has "Table 3 view, RMSE per initial temperature"
check "evaluate a north-finding campaign" run 1 "$fd" evaluate "$work/svr.json" "$work/nf2"
check "no test recordings message" err_has "campaign.json: no calibration recordings with role test in the campaign"
check "northfind with a model" run 0 "$fd" northfind "$work/nf2" --model "$work/bp.json"
check "northfind compensated column" out_has "comp. err °"
check "northfind --json" run 0 "$fd" northfind --json "$work/nf2" --model "$work/svr.json"
check "northfind json table" out_has '"compensated_rmse_deg"'
check "northfind shows the floor" out_has '"true_drift_subtracted_rmse_deg"'
check "northfind --json pairs the findings" out_has '"drift_error_removed"'
check "northfind share removed" run 0 "$fd" northfind "$work/nf2" --model "$work/svr.json" --no-guard
check "northfind names the share" out_has "of the removable error"
check "northfind names the paired share" out_has "of the drift's own error, finding by finding"
check "northfind on a calibration campaign" run 1 "$fd" northfind "$work/small"
check "northfind calibration message" err_has "no northfind or stable recordings"
check "northfind with a wider tolerance" run 0 "$fd" northfind --json "$work/nf2" --tolerance-deg 0.5 --settle-s 4
check "the findings" out_has '"raw_rmse_deg"'
check "northfind impossible tolerance" run 1 "$fd" northfind "$work/nf2" --tolerance-deg 50
check "tolerance message" err_has "option --tolerance-deg: 50 ° must be > 0, < 45"
check "northfind impossible dwell" run 1 "$fd" northfind "$work/nf2" --min-dwell-s 0
check "dwell message" err_has "option --min-dwell-s: 0 s must be > 0"
check "northfind's options described once" run 0 "$fd" options northfind --json
check "northfind's table has the guard" out_has '"flag": "--no-guard"'

echo "cli: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
