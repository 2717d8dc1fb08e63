#!/usr/bin/env bash
# The C header on a Cortex-M4F (docs/firmware.md, "What it costs"): flash, RAM and instructions
# per update of the paper's BP, polynomial and SSA-SVR models (causal rates, trained with
# `fogdrift train`'s defaults on the paper's calibration campaign, seed 1), in double and float.
#   flash   .text + .rodata of the compensator alone (examples/firmware/footprint.c) linked with
#           the C library's functions it calls, unused code removed (--gc-sections)
#   RAM     .data + .bss of the same (the state) + the deepest stack one update used on the target
#   instructions per update  over the 1800 samples of the test start-up at 20 °C (cal_r4_20C),
#           on QEMU's mps2-an386 with -icount (one instruction per ns; SysTick turned into
#           instructions by a calibrated loop), mean and largest
# Usage: bench/firmware_footprint.sh [BUILD_DIR]   (default build/); prints a Markdown table.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fd=${1:-$root/build}/apps/fogdrift/fogdrift
example=$root/examples/firmware
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$fd" simulate calibration --out "$work/cal" --seed 1 >/dev/null
"$fd" train "$work/cal" --method bp --differentiator causal -q -o "$work/bp.json"
"$fd" train "$work/cal" --method poly --differentiator causal -q -o "$work/poly.json"
"$fd" train "$work/cal" --method ssa-svr --differentiator causal -q -o "$work/ssa-svr.json"
rec=$work/cal/cal_r4_20C.csv

echo "| model | precision | flash, bytes (text + rodata) | RAM, bytes (data + bss + stack) | instructions per update, mean (largest) |"
echo "|---|---|---|---|---|"
for method in bp poly ssa-svr; do
  size=$(python3 -c "import json,sys; m=json.load(open(sys.argv[1]))['regressor']; print({'svr': lambda: f\"{len(m['coef'])} support vectors\", 'mlp': lambda: f\"{m['hidden']} hidden units\", 'poly': lambda: f\"{len(m['coef'])} terms\"}[m['type']]())" "$work/$method.json")
  for precision in double float; do
    h=$work/${method}_$precision.h
    b=$work/fw_${method}_$precision
    "$fd" export-c "$work/$method.json" -o "$h" --prefix unit --stream-rate-hz 1 --precision "$precision" -q
    cmake -S "$example" -B "$b" -G Ninja -DMODEL_HEADER="$h" \
      -DCMAKE_TOOLCHAIN_FILE="$example/toolchain-cortex-m4f.cmake" >/dev/null
    cmake --build "$b" >/dev/null
    obj=$(find "$b" -name 'footprint.c.obj' | head -1)
    arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 "$obj" \
      -nostartfiles --specs=nosys.specs -Wl,--gc-sections -Wl,-e,fogdrift_update \
      -Wl,-u,fogdrift_compensated -Wl,-u,fogdrift_power_on -lm -o "$b/alone.elf"
    read -r text rodata data bss < <(arm-none-eabi-size -A "$b/alone.elf" | awk '
      $1 ~ /^\.text/ {t += $2} $1 ~ /^\.rodata/ {r += $2} $1 ~ /^\.data/ {d += $2}
      $1 ~ /^\.bss/ {s += $2} END {print t + 0, r + 0, d + 0, s + 0}')
    (cd "$work/cal" && qemu-system-arm -machine mps2-an386 -icount shift=0 -nographic -monitor none \
      -serial none -semihosting-config "enable=on,target=native,arg=fw,arg=$(basename "$rec"),arg=out.csv" \
      -kernel "$b/firmware.elf") >"$work/cost.txt"
    read -r n total largest stack per2m < <(awk '{print $2, $4, $6, $8, $12}' "$work/cost.txt")
    python3 - "$method ($size)" "$precision" "$text" "$rodata" "$data" "$bss" "$stack" "$n" "$total" "$largest" "$per2m" <<'PY'
import sys
name, precision = sys.argv[1], sys.argv[2]
text, rodata, data, bss, stack, n, total, largest, per2m = map(int, sys.argv[3:])
per_tick = 2_000_000 / per2m
print(f"| {name} | {precision} | {text + rodata:,} ({text:,} + {rodata:,}) | "
      f"{data + bss + stack:,} ({data:,} + {bss:,} + {stack:,}) | "
      f"{total * per_tick / n:,.0f} ({largest * per_tick:,.0f}) |")
PY
  done
done
