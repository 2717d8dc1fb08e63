#!/usr/bin/env bash
# Ctrl-C in Octave stops fogdrift.train's search (octave_interrupt, docs/matlab.md): SIGINT two
# seconds into a search of many minutes, and Octave must be back within five more seconds,
# without the model file. (Octave takes the interrupt itself once the call returns, so the
# script sees neither the end of train nor its fogdrift:interrupted error.)
# Usage: interrupt_test.sh MATLAB_DIR CLI
set -euo pipefail
matlab_dir=$1 cli=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$cli" simulate calibration --out cal --seed 1 >/dev/null
cat >long_train.m <<OCTAVE
addpath('$matlab_dir');
try
  fogdrift.train('cal', 'population', 200, 'iterations', 500, 'out', 'model.json', 'progress', false);
  disp('finished');
catch e
  disp(e.identifier);
end
OCTAVE
start_ms=$(($(date +%s%N) / 1000000))
octave-cli long_train.m >out.txt 2>&1 &
pid=$!
sleep 2
kill -INT "$pid"
wait "$pid" || true
elapsed_ms=$(($(date +%s%N) / 1000000 - start_ms))
cat out.txt
if grep -q finished out.txt; then echo "FAIL: the search was not interrupted"; exit 1; fi
[ ! -e model.json ] || { echo "FAIL: a model was written"; exit 1; }
if [ "$elapsed_ms" -gt 7000 ]; then echo "FAIL: took ${elapsed_ms} ms"; exit 1; fi
echo "ok  back ${elapsed_ms} ms after the start (SIGINT at 2000 ms)"
