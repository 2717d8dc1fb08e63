#!/usr/bin/env bash
# fogdrift's wavelet denoiser against the same pipeline in PyWavelets (python3-pywt: wavedec,
# threshold per band, waverec), on the same machine in the same run. Prints a Markdown table of
# median wall times over 7 runs each and their ratio.
#
#   bash bench/denoise_vs_pywavelets.sh [BUILD_DIR]
set -euo pipefail
build=${1:-build}
python=/usr/bin/python3
echo "| N | wavelet | rule | fogdrift (ms) | PyWavelets + numpy (ms) | ratio |"
echo "|---|---|---|---|---|---|"
for n in 1800 100000 1000000; do
  for setting in "sym4 bayes" "db8 universal" "sym8 sure"; do
    set -- $setting
    ours=$("$build/bench/denoise_speed" "$n" "$1" "$2" --repeats 7 | cut -d' ' -f1)
    theirs=$("$python" - "$n" "$1" "$2" <<'PY'
import sys, time
import numpy as np
import pywt
n, name, rule = int(sys.argv[1]), sys.argv[2], sys.argv[3]
rng = np.random.default_rng(1)
x = 0.05 * np.exp(-np.arange(n) / (0.2 * n)) + 0.03 * rng.normal(size=n)
def denoise(x):
    c = pywt.wavedec(x, name, mode="symmetric")
    s = np.median(np.abs(c[-1])) / 0.6745
    out = [c[0]]
    for d in c[1:]:
        if rule == "universal":
            lam = s * np.sqrt(2 * np.log(len(x)))
        elif rule == "sure":
            w2 = np.sort((d / s) ** 2); m = len(w2); k = np.arange(1, m + 1)
            r = m - 2 * k + np.cumsum(w2) + (m - k) * w2
            lam = s * np.sqrt(w2[np.argmin(r)])
        else:
            v = np.mean(d ** 2) - s * s
            lam = s * s / np.sqrt(v) if v > 0 else np.abs(d).max()
        out.append(pywt.threshold(d, lam, mode="soft"))
    return pywt.waverec(out, name, mode="symmetric")[: len(x)]
times = []
for _ in range(7):
    t0 = time.perf_counter(); denoise(x); times.append((time.perf_counter() - t0) * 1e3)
print(f"{sorted(times)[3]:.3f}")
PY
)
    ratio=$(awk -v a="$theirs" -v b="$ours" 'BEGIN { printf "%.1f", a / b }')
    echo "| $n | $1 | $2 | $ours | $theirs | $ratio× |"
  done
done
