#!/usr/bin/env bash
# Runs one Octave test script (tests/matlab/*.m) in a fresh folder: octave_svm, octave_workflow.
# Usage: run_octave.sh SCRIPT.m   (FOGDRIFT_MATLAB_DIR and the script's other variables set)
set -euo pipefail
script=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
octave-cli --no-window-system --norc "$script" 2>&1 | tee out.txt
grep -q "^all passed$" out.txt
