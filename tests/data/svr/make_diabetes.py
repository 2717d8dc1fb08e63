#!/usr/bin/env python3
"""Writes diabetes.libsvm: scikit-learn's diabetes regression data (Efron et al. 2004, 442
samples, 10 features) in LIBSVM format, the real data set the SVR engine is tested on.

Needs Debian's python3-sklearn (apt-get install python3-sklearn). Run from this folder:
    python3 make_diabetes.py && git diff --stat diabetes.libsvm
Numbers are written with repr(), which reads back to the same double.
"""
from sklearn.datasets import load_diabetes

data = load_diabetes()
with open("diabetes.libsvm", "w") as out:
    for features, target in zip(data.data, data.target):
        fields = [repr(float(target))]
        fields += [f"{k + 1}:{float(v)!r}" for k, v in enumerate(features) if v != 0]
        out.write(" ".join(fields) + "\n")
