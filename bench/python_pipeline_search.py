#!/usr/bin/env python3
"""fogdrift.SVRGridSearchCV over a Pipeline against scikit-learn's GridSearchCV, the Python
issue's case: Pipeline(StandardScaler, SVR), 5 values of C × 4 of gamma, 5-fold KFold, N = 3000,
R². scikit-learn's GridSearchCV with sklearn.svm.SVR (its default, one process) against
SVRGridSearchCV on two threads and on one; each line one run, the same data and folds.

    PYTHONPATH=build/python python3 bench/python_pipeline_search.py [--repeats 3] [--n 3000]

Data: tests/python/conftest.py's startup_like (d = 6), the features put on unlike scales so
that the scaler matters.
"""
import argparse
import os
import sys
import time

import numpy as np
from sklearn.model_selection import GridSearchCV, KFold
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import StandardScaler
from sklearn.svm import SVR as SkSVR

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "tests", "python"))
from conftest import startup_like  # noqa: E402

import fogdrift  # noqa: E402


def timed(f):
    start = time.perf_counter()
    out = f()
    return time.perf_counter() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--n", type=int, default=3000)
    args = parser.parse_args()
    X, y = startup_like(np.random.default_rng(7), args.n)
    X = X * np.array([1, 10, 100, 0.1, 1, 5])
    grid = {"svr__C": [0.3, 1, 3, 10, 30], "svr__gamma": [0.03, 0.1, 0.3, 1.0]}
    folds = KFold(5, shuffle=True, random_state=0)

    def pipe(svr):
        return Pipeline([("scale", StandardScaler()), ("svr", svr)])

    print(f"N = {args.n}, 5 × 4 grid, 5 folds; fogdrift {fogdrift.__version__}\n")
    print("| scikit-learn s | SVRGridSearchCV, 2 threads | 1 thread | same best | worst |Δ mean R²| |")
    print("|---|---|---|---|---|")
    for _ in range(args.repeats):
        t_sk, sk = timed(lambda: GridSearchCV(pipe(SkSVR()), grid, cv=folds).fit(X, y))
        t_2, two = timed(lambda: fogdrift.SVRGridSearchCV(pipe(fogdrift.SVR()), grid, cv=folds,
                                                          n_jobs=2).fit(X, y))
        t_1, one = timed(lambda: fogdrift.SVRGridSearchCV(pipe(fogdrift.SVR()), grid,
                                                          cv=folds).fit(X, y))
        same = sk.best_params_ == two.best_params_ == one.best_params_
        worst = np.max(np.abs(sk.cv_results_["mean_test_score"] -
                              two.cv_results_["mean_test_score"]))
        print(f"| {t_sk:.2f} | {t_2:.2f} s, {t_sk / t_2:.1f}× | {t_1:.2f} s, {t_sk / t_1:.1f}× | "
              f"{'yes' if same else 'no'} | {worst:.1e} |", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
