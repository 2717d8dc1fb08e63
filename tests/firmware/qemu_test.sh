#!/usr/bin/env bash
# The C header on a microcontroller (docs/firmware.md): causal BP, polynomial and SVR models are
# exported in double and float, built with examples/firmware for a Cortex-M4F (hard float) and run
# on QEMU's mps2-an386, whole recordings fed over semihosting; every output is compared with
# `fogdrift stream` on the same recording:
#   double  equal to 1e-12 relative (and the fault flags equal);
#   float   within 1e-3 of the drift's STD, and the share of the removable north-finding error
#           removed within 1 point of stream's.
# Usage: qemu_test.sh PATH/TO/fogdrift PATH/TO/examples/firmware
set -u
fd=$1
example=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
check() {  # check NAME CONDITION-COMMAND...
  local name=$1
  shift
  if "$@"; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "FAILED: $name" >&2; fi
}
quiet() { "$@" >"$work/log" 2>&1 || { sed 's/^/    /' "$work/log" >&2; return 1; }; }

# A chamber campaign and north-finding start-ups like it, at 1 Hz, and three causal models.
quiet "$fd" simulate calibration --out "$work/cal" --temps -20,10,40 --repetitions 2 --seed 3
quiet "$fd" simulate northfind --out "$work/nf" --temps -5,25 --findings 2 --seed 4
for method in bp poly; do
  check "train $method" quiet "$fd" train "$work/cal" --method "$method" --differentiator causal \
    -q -o "$work/$method.json"
done
# The SVR tuned by sparrow search, on a small budget and a small campaign (174 support vectors,
# C = 299): its share on these start-ups is poor (−81 %, worse than raw), but a real one to
# compare, and its large coefficients cancel to a small z, which is what float must survive.
# On the paper's target (--denoise): train's default, the gyro as logged, gives 438 support
# vectors and float 1.07e-3 of the drift's STD from stream (docs/firmware.md).
check "train svr" quiet "$fd" train "$work/cal" --method ssa-svr --population 6 --iterations 4 \
  --folds 2 --differentiator causal --denoise -q -o "$work/svr.json"

# firmware METHOD PRECISION: builds examples/firmware around the exported header.
firmware() {
  local h="$work/$1_$2.h" build="$work/fw_$1_$2"
  "$fd" export-c "$work/$1.json" -o "$h" --prefix unit --stream-rate-hz 1 --precision "$2" -q &&
    cmake -S "$example" -B "$build" -G Ninja -DMODEL_HEADER="$h" \
      -DCMAKE_TOOLCHAIN_FILE="$example/toolchain-cortex-m4f.cmake" >"$work/log" 2>&1 &&
    cmake --build "$build" >>"$work/log" 2>&1 || { sed 's/^/    /' "$work/log" >&2; return 1; }
}
# on_target METHOD PRECISION RECORDING OUT: runs it; instructions are counted one per ns.
on_target() {
  (cd "$(dirname "$3")" &&
    timeout 300 qemu-system-arm -machine mps2-an386 -icount shift=0 -nographic -monitor none \
      -serial none -semihosting-config "enable=on,target=native,arg=fw,arg=$(basename "$3"),arg=$4" \
      -kernel "$work/fw_$1_$2/firmware.elf") >"$work/cost_$1_$2.txt" 2>"$work/log" ||
    { sed 's/^/    /' "$work/log" >&2; return 1; }
}

# compare STREAM.csv TARGET.csv TOLERANCE KIND: drift_dph, gyro_comp_dph and the flags, line by line.
compare() {
  python3 - "$@" <<'PY'
import csv, math, sys
stream, target, tol, kind = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
s = list(csv.DictReader(open(stream)))
t = list(csv.DictReader(open(target)))
if len(s) != len(t):
    sys.exit(f"{len(t)} lines on the target, {len(s)} from stream")
drift = [float(r["drift_dph"]) for r in s]
mean = sum(drift) / len(drift)
std = math.sqrt(sum((d - mean) ** 2 for d in drift) / len(drift))
worst = 0.0
for i, (a, b) in enumerate(zip(s, t)):
    if int(a["fault_flags"]) != int(b["fault_flags"]):
        sys.exit(f"line {i + 2}: flags {b['fault_flags']} on the target, {a['fault_flags']} from stream")
    for col in ("drift_dph", "gyro_comp_dph"):
        x, y = float(a[col]), float(b[col])
        err = abs(x - y) / (abs(x) if kind == "relative" else std)
        worst = max(worst, err if x != 0 or kind != "relative" else abs(y))
if worst > tol:
    sys.exit(f"worst difference {worst:.3g} ({kind}) exceeds {tol:g}")
print(f"{worst:.3g}")
PY
}

rec="$work/nf/nf_25C.csv"
for method in bp poly svr; do
  "$fd" stream "$work/$method.json" "$rec" --rate-hz 1 >"$work/stream_$method.csv" 2>/dev/null
  for precision in double float; do
    check "$method $precision builds for the Cortex-M4F" firmware "$method" "$precision"
    check "$method $precision runs on mps2-an386" on_target "$method" "$precision" "$rec" "$work/out_${method}_$precision.csv"
    check "$method $precision output is whole" test -s "$work/out_${method}_$precision.csv"
    if [ "$precision" = double ]; then
      check "$method double equals stream to 1e-12" compare "$work/stream_$method.csv" "$work/out_${method}_$precision.csv" 1e-12 relative
    else
      check "$method float within 1e-3 of the drift's STD" compare "$work/stream_$method.csv" "$work/out_${method}_$precision.csv" 1e-3 std
    fi
    check "$method $precision cost line" grep -q "^updates $(($(wc -l <"$rec") - 1)) " "$work/cost_${method}_$precision.txt"
  done
done

# The share of the removable north-finding error the float SVR removes on the target, from its
# compensated gyro put in the recordings' place, against stream's (fogdrift northfind --model).
mkdir "$work/nf_target"
cp "$work/nf/campaign.json" "$work/nf_target/"
for r in "$work"/nf/*.csv; do
  name=$(basename "$r")
  on_target svr float "$r" "$work/target_$name" || check "svr float runs on $name" false
  python3 - "$r" "$work/target_$name" "$work/nf_target/$name" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
comp = [r["gyro_comp_dph"] for r in csv.DictReader(open(sys.argv[2]))]
with open(sys.argv[3], "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(rows[0])
    for row, g in zip(rows[1:], comp):
        row[1] = g
        w.writerow(row)
PY
done
"$fd" northfind "$work/nf" --model "$work/svr.json" --json >"$work/nf_stream.json"
"$fd" northfind "$work/nf_target" --json >"$work/nf_target.json"
share_close() {
  python3 - "$work/nf_stream.json" "$work/nf_target.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))["table3"]
t = json.load(open(sys.argv[2]))["table3"]
mean = lambda v: sum(v) / len(v)
raw, floor = mean(s["raw_rmse_deg"]), mean(s["true_drift_subtracted_rmse_deg"])
share = lambda comp: (raw ** 2 - comp ** 2) / (raw ** 2 - floor ** 2)
stream, target = share(mean(s["compensated_rmse_deg"])), share(mean(t["raw_rmse_deg"]))
print(f"share removed: stream {100 * stream:.2f} %, float on the target {100 * target:.2f} %")
sys.exit(0 if abs(stream - target) <= 0.01 else 1)
PY
}
check "svr float: north-finding share within 1 point of stream's" share_close

echo "firmware: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
