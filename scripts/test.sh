#!/usr/bin/env bash
# Installs what is missing, builds fogdrift and runs the whole test suite with CTest.
# Usage: scripts/test.sh            Release build in build/
#        scripts/test.sh --sanitize AddressSanitizer + UndefinedBehaviorSanitizer build in build-asan/
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "--sanitize" ]; then
  build="$root/build-asan"
  # The benchmarks are built (and so checked) by the Release pass; the sanitizer pass skips them.
  # -Og compiles the instrumented code in less than half the time -O2 takes (measured: 18 s
  # against 41 s for src/model/model.cpp), which keeps CI inside its time; -g1 keeps function names
  # and line tables for the sanitizers' stack traces.
  bash "$root/scripts/build.sh" "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFOGDRIFT_SANITIZE=ON \
    -DFOGDRIFT_BUILD_BENCH=OFF -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # The paper's experiment run again at its scale adds no code path the pass has not checked: the
  # Release pass runs these; here they would take a third of the pass (measured: 273 of 1109 s
  # of tests). Paper.RunsEveryMethodOnEverySeedAndReportsIt and cli_kill's small paper keep
  # report/ and `fogdrift paper` under the sanitizers; the SVR engine's other tests keep it.
  skip='^(cli_paper|Paper\.AnotherMethodIsARowOfEveryTable|Paper\.SameSeedSameResultWhateverTheThreads|SvrVsLibsvm\.AgreesOnFiveDataSetsOverAGridOfCSigmaAndEpsilon)$'
else
  build="$root/build"
  bash "$root/scripts/build.sh" "$build"
  skip=''
fi
cd "$build"
if [ -n "$skip" ]; then
  ctest --output-on-failure --parallel "$(nproc)" --exclude-regex "$skip"
else
  ctest --output-on-failure --parallel "$(nproc)"
fi
