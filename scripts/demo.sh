#!/usr/bin/env bash
# Installs what is missing, builds fogdrift in Release and runs the main job: `fogdrift demo`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh" "$root/build"
exec "$root/build/apps/fogdrift/fogdrift" demo "$@"
