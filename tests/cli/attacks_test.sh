#!/usr/bin/env bash
# The attacks of a tester on fogdrift's outputs, each a regression test named after it: outputs
# that are links, devices or inputs; interrupted runs; C injected through a model file; axes that
# make no C; data at another rate; quoted CSV on the stream; edited models; a float header far
# from its model; and the messages that named the wrong culprit (docs/reliability.md).
# Usage: attacks_test.sh PATH/TO/fogdrift
set -u
fd=$1
source "$(dirname "$0")/common.sh"
cc=${CC:-cc}

check "campaign" run 0 "$fd" simulate calibration --out "$work/cal" --seed 3 --temps 0,40 --repetitions 3
check "causal model" run 0 "$fd" train "$work/cal" -o "$work/m.json" --method svr --differentiator causal -q
rec="$work/cal/cal_r3_40C.csv"

# --- outputs: one rule for every -o -----------------------------------------------------------
# -o /dev/stdout writes through the descriptor: the shell's file gets the header, /dev/stdout
# stays the link it was.
link_before=$(readlink /dev/stdout)
"$fd" export-c "$work/m.json" -o /dev/stdout -q >"$work/stdout.h" 2>"$work/err"
check "-o /dev/stdout exits 0" [ $? -eq 0 ]
check "-o /dev/stdout fills the redirected file" grep -q "fogdrift_model_predict_dph" "$work/stdout.h"
check "-o /dev/stdout leaves /dev/stdout a link" [ -L /dev/stdout ]
check "-o /dev/stdout leaves its target" [ "$(readlink /dev/stdout)" = "$link_before" ]
# >> appends, as the shell asked.
echo "/* kept */" >"$work/appended.h"
"$fd" export-c "$work/m.json" -o /dev/stdout -q >>"$work/appended.h"
check "-o /dev/stdout with >> appends" bash -c "head -1 '$work/appended.h' | grep -qF '/* kept */' && grep -q predict_dph '$work/appended.h'"
# A closed standard output is an error, never a file that takes its number.
"$fd" export-c "$work/m.json" -o /dev/stdout -q >&- 2>"$work/err"
check "-o /dev/stdout with stdout closed exits 1" [ $? -eq 1 ]
check "  and says the descriptor is closed" err_has "descriptor 1 is closed"
check "-o /dev/stdout with stdout closed leaves /dev/stdout a link" [ -L /dev/stdout ]
# -o LINK writes the link's target; the link stays a link.
echo "old" >"$work/target.h"
ln -s "$work/target.h" "$work/link.h"
check "-o LINK" run 0 "$fd" export-c "$work/m.json" -o "$work/link.h" -q
check "  the link is still a link" [ -L "$work/link.h" ]
check "  its target holds the header" grep -q predict_dph "$work/target.h"
ln -s "$work/absent.h" "$work/dangling.h"
check "-o DANGLING_LINK creates its target" run 0 "$fd" export-c "$work/m.json" -o "$work/dangling.h" -q
check "  the dangling link now leads to the header" bash -c "[ -L '$work/dangling.h' ] && grep -q predict_dph '$work/absent.h'"
check "-o FOLDER is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/cal" -q
check "  naming the rule" err_has "is a folder; name a file"

