#!/usr/bin/env bash
# Installs what is missing, builds the fogdrift executable in Release (the tests, benchmarks and
# Python module are built by scripts/test.sh) and runs the main job: `fogdrift demo`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
FOGDRIFT_TARGET=fogdrift_cli bash "$root/scripts/build.sh" "$root/build"
exec "$root/build/apps/fogdrift/fogdrift" demo "$@"
