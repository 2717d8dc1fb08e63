#!/usr/bin/env bash
# Installs the Debian packages fogdrift builds and tests with, only those that are missing.
# Run as root on Debian 12 (or with sudo available). Safe to run again.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config     # toolchain
  libeigen3-dev libcli11-dev nlohmann-json3-dev libfmt-dev   # library dependencies
  libgtest-dev libgmock-dev            # tests
  libsvm-dev libsvm-tools              # LIBSVM: the reference the SVR engine is tested and benchmarked against
  python3 python3-numpy python3-pywt python3-scipy   # PyWavelets and SciPy: references for the signal tests
  gnuplot-nox                          # fogdrift paper's figures (PNG)
  pybind11-dev python3-dev             # the Python package (python/)
  python3-venv python3-pip python3-build   # installing it: pip, a virtual environment, a wheel
  python3-sklearn python3-pytest       # its tests: scikit-learn's estimator checks, its SVR and GP as references
  python3-pandas                       # recordings as DataFrames, and scikit-learn's DataFrame checks
  python3-dask python3-distributed     # fogdrift.fleet: one model per unit on a Dask cluster
  python3-tqdm                         # the progress bar of fogdrift.train, and its test
  python3-matplotlib                   # docs/python.md's worked example, run as a test
  gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm   # the C header on a Cortex-M4F
  octave liboctave-dev                 # fogdrift for Octave and MATLAB (matlab/, docs/matlab.md)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "fogdrift setup: installing ${missing[*]}" >&2
  sudo_cmd=""
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