# An output that is an input is refused before any work, the input left as it was.
cp "$work/cal/campaign.json" "$work/campaign.before"
check "train -o CAMPAIGN/campaign.json is refused" run 1 "$fd" train "$work/cal" -o "$work/cal/campaign.json" --method svr -q
check "  naming the input" err_has "which this run reads"
check "  the manifest is untouched" cmp -s "$work/campaign.before" "$work/cal/campaign.json"
cp "$work/cal/cal_r1_40C.csv" "$work/r1.before"
check "train -o A_RECORDING is refused" run 1 "$fd" train "$work/cal" -o "$work/cal/cal_r1_40C.csv" --method svr -q
check "  because it is an input" err_has "which this run reads"
check "  the recording is untouched" cmp -s "$work/r1.before" "$work/cal/cal_r1_40C.csv"
cp "$work/m.json" "$work/m.before"
check "export-c MODEL -o MODEL is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/m.json"
check "  because it is an input" err_has "which this run reads"
check "  the model is untouched" cmp -s "$work/m.before" "$work/m.json"
ln -s "$work/m.json" "$work/m_link.json"
check "export-c MODEL -o LINK_TO_MODEL is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/m_link.json"
check "  because it is an input" err_has "which this run reads"
check "  the model is untouched" cmp -s "$work/m.before" "$work/m.json"
cp "$rec" "$work/in.csv"
check "compensate -o INPUT is refused" run 1 "$fd" compensate "$work/m.json" "$work/in.csv" -o "$work/in.csv"
check "  because it is an input" err_has "which this run reads"
check "  the recording is untouched" cmp -s "$rec" "$work/in.csv"
check "denoise -o INPUT is refused" run 1 "$fd" denoise "$work/in.csv" -o "$work/in.csv"
check "  because it is an input" err_has "which this run reads"
check "  the recording is untouched" cmp -s "$rec" "$work/in.csv"
check "simulate --out FOLDER_HOLDING_ITS_INSTRUMENT --force is refused" bash -c "
  '$fd' simulate --print-instrument >'$work/cal/instrument.json' &&
  '$fd' simulate calibration --out '$work/cal' --force --instrument '$work/cal/instrument.json' \
    --temps 0,40 --repetitions 2 >/dev/null 2>'$work/err'; [ \$? -eq 1 ] && [ -f '$work/cal/instrument.json' ] &&
  grep -q 'is or holds the input' '$work/err'"
rm -f "$work/cal/instrument.json"

# A late write error (EIO at fsync: a network file system, a quota) is an error, and nothing is
# renamed into place.
cat >"$work/eio.c" <<'C'
#include <errno.h>
int fsync(int fd) { (void)fd; errno = EIO; return -1; }
C
if "$cc" -shared -fPIC -o "$work/eio.so" "$work/eio.c" 2>/dev/null; then
  check "fsync failing with EIO" run 1 env LD_PRELOAD="$work/eio.so" ASAN_OPTIONS="${ASAN_OPTIONS:-}:verify_asan_link_order=0" "$fd" export-c "$work/m.json" -o "$work/eio.h"
  check "  is an error naming the reason" err_has "write failed at sync (Input/output error)"
  check "  and writes nothing" bash -c "[ ! -e '$work/eio.h' ] && ! ls -A '$work' | grep -q '\.eio\.h\.tmp-'"
fi

ln -s "$work/loop_b.h" "$work/loop_a.h"
ln -s "$work/loop_a.h" "$work/loop_b.h"
check "-o A_LINK_LOOP is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/loop_a.h"
check "  naming the loop" err_has "more than 40 symbolic links"
cp "$rec" "$work/join_in.csv"
check "join -o ITS_RECORDING is refused" run 1 "$fd" join "$work/join_in.csv" "$rec" -o "$work/join_in.csv" --offset-s 0
check "  naming the input" err_has "which this run reads"
check "  the recording is untouched" cmp -s "$rec" "$work/join_in.csv"
check "campaign --force over the folder holding its recording is refused" \
  run 1 "$fd" campaign "$work/cal" "$work/cal/cal_r2_40C.csv" "$work/cal/cal_r3_40C.csv" \
  --input-rate-dph 0 --test 2 --force
check "  naming the input" err_has "is or holds the input"
check "  the campaign is untouched" cmp -s "$work/campaign.before" "$work/cal/campaign.json"

# A long output name the file system takes is written; the temporary does not make it too long.
long=$(printf 'n%.0s' $(seq 1 250))
check "a 250-character output name" run 0 "$fd" export-c "$work/m.json" -o "$work/$long" -q
check "  is written" [ -s "$work/$long" ]

