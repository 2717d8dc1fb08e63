#!/usr/bin/env bash
# Whole commands side by side: `fogdrift svr train` against Debian's `svm-train`, process start,
# file reading and model writing included, on the bench's data (startup_like(N), d = 9).
# Prints, for C = 1, 10 and 100 (σ = 1, ε = 0.1, tolerance 1e-3, shrinking, 100 MB cache for
# both), the median wall time of RUNS runs of each, run in turn, and their ratio.
# Usage: bench/svr_command_vs_svm_train.sh [BUILD_DIR] [N] [RUNS]
set -euo pipefail
build=${1:-build}
n=${2:-6000}
runs=${3:-7}
fd="$build/apps/fogdrift/fogdrift"
command -v svm-train >/dev/null || { echo "svm-train not found (apt-get install libsvm-tools)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/bench/svr_vs_libsvm" --write-data "$n" "$work/data.txt"

seconds() {  # seconds CMD...: wall time of one run
  local start end
  start=$(date +%s%N)
  "$@" >/dev/null
  end=$(date +%s%N)
  echo "scale=4; ($end - $start) / 1000000000" | bc
}
median() { sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }

echo "| N | C | svm-train s | fogdrift svr train s | speed-up |"
echo "|---|---|---|---|---|"
for c in 1 10 100; do
  : >"$work/l" && : >"$work/f"
  for ((r = 0; r < runs; r++)); do
    seconds svm-train -s 3 -t 2 -g 0.5 -c "$c" -p 0.1 -e 0.001 -m 100 -q "$work/data.txt" \
      "$work/l.model" >>"$work/l"
    seconds "$fd" svr train -g 0.5 -c "$c" -p 0.1 -e 0.001 -m 100 -q "$work/data.txt" \
      "$work/f.model" >>"$work/f"
  done
  l=$(median <"$work/l")
  f=$(median <"$work/f")
  printf "| %s | %s | %.3f | %.3f | %.1f× |\n" "$n" "$c" "$l" "$f" "$(echo "$l / $f" | bc -l)"
done
