#!/usr/bin/env python3
"""fogdrift.SVR against scikit-learn's SVR (LIBSVM) in one Python process, on the same data.

    PYTHONPATH=build/python python3 bench/python_svr_vs_sklearn.py [--build build]
        [--sizes 2000,6000] [--repeats 3] [--no-grid] [--grid-n 2000] [--grid-c 3] [--pipeline]

Data: the C++ bench's startup_like(N) (d = 9, standardised; tests/svr/datasets.hpp), written by
`svr_vs_libsvm --write-data` and read with scikit-learn's svmlight reader. Both estimators get
the same arrays and parameters (γ = 0.5, that is σ = 1; ε = 0.1; tol 1e-3; 200 MB cache);
fits and predictions are timed in turn, medians of the repeats. The grid search is over
C ∈ {1, 10, 100} × γ ∈ {0.125, 0.5, 2}, 3-fold: scikit-learn's GridSearchCV with each
estimator, and fogdrift.SVRGridSearchCV (warm-started C paths) on one and two threads. With
--pipeline, the search is over a Pipeline(StandardScaler, SVR) instead, with ε ∈ {0.05, 0.1} in
the grid too and scored by the mean absolute error (a scorer that is not a squared error).
Prints Markdown tables for bench/RESULTS.md.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from sklearn.datasets import load_svmlight_file
from sklearn.model_selection import GridSearchCV, KFold
from sklearn.pipeline import Pipeline
from sklearn.preprocessing import StandardScaler
from sklearn.svm import SVR as SkSVR

import fogdrift


def data(build, n):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "data.txt")
        subprocess.run([os.path.join(build, "bench", "svr_vs_libsvm"), "--write-data", str(n), path],
                       check=True)
        X, y = load_svmlight_file(path, n_features=9)
    return np.ascontiguousarray(X.toarray()), y


def timed(f):
    start = time.perf_counter()
    out = f()
    return time.perf_counter() - start, out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default="build")
    parser.add_argument("--sizes", default="2000,6000")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--no-grid", action="store_true")
    parser.add_argument("--grid-n", type=int, default=2000)
    parser.add_argument("--grid-c", type=int, default=3,
                        help="values of C: 3 is {1, 10, 100}, more are log-spaced 0.1 … 100")
    parser.add_argument("--pipeline", action="store_true",
                        help="search a Pipeline(StandardScaler, SVR) over C × γ × ε, scored by "
                             "neg_mean_absolute_error")
    args = parser.parse_args()

    print(f"fogdrift {fogdrift.__version__}, scikit-learn "
          f"{__import__('sklearn').__version__}, repeats {args.repeats}\n")
    print("### Single fits: fogdrift.SVR against sklearn.svm.SVR (γ = 0.5, ε = 0.1)\n")
    print("| N | C | sklearn fit s | fogdrift fit s | speed-up | sklearn predict s | "
          "fogdrift predict s | speed-up | max pred. diff / range(y) |")
    print("|---|---|---|---|---|---|---|---|---|")
    fit_ratios = {}
    for n in [int(s) for s in args.sizes.split(",")]:
        X, y = data(args.build, n)
        for c in (1, 10, 100):
            params = dict(C=c, gamma=0.5, epsilon=0.1, tol=1e-3, cache_size=200)
            tf_sk, tf_fd, tp_sk, tp_fd = [], [], [], []
            for _ in range(args.repeats):
                t, sk = timed(lambda: SkSVR(**params).fit(X, y))
                tf_sk.append(t)
                t, fd = timed(lambda: fogdrift.SVR(**params).fit(X, y))
                tf_fd.append(t)
                t, p_sk = timed(lambda: sk.predict(X))
                tp_sk.append(t)
                t, p_fd = timed(lambda: fd.predict(X))
                tp_fd.append(t)
            f_sk, f_fd = np.median(tf_sk), np.median(tf_fd)
            q_sk, q_fd = np.median(tp_sk), np.median(tp_fd)
            diff = np.max(np.abs(p_sk - p_fd)) / np.ptp(y)
            fit_ratios.setdefault(n, []).append(f_sk / f_fd)
            print(f"| {n} | {c} | {f_sk:.3f} | {f_fd:.3f} | {f_sk / f_fd:.1f}× | {q_sk:.3f} | "
                  f"{q_fd:.3f} | {q_sk / q_fd:.1f}× | {diff:.1e} |", flush=True)
    for n, r in fit_ratios.items():
        print(f"| {n} | | | | **median {np.median(r):.1f}×** | | | | |")

    if not args.no_grid:
        X, y = data(args.build, args.grid_n)
        c_values = [1, 10, 100] if args.grid_c == 3 else list(np.logspace(-1, 2, args.grid_c))
        grid = {"C": c_values, "gamma": [0.125, 0.5, 2]}
        folds = KFold(3, shuffle=True, random_state=0)
        scoring = None
        if args.pipeline:
            grid = {"svr__" + k: v for k, v in grid.items()}
            grid["svr__epsilon"] = [0.05, 0.1]
            scoring = "neg_mean_absolute_error"

        def estimator(svr):
            return Pipeline([("scale", StandardScaler()), ("svr", svr)]) if args.pipeline else svr

        candidates = len(c_values) * 3 * (2 if args.pipeline else 1)
        t_sk, sk = timed(lambda: GridSearchCV(estimator(SkSVR()), grid, cv=folds,
                                              scoring=scoring).fit(X, y))
        what = "Pipeline(StandardScaler, SVR), C × γ × ε" if args.pipeline else "C × γ"
        print(f"\n### {what} grid search, {candidates} candidates, 3 folds "
              f"({3 * candidates} fits and the refit), N = {args.grid_n}, scoring "
              f"{scoring or 'R²'}\n")
        print(f"scikit-learn: GridSearchCV({'Pipeline(…, ' if args.pipeline else ''}"
              f"sklearn.svm.SVR()) {t_sk:.2f} s.\n")
        print("| fogdrift | s | speed-up | same best params | worst |Δ mean score| |")
        print("|---|---|---|---|---|")
        for name, make in [
                ("GridSearchCV(fogdrift.SVR())",
                 lambda: GridSearchCV(estimator(fogdrift.SVR()), grid, cv=folds, scoring=scoring)),
                ("SVRGridSearchCV, 1 thread",
                 lambda: fogdrift.SVRGridSearchCV(estimator(fogdrift.SVR()), grid, cv=folds,
                                                  scoring=scoring)),
                ("SVRGridSearchCV, n_jobs=2",
                 lambda: fogdrift.SVRGridSearchCV(estimator(fogdrift.SVR()), grid, cv=folds,
                                                  scoring=scoring, n_jobs=2))]:
            t_fd, fd = timed(lambda: make().fit(X, y))
            worst = np.max(np.abs(sk.cv_results_["mean_test_score"] -
                                  fd.cv_results_["mean_test_score"]))
            same = "yes" if sk.best_params_ == fd.best_params_ else "no"
            print(f"| {name} | {t_fd:.2f} | {t_sk / t_fd:.1f}× | {same} | {worst:.1e} |",
                  flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