# SIGINT, SIGTERM and SIGHUP remove the run's temporaries and exit 128 + the signal: each sent
# once the run's temporary folder exists, so it lands mid-write.
for sig in INT TERM HUP; do
  rm -rf "$work/sig"
  "$fd" simulate calibration --out "$work/sig" --seed 1 --repetitions 6 --rate-hz 10 \
    --temps -40,-20,0,20,40,60 >/dev/null 2>"$work/sig.err" &
  pid=$!
  seen=no
  for _ in $(seq 1 1000); do
    if ls -A "$work" | grep -q '^\.sig\.tmp-'; then seen=yes; break; fi
    sleep 0.005
  done
  kill -s "$sig" "$pid" 2>/dev/null
  wait "$pid"
  status=$?
  code=$((128 + $(kill -l "$sig")))
  check "simulate stopped by SIG$sig mid-write exits $code" bash -c "[ $seen = yes ] && [ $status -eq $code ]"
  check "  and says so" grep -q "stopped by SIG$sig" "$work/sig.err"
  check "  and leaves no temporary" bash -c "! ls -A '$work' | grep -q '\.sig\.tmp-'"
  check "  and no output" [ ! -e "$work/sig" ]
done

# --- generated code: nothing from a model file outside an escaped literal or comment ---------
edit_model() {  # edit_model IN OUT PYTHON-STATEMENTS-ON-m
  python3 - "$1" "$2" "$3" <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(m, open(sys.argv[2], "w"), indent=2)
EOF
}
copy_campaign() {  # copy_campaign SRC DST PYTHON: run on each recording's rows, g the gyro's column
  python3 - "$1" "$2" "$3" <<'EOF'
import csv, json, os, sys
src, dst = sys.argv[1], sys.argv[2]
os.makedirs(dst, exist_ok=True)
manifest = json.load(open(os.path.join(src, "campaign.json")))
for e in manifest["recordings"]:
    rows = list(csv.reader(open(os.path.join(src, e["file"]))))
    g = rows[0].index("gyro_dph")
    exec(sys.argv[3])
    csv.writer(open(os.path.join(dst, e["file"]), "w", newline="")).writerows(rows)
    e.pop("sha256", None)
json.dump(manifest, open(os.path.join(dst, "campaign.json"), "w"), indent=2)
EOF
}
edit_model "$work/m.json" "$work/evil_method.json" \
  'm["provenance"]["method"] = "svr */ int evil = 42; /* \\\n ??/"; m["provenance"]["fogdrift_version"] = "1\"; int evil2;"'
check "injected method and version: the header is written (--allow-edited)" \
  run 0 "$fd" export-c "$work/evil_method.json" --allow-edited -o "$work/evil.h" --stream-rate-hz 1 -q
check "  and compiles with -Wall -Werror" "$cc" -std=c99 -Wall -Wextra -Werror -pedantic -fsyntax-only -x c "$work/evil.h"
for name in evil evil2; do
  printf '#include "evil.h"\nint main(void) { return %s; }\n' "$name" >"$work/use_$name.c"
  check "  declaring no '$name', as the model's text tried" \
    bash -c "! '$cc' -std=c99 -fsyntax-only -I'$work' '$work/use_$name.c' 2>/dev/null"
done
check "  the text kept, escaped, in its comment" grep -qF 'svr \x2a\x2f int evil = 42;' "$work/evil.h"
edit_model "$work/m.json" "$work/evil_names.json" \
  'm["features"]["names"][0] = "T_fog_degc*/ int evil = 42; /*"'
check "a feature name not its spec's is refused on load" run 1 "$fd" export-c "$work/evil_names.json" --allow-edited -o "$work/x.h"
check "  naming the field" err_has "features.names"
edit_model "$work/m.json" "$work/reordered.json" \
  'n = m["features"]["names"]; n[0], n[1] = n[1], n[0]'
