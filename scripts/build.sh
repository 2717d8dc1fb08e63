#!/usr/bin/env bash
# Configures and builds fogdrift. Usage: scripts/build.sh [BUILD_DIR] [extra cmake args...]
# FOGDRIFT_TARGET=NAME builds that target alone (scripts/demo.sh: the fogdrift executable).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-"$root/build"}
shift || true
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
if [ -n "${FOGDRIFT_TARGET:-}" ]; then
  cmake --build "$build" --parallel "$(nproc)" --target "$FOGDRIFT_TARGET"
else
  cmake --build "$build" --parallel "$(nproc)"
fi
