#!/usr/bin/env bash
# Fuzzes one reader with libFuzzer and adds what it finds to the committed corpus
# (docs/reliability.md).
# Usage: scripts/fuzz.sh TARGET SECONDS [JOBS]
#   TARGET: recording_csv campaign_json instrument_json model_json libsvm_data libsvm_model
#           feature_spec import_file (tests/fuzz/TARGET.cpp); "list" prints them.
#   The clang build is in build-fuzz/. New inputs that reach new code are merged into
#   tests/fuzz/corpus/TARGET/; a crash, leak, sanitizer report or an exception other than
#   fogdrift's InputError/OptionError stops the run, leaves the input in
#   build-fuzz/artifacts/TARGET/ and exits non-zero. Commit the corpus after fixing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
targets=$(sed -n '/^set(FOGDRIFT_FUZZ_TARGETS/,/)/p' "$root/tests/fuzz/CMakeLists.txt" |
  sed 's/^set(FOGDRIFT_FUZZ_TARGETS//' | tr -d '()' | tr -s ' \n' ' ')
if [ "${1:-}" = list ]; then echo $targets; exit 0; fi
if [ $# -lt 2 ]; then sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2; fi
target=$1
seconds=$2
jobs=${3:-1}
case " $targets " in *" $target "*) ;; *) echo "fuzz.sh: '$target' is not a target ($targets)" >&2; exit 2 ;; esac
command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ is needed (apt-get install clang)" >&2; exit 2; }
build="$root/build-fuzz"
if [ ! -f "$build/build.ninja" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DFOGDRIFT_FUZZ=ON >/dev/null
fi
cmake --build "$build" --target "fuzz_$target"
corpus="$root/tests/fuzz/corpus/$target"
found="$build/found/$target"
artifacts="$build/artifacts/$target"
mkdir -p "$found" "$artifacts"
# Model files are larger than libFuzzer's default 4 kB inputs.
max_len=4096
[ "$target" = model_json ] && max_len=20000
# With several jobs libFuzzer writes each job's log as fuzz-N.log in the working folder.
parallel=()
[ "$jobs" -gt 1 ] && parallel=(-jobs="$jobs" -workers="$jobs")
status=0
(cd "$build" && "$build/tests/fuzz/fuzz_$target" "$found" "$corpus" -max_total_time="$seconds" \
  -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "${parallel[@]}") || status=$?
# Keep only the inputs that add coverage to the committed corpus.
(cd "$build" && "$build/tests/fuzz/fuzz_$target" -merge=1 -max_len="$max_len" \
  -artifact_prefix="$artifacts/" "$corpus" "$found" 2>&1) |
  grep -E "MERGE-OUTER: [0-9]+ new files" || true
exit "$status"