check "reordered feature names are refused on load" run 1 "$fd" compensate "$work/reordered.json" "$rec" --allow-edited -o "$work/x.csv"
check "--prefix _math is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/x.h" --prefix _math
check "  saying why" err_has "C reserves such names"
check "--prefix 1x is refused" run 1 "$fd" export-c "$work/m.json" -o "$work/x.h" --prefix 1x

# Axes that would make no C are refused at train --targets (and again at export-c).
copy_campaign "$work/cal" "$work/axes" '
for name in ("gyro_gyro_dph", "gyro_accel_x_dph", "gyro_1_dph", "gyro_int_dph", "gyro_comp_dph"):
    rows[0].append(name)
    for r in rows[1:]:
        r.append(r[g])'
for targets in gyro_dph,gyro_gyro_dph gyro_accel_x_dph,accel_x_g gyro_1_dph gyro_int_dph gyro_comp_dph; do
  check "train --targets $targets is refused" run 1 "$fd" train "$work/axes" -o "$work/x.json" --method poly --targets "$targets" -q
  check "  naming --targets" err_has "--targets"
done
check "the same campaign trains on an axis of its own" \
  run 0 "$fd" train "$work/axes" -o "$work/two.json" --method poly --targets gyro_dph -q

# --- rates: one tolerance for a step at the model's interval --------------------------------
python3 - "$rec" "$work/twice.csv" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
t = rows[0].index("time_s")
for r in rows[1:]:
    r[t] = repr(float(r[t]) / 2)
csv.writer(open(sys.argv[2], "w", newline="")).writerows(rows)
EOF
check "2 Hz data streamed as 1 Hz" run 0 "$fd" stream "$work/m.json" "$work/twice.csv" --rate-hz 1
check "  is flagged off_interval" err_has "off_interval"
check "  on every sample after the first" python3 -c "
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
sys.exit(any(int(r['fault_flags']) & 2048 == 0 for r in rows[1:]))" "$work/out"
check "stream without --rate-hz runs at the model's rate" run 0 "$fd" stream "$work/m.json" "$rec"
cp "$work/out" "$work/stream_default.csv"
check "  the same lines as --rate-hz 1" bash -c "'$fd' stream '$work/m.json' '$rec' --rate-hz 1 2>/dev/null | cmp -s - '$work/stream_default.csv'"
check "an explicit --rate-hz 0 is refused, not taken as the default" run 1 "$fd" stream "$work/m.json" "$rec" --rate-hz 0
check "  naming the range" err_has "option --rate-hz: 0 Hz must be > 0, ≤ 10000"
check "a rate far from the model's is refused" run 1 "$fd" stream "$work/m.json" "$rec" --rate-hz 1.3
check "  naming --rate-hz" err_has "--rate-hz"

# --- CSV: stream reads what compensate reads -----------------------------------------------
python3 - "$rec" "$work/quoted.csv" <<'EOF'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
csv.writer(open(sys.argv[2], "w", newline=""), quoting=csv.QUOTE_ALL).writerows(rows)
EOF
check "a fully quoted file streams" run 0 "$fd" stream "$work/m.json" "$work/quoted.csv"
check "  with the drift of the unquoted file" bash -c "
  cut -d, -f1 --complement '$work/out' >/dev/null &&
  paste -d'|' <(awk -F, '{print \$NF}' '$work/out') <(awk -F, '{print \$NF}' '$work/stream_default.csv') | awk -F'|' 'NR>1 && \$1!=\$2 {bad=1} END{exit bad}'"
check "  and no flag" bash -c "awk -F, 'NR>1 && \$NF!=0 {bad=1} END{exit bad}' '$work/out'"
{ head -3 "$rec"; printf '"%s\n' "$(sed -n 4p "$rec")"; tail -n +5 "$rec" | head -3; } >"$work/torn.csv"
check "an unterminated quote is skipped, never echoed with outputs" run 0 "$fd" stream "$work/m.json" "$work/torn.csv"
check "  and reported" err_has "unterminated quoted field"
cp "$work/out" "$work/torn_out.csv"
check "  the output reads back" run 0 "$fd" inspect "$work/torn_out.csv"
check "  --strict stops at it" run 1 "$fd" stream "$work/m.json" "$work/torn.csv" --strict
{ head -2 "$rec"; sed -n 3p "$rec" | sed 's/,/,\x00/2'; } >"$work/nul.csv"
check "a NUL in a cell with --strict" run 1 "$fd" stream "$work/m.json" "$work/nul.csv" --strict
check "  the message keeps its rule after the NUL" err_has 'is not a number'

