#!/usr/bin/env bash
# A fourth thermometer (docs/logs.md, "More thermometers"): a simulated campaign given a case
# thermometer and the drift it causes (scripts/add_case_thermometer.py), trained without and with
# it, then evaluated, streamed and exported with the commands of the docs only.
# Usage: thermometers_test.sh PATH/TO/fogdrift
set -u
fd=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
source "$(dirname "$0")/common.sh"
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$work" || exit 1

check "simulate" run 0 "$fd" simulate calibration --out cal --temps -20,10,40 --repetitions 3
check "add the case thermometer" python3 "$root/scripts/add_case_thermometer.py" cal

# --- train: the three by default, the fourth when named --------------------------------------
check "train on the three" run 0 "$fd" train cal -o three.json --method poly --differentiator causal
check "the fourth is said to be unread" out_has "note: temp_case_degc not read by the features 'T,dT,grad,dT@300': a further thermometer becomes a feature when named, e.g. fog,acc1,acc2,case"
check "and the option that reads it" out_has "(--thermometers)"
check "train on four" run 0 "$fd" train cal -o four.json --method poly --differentiator causal --thermometers fog,acc1,acc2,case
check "eighteen features" out_has "(18 features)"
check "no note once it is read" bash -c "! grep -q 'not read by the features' '$work/out'"
check "spec stored" bash -c "grep -q '\"spec\": \"T(fog,acc1,acc2,case),dT(fog,acc1,acc2,case),grad(fog,acc1,acc2,case),dT@300(fog,acc1,acc2,case)\"' four.json"
check "a term of --features reads the list" run 0 "$fd" train cal -o gradonly.json --method poly --features "T(fog),grad" --thermometers fog,case
check "its features" out_has "(2 features)"
check "bad thermometer name" run 1 "$fd" train cal -o x.json --thermometers fog,Case
check "bad name message" err_has "option --thermometers: 'Case' is not a thermometer"
check "a thermometer the recordings lack" run 1 "$fd" train cal -o x.json --thermometers fog,top
check "lacking message" err_has "has no temp_top_degc column, which the feature T_top_degc reads"
check "nothing written on error" test ! -e x.json

# --- evaluate: the case's drift removed only when read ---------------------------------------
check "evaluate three" run 0 "$fd" evaluate three.json cal --json
cp out three_eval.json
check "evaluate four" run 0 "$fd" evaluate four.json cal --json
cp out four_eval.json
check "four removes what three cannot" python3 - <<'PY'
import json
three = json.load(open("three_eval.json"))["overall"]
four = json.load(open("four_eval.json"))["overall"]
before, t, f = three["std_denoised_dph"], three["std_compensated_dph"], four["std_compensated_dph"]
print(f"STD {before:.4f} -> three {t:.4f}, four {f:.4f} deg/h")
assert f < 0.05 * before and t > 0.5 * before, (before, t, f)
PY

# --- stream and compensate: the fourth column read by name -----------------------------------
check "compensate" run 0 "$fd" compensate four.json cal/cal_r3_10C.csv -o comp.csv
check "stream" run 0 "$fd" stream four.json cal/cal_r3_10C.csv --rate-hz 1
cp out streamed.csv
check "stream equals compensate (causal rates)" python3 - <<'PY'
import csv
comp = list(csv.DictReader(open("comp.csv")))
stream = list(csv.DictReader(open("streamed.csv")))
assert len(comp) == len(stream) == 1800, (len(comp), len(stream))
worst = max(abs(float(a["drift_dph"]) - float(b["drift_dph"])) for a, b in zip(comp, stream))
assert worst <= 1e-9, worst
PY
check "a stream without the case column" bash -c "cut -d, -f1-5 cal/cal_r3_10C.csv > nocase.csv"
check "is refused" run 1 "$fd" stream four.json nocase.csv --rate-hz 1
check "naming the column" err_has "nocase.csv:1: has no temp_case_degc column"
check "the three-thermometer model streams it" run 0 "$fd" stream three.json nocase.csv --rate-hz 1

# --- export-c: update takes the fourth temperature -------------------------------------------
check "export-c" run 0 "$fd" export-c four.json -o four.h --stream-rate-hz 1 --prefix unit
check "update's arguments" out_has "unit_update(&state, time_s, temp_fog, temp_acc1, temp_acc2, temp_case) at 1 Hz"
check "four thermometers in the header" grep -qF "#define UNIT_N_THERMOMETERS 4 /* fog, acc1, acc2, case */" four.h
check "the header compiles" bash -c "printf '#include \"four.h\"\nint main(void) { unit_state s; unit_reset(&s); return unit_update(&s, 1.0, 20, 20, 20, 21) != unit_update(&s, 1.0, 20, 20, 20, 21); }\n' > main.c && cc -std=c99 -Wall -Wextra -pedantic -Werror -o main main.c -lm && ./main"

echo "thermometers: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
