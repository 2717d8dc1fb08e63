"""fogdrift.SVRGridSearchCV: GridSearchCV over C × gamma for fogdrift.SVR, with warm starts.

scikit-learn's GridSearchCV fits every (C, gamma, fold) cold and alone. This search gives each
(fold, gamma) one path over C, ascending, each fit warm-started from the one before with the
kernel rows it computed (docs/svr.md, "Where the speed comes from": warm start), and runs the
paths in parallel threads. The scores, the choice and the refit follow GridSearchCV's
conventions, so the two are interchangeable for this grid.
"""
import numbers

import numpy as np
from sklearn.base import BaseEstimator, RegressorMixin, clone
from sklearn.model_selection import check_cv
from sklearn.utils.validation import check_is_fitted

from . import _fogdrift
from .svr import SVR

_SCORINGS = ("r2", "neg_mean_squared_error", "neg_root_mean_squared_error")


class SVRGridSearchCV(RegressorMixin, BaseEstimator):
    """Exhaustive search over C and gamma for fogdrift.SVR, scored by cross-validation.

    Parameters
    ----------
    estimator : fogdrift.SVR, default=None
        Its other parameters (kernel, epsilon, tol, …) are kept; None means SVR().
    param_grid : dict
        {"C": [...], "gamma": [...]}; gamma may hold 'scale' and 'auto' and may be left out (the
        estimator's). Other keys are not searched: set them on the estimator.
    scoring : {'r2', 'neg_mean_squared_error', 'neg_root_mean_squared_error'} or None
        None is the estimator's score, R².
    cv : int, cross-validation generator or iterable, default=None
        As GridSearchCV: None is 5-fold KFold, an int that many folds.
    n_jobs : int or None, default=None
        Threads for the paths (None: one, -1: every core). Results do not depend on it.
    refit : bool, default=True
        Refit the best candidate on all of X.

    Attributes
    ----------
    cv_results_ : dict of arrays, GridSearchCV's keys: params, param_C, param_gamma,
        split{k}_test_score, mean_test_score, std_test_score, rank_test_score.
    best_params_, best_score_, best_index_, best_estimator_ (with refit), n_splits_.
    """

    def __init__(self, estimator=None, param_grid=None, *, scoring=None, cv=None, n_jobs=None,
                 refit=True):
        self.estimator = estimator
        self.param_grid = param_grid
        self.scoring = scoring
        self.cv = cv
        self.n_jobs = n_jobs
        self.refit = refit

    def fit(self, X, y, sample_weight=None):
        base = SVR() if self.estimator is None else self.estimator
        if not isinstance(base, SVR):
            raise ValueError("estimator must be a fogdrift.SVR")
        grid = dict(self.param_grid or {})
        unknown = set(grid) - {"C", "gamma"}
        if unknown:
            raise ValueError(f"param_grid may hold C and gamma only (got {sorted(unknown)}); set "
                             "other parameters on the estimator")
        c_given = list(grid.get("C", [base.C]))
        c_values = [float(c) for c in c_given]
        gammas = list(grid.get("gamma", [base.gamma]))
        if not c_values or not gammas:
            raise ValueError("param_grid: C and gamma need at least one value each")
        scoring = "r2" if self.scoring is None else self.scoring
        if scoring not in _SCORINGS:
            raise ValueError(f"scoring must be one of {_SCORINGS} or None (got {scoring!r})")
        probe = clone(base).set_params(C=c_values[0], gamma=gammas[0])
        X, y, weights = probe._prepare(X, y, sample_weight)
        for g in gammas:
            clone(base).set_params(gamma=g)._check_params()
        folds = list(check_cv(self.cv, y, classifier=False).split(X, y))
        # Samples of weight 0 are left out of every fold, as SVR.fit leaves them out.
        train_rows, test_rows = [], []
        for train, test in folds:
            if weights.keep is not None:
                train = train[weights.keep[train]]
            train_rows.append(np.asarray(train, dtype=np.int64))
            test_rows.append(np.asarray(test, dtype=np.int64))
        # The engine takes positive weights only; a zero-weight row is in no training set.
        w = None if weights.checked is None else np.where(weights.keep, weights.checked, 1.0)
        engine_gammas = [g if isinstance(g, str) else float(g) for g in gammas]
        args = probe._engine_args()
        del args["gamma"]
        n_jobs = 1 if self.n_jobs is None else int(self.n_jobs)
        sse = _fogdrift.svr_search(X, y, w, train_rows, test_rows, C=c_values, gamma=engine_gammas,
                                   n_jobs=n_jobs, **args)
        scores = np.empty_like(sse)
        for f, test in enumerate(test_rows):
            yt = y[test]
            if scoring == "r2":
                sst = np.sum((yt - yt.mean()) ** 2)
                scores[:, :, f] = 1 - sse[:, :, f] / sst if sst > 0 else np.where(
                    sse[:, :, f] == 0, 1.0, 0.0)
            elif scoring == "neg_mean_squared_error":
                scores[:, :, f] = -sse[:, :, f] / len(test)
            else:
                scores[:, :, f] = -np.sqrt(sse[:, :, f] / len(test))
        # Candidates in GridSearchCV's order: ParameterGrid sorts the keys, so C varies slowest.
        params, split = [], []
        for ci, c in enumerate(c_given):  # the values as given, as GridSearchCV reports them
            for gi, g in enumerate(gammas):
                params.append({"C": c, "gamma": g})
                split.append(scores[gi, ci, :])
        split = np.array(split)
        mean = split.mean(axis=1)
        results = {
            "params": params,
            "param_C": np.ma.masked_array([p["C"] for p in params], mask=False, dtype=object),
            "param_gamma": np.ma.masked_array([p["gamma"] for p in params], mask=False,
                                              dtype=object),
            "mean_test_score": mean,
            "std_test_score": split.std(axis=1),
        }
        for k in range(split.shape[1]):
            results[f"split{k}_test_score"] = split[:, k]
        order = np.argsort(-mean, kind="stable")
        rank = np.empty(len(mean), dtype=np.int32)
        rank[order] = np.arange(1, len(mean) + 1)
        results["rank_test_score"] = rank
        self.cv_results_ = results
        self.best_index_ = int(order[0])
        self.best_params_ = params[self.best_index_]
        self.best_score_ = float(mean[self.best_index_])
        self.n_splits_ = len(folds)
        self.n_features_in_ = probe.n_features_in_
        if self.refit:
            self.best_estimator_ = clone(base).set_params(**self.best_params_).fit(
                X, y, sample_weight)
        return self

    def predict(self, X):
        check_is_fitted(self, "best_estimator_")
        return self.best_estimator_.predict(X)