# --- models: bounded numbers, the same rule in every path -----------------------------------
edit_model "$work/m.json" "$work/huge_mean.json" 'm["scalers"]["features"]["mean"][0] = 1.7e308'
check "a feature mean of 1.7e308 is refused" run 1 "$fd" compensate "$work/huge_mean.json" "$rec" --allow-edited -o "$work/x.csv"
check "  naming the field" err_has "scalers.features.mean"
edit_model "$work/m.json" "$work/tiny_scale.json" 'm["scalers"]["features"]["scale"][0] = 5e-324'
check "a feature scale of 5e-324 is refused" run 1 "$fd" stream "$work/tiny_scale.json" "$rec" --allow-edited
check "  naming the field" err_has "scalers.features.scale"
edit_model "$work/m.json" "$work/huge_coef.json" \
  'r = m["regressor"]; k = next(k for k in r if isinstance(r[k], list)); r[k][0] = 1e300'
check "a regressor number of 1e300 is refused" run 1 "$fd" export-c "$work/huge_coef.json" --allow-edited -o "$work/x.h"
check "  naming the regressor" err_has "regressor"

edit_model "$work/m.json" "$work/huge_drift_scale.json" 'm["scalers"]["drift_dph"]["scale"] = 1e300'
check "a drift scale of 1e300 is refused" run 1 "$fd" compensate "$work/huge_drift_scale.json" "$rec" --allow-edited -o "$work/x.csv"
check "  naming the field" err_has "scalers.drift_dph.scale"
edit_model "$work/m.json" "$work/huge_radius.json" 'm["guard"]["radius"] = 1e300'
check "a guard radius of 1e300 is refused" run 1 "$fd" compensate "$work/huge_radius.json" "$rec" --allow-edited -o "$work/x.csv"
check "  naming the field" err_has "guard.radius"
check "stream of a model that records no rate, without --rate-hz" \
  run 1 "$fd" stream "$(dirname "$0")/../data/models/bp_v2.json" "$rec" --allow-old-format
check "  asks for --rate-hz" err_has "--rate-hz: is needed"

# --- a float header that departs from its model is refused ---------------------------------
edit_model "$work/m.json" "$work/micro.json" '
s = m["scalers"]["features"]
for k in range(len(s["scale"])):
    s["scale"][k] = 1e-6
    s["mean"][k] = 25.0'
check "a float header of micro-degree inputs is refused" run 1 "$fd" export-c "$work/micro.json" --allow-edited --precision float -o "$work/x.h"
check "  naming --precision and the fix" err_has "--force-float"
check "  and written with --force-float, warned" run 0 "$fd" export-c "$work/micro.json" --allow-edited --precision float --force-float -o "$work/x.h" -q
check "  the warning" err_has "warning: in float"
check "the default model's float header passes the check" run 0 "$fd" export-c "$work/m.json" --precision float -o "$work/f.h" -q

# --- messages that named the wrong culprit -----------------------------------------------------
check "a model where a campaign belongs" run 1 "$fd" train "$work/m.json" -o "$work/x.json"
check "  says it is a model" err_has "(a model), not a campaign manifest"
copy_campaign "$work/cal" "$work/flat" '
for r in rows[1:]:
    r[g] = "0"
e["input_rate_dph"] = 0
e.pop("true_azimuth_deg", None)'
check "an all-zero gyro" run 1 "$fd" train "$work/flat" -o "$work/x.json" --method poly
check "  is blamed on the target, not on --features" err_has "the drift to learn"

echo "attacks: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
