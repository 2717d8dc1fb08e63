#!/usr/bin/env bash
# Installs what is missing, builds fogdrift and runs the whole test suite with CTest.
# Usage: scripts/test.sh            Release build in build/
#        scripts/test.sh --sanitize AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "--sanitize" ]; then
  build="$root/build-asan"
  bash "$root/scripts/build.sh" "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFOGDRIFT_SANITIZE=ON
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
else
  build="$root/build"
  bash "$root/scripts/build.sh" "$build"
fi
cd "$build"
ctest --output-on-failure --parallel "$(nproc)"
