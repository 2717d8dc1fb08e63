#!/usr/bin/env python3
"""Writes the PyWavelets and SciPy reference the signal tests compare fogdrift against.

Run by the build (tests/CMakeLists.txt) with Debian's python3-pywt; the output goes to the build
folder, not the repository. For every wavelet fogdrift offers, every extension mode and odd and
even signal lengths it records pywt.wavedec's coefficients and pywt.waverec's reconstruction, and
for a set of drift-plus-noise signals the result of wavelet-threshold denoising written here
directly with numpy and pywt (universal, level-dependent, SURE and BayesShrink thresholds, soft
and hard), so the C++ denoiser is checked against an independent implementation. For the
temperature differentiator it records scipy.signal.savgol_filter's first derivative (mode='interp')
of quantised, noisy temperature ramps (Debian's python3-scipy).

Usage: make_signal_reference.py OUTPUT.json
"""
import json
import os
import warnings
import sys

import numpy as np
import pywt
from scipy.signal import savgol_filter

NAMES = ([f"db{i}" for i in range(1, 21)] + [f"sym{i}" for i in range(2, 21)] +
         [f"coif{i}" for i in range(1, 6)])
MODES = ["symmetric", "periodization", "zero", "periodic"]
LENGTHS = [5, 16, 33, 128, 257]


def dwt_cases(rng):
    cases = []
    for name in NAMES:
        w = pywt.Wavelet(name)
        for mode in MODES:
            for n in LENGTHS:
                x = rng.normal(size=n) * 3.0 + np.linspace(0.0, 5.0, n)
                max_level = pywt.dwt_max_level(n, w.dec_len)
                for level in sorted({1, max(max_level, 1)}):
                    coeffs = pywt.wavedec(x, w, mode=mode, level=level)
                    rec = pywt.waverec(coeffs, w, mode=mode)
                    cases.append({"wavelet": name, "mode": mode, "level": level,
                                  "max_level": max_level, "x": x.tolist(),
                                  "coeffs": [c.tolist() for c in coeffs],
                                  "waverec": rec.tolist()})
    return cases


def mad_sigma(d):
    return np.median(np.abs(d)) / 0.6745


def sure_threshold(d, sigma):
    w2 = np.sort((d / sigma) ** 2)
    n = len(w2)
    k = np.arange(1, n + 1)
    risks = n - 2 * k + np.cumsum(w2) + (n - k) * w2
    best = np.argmin(risks)
    return sigma * np.sqrt(w2[best]) if risks[best] < n else 0.0


def denoise(x, name, mode, level, rule, shrink):
    coeffs = pywt.wavedec(x, name, mode=mode, level=level)
    sigma = mad_sigma(coeffs[-1])
    universal = np.sqrt(2 * np.log(len(x)))
    out = [coeffs[0]]
    for d in coeffs[1:]:
        if rule == "universal":
            lam = sigma * universal
        elif rule == "level":
            lam = mad_sigma(d) * universal
        elif rule == "sure":
            lam = sure_threshold(d, sigma)
        else:  # bayes
            sx2 = np.mean(d ** 2) - sigma ** 2
            lam = sigma ** 2 / np.sqrt(sx2) if sx2 > 0 else np.nextafter(np.max(np.abs(d)), np.inf)
        out.append(pywt.threshold(d, lam, mode=shrink))
    return pywt.waverec(out, name, mode=mode)[: len(x)]


def denoise_cases(rng):
    cases = []
    settings = [("db4", "symmetric", None), ("sym8", "symmetric", 6), ("coif3", "periodization", 5),
                ("db1", "zero", 4), ("db10", "periodic", 3)]
    for n in [1000, 1801]:
        t = np.arange(n, dtype=float)
        drift = 0.05 * np.exp(-t / 400.0) + 0.01 * np.sin(t / 150.0)
        x = drift + rng.normal(scale=0.02, size=n) + 0.003 * np.cumsum(rng.normal(size=n)) / 30
        for name, mode, level in settings:
            for rule in ["universal", "level", "sure", "bayes"]:
                for shrink in ["soft", "hard"]:
                    y = denoise(x, name, mode, level, rule, shrink)
                    cases.append({"wavelet": name, "mode": mode, "level": level, "rule": rule,
                                  "shrink": shrink, "x": x.tolist(), "denoised": y.tolist()})
    return cases


def savgol_cases(rng):
    cases = []
    for n, dt in [(300, 1.0), (1001, 1.0), (240, 0.5)]:
        t = np.arange(n) * dt
        temp = 20.0 + 15.0 * (1.0 - np.exp(-t / 300.0)) + rng.normal(scale=0.02, size=n)
        temp = np.round(temp / 0.01) * 0.01  # a 0.01 degC thermometer
        for window, order in [(5, 1), (21, 2), (61, 2), (121, 3), (31, 4)]:
            cases.append({"dt_s": dt, "window": window, "poly_order": order, "x": temp.tolist(),
                          "derivative": savgol_filter(temp, window, order, deriv=1, delta=dt,
                                                      mode="interp").tolist()})
    return cases


def main():
    warnings.simplefilter("ignore")  # levels above the maximum are part of the reference
    rng = np.random.default_rng(20240601)
    out = {"pywt_version": pywt.__version__, "dwt": dwt_cases(rng), "denoise": denoise_cases(rng),
           "savgol": savgol_cases(rng)}
    with open(sys.argv[1] + ".tmp", "w", encoding="utf-8") as f:
        json.dump(out, f)
    os.replace(sys.argv[1] + ".tmp", sys.argv[1])


if __name__ == "__main__":
    main()
