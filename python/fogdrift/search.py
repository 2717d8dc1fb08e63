"""fogdrift.SVRGridSearchCV: GridSearchCV for fogdrift.SVR, alone or ending a Pipeline, with warm
starts.

scikit-learn's GridSearchCV fits every candidate on every fold cold and alone. This search groups
the candidates that differ only in C and gamma: for each group and fold, the pipeline's earlier
steps are fitted once, and each gamma gets one path over C, ascending, each fit warm-started from
the one before with the kernel rows it computed (docs/svr.md, "Where the speed comes from": warm
start); the paths run in parallel threads. Every other parameter in the grid (epsilon, a
scaler's setting, …) makes groups of its own. Each path returns its predictions, so any scorer
scores them; the scores, the choice, cv_results_ and the refit follow GridSearchCV's conventions,
so the two are interchangeable.
"""
import numbers
import time

import numpy as np
from scipy.stats import rankdata
from sklearn.base import BaseEstimator, RegressorMixin, clone
from sklearn.metrics import check_scoring
from sklearn.model_selection import ParameterGrid, check_cv
from sklearn.pipeline import Pipeline
from sklearn.utils import _safe_indexing, check_array, indexable
from sklearn.utils._param_validation import Interval
from sklearn.utils.validation import check_is_fitted

from . import _fogdrift
from .svr import SVR, _Weights


class _Predicted:
    """Stands in for a fitted estimator inside a scorer: predict() returns the path's
    predictions for the rows being scored (a scorer calls predict once, on those rows)."""

    def __init__(self, prediction):
        self._prediction = prediction

    def predict(self, X):
        if len(X) != len(self._prediction):
            raise RuntimeError("a scorer asked for predictions of other rows than it scores")
        return self._prediction


class SVRGridSearchCV(RegressorMixin, BaseEstimator):
    """Exhaustive search for fogdrift.SVR, alone or as the last step of a Pipeline, scored by
    cross-validation as GridSearchCV scores it.

    Parameters
    ----------
    estimator : fogdrift.SVR or sklearn.pipeline.Pipeline ending in one, default=None
        None means SVR(). Parameters not in the grid are the estimator's.
    param_grid : dict or list of dicts
        As GridSearchCV: parameter names (``C``, ``gamma``, ``epsilon``, …; in a Pipeline
        ``step__name``, e.g. ``svr__C`` or ``scaler__with_mean``) to lists of values. C and gamma
        are searched along warm-started paths; every other parameter's values are searched as
        GridSearchCV does, a path for each.
    scoring : str, callable or None
        Any scikit-learn regression scorer (a name such as ``'neg_mean_absolute_error'``, or a
        callable ``scorer(estimator, X, y)`` that calls ``estimator.predict`` once). None is R²,
        the estimator's score.
    cv : int, cross-validation generator or iterable, default=None
        As GridSearchCV: None is 5-fold KFold, an int that many folds.
    n_jobs : int or None, default=None
        Threads for the paths (None: one, -1: every core). Results do not depend on it.
    refit : bool, default=True
        Refit the best candidate on all of X.
    return_train_score : bool, default=False
        Also score every candidate on its training rows (split{k}_train_score, …).

    Attributes
    ----------
    cv_results_ : dict of arrays with GridSearchCV's keys: mean_fit_time, std_fit_time,
        mean_score_time, std_score_time, param_{name} (masked where a candidate's grid lacks the
        name), params, split{k}_test_score, mean_test_score, std_test_score, rank_test_score, and
        with return_train_score the train scores. A candidate's fit time is its share of the time
        its fold's path took (the paths share their work).
    best_params_, best_score_, best_index_, best_estimator_ (with refit), refit_time_, scorer_,
    n_splits_, multimetric_ (False), n_features_in_.
    """

    # scikit-learn's constraints and messages, as GridSearchCV's (the grid and the estimator are
    # checked further in fit).
    _parameter_constraints = {
        "estimator": [object],  # anything: _svr_prefix says what it must be
        "param_grid": [dict, list, None],
        "scoring": [None, str, callable],
        "cv": ["cv_object"],
        "n_jobs": [None, Interval(numbers.Integral, -1, None, closed="left")],
        "refit": ["boolean"],
        "return_train_score": ["boolean"],
    }

    def __init__(self, estimator=None, param_grid=None, *, scoring=None, cv=None, n_jobs=None,
                 refit=True, return_train_score=False):
        self.estimator = estimator
        self.param_grid = param_grid
        self.scoring = scoring
        self.cv = cv
        self.n_jobs = n_jobs
        self.refit = refit
        self.return_train_score = return_train_score

    # -- the search ----------------------------------------------------------------------------

    def fit(self, X, y, sample_weight=None, *, groups=None, **fit_params):
        """sample_weight: per sample, for the SVR (a Pipeline's SVR step gets it); samples of
        weight 0 are left out of every fit, as SVR.fit leaves them out. groups: the group of each
        sample, for a cv that splits by group (GroupKFold, LeaveOneGroupOut: fogdrift's own
        folds are one group per recording). fit_params: GridSearchCV's, of which the engine
        takes the SVR's sample weight under the Pipeline step's name (``svr__sample_weight``)."""
        self._validate_params()
        base = SVR() if self.estimator is None else self.estimator
        prefix = self._svr_prefix(base)
        for name, value in fit_params.items():
            if prefix and name == prefix + "sample_weight":
                if sample_weight is not None:
                    raise ValueError(f"fit(): sample_weight and {name} are the same weights; "
                                     f"give one of them")
                sample_weight = value
            else:
                taken = f"sample_weight or {prefix}sample_weight" if prefix else "sample_weight"
                raise ValueError(f"fit(): the fit parameter {name!r} is not taken: the search "
                                 f"fits the SVR on its engine, which takes {taken} only")
        candidates = self._candidates(base)
        self.scorer_ = check_scoring(base, scoring="r2" if self.scoring is None else self.scoring)
        self.multimetric_ = False
        if prefix:  # the Pipeline's first step takes X as it is (a DataFrame, say)
            X, y = indexable(X, check_array(y, ensure_2d=False, dtype=np.float64))
            weights = _Weights(sample_weight, X)
        else:
            X, y, weights = clone(base)._prepare(X, y, sample_weight)
            self.n_features_in_ = X.shape[1]
        folds = list(check_cv(self.cv, y, classifier=False).split(X, y, groups))
        n_jobs = 1 if self.n_jobs is None else int(self.n_jobs)
        if n_jobs == 0 or n_jobs < -1:
            raise ValueError(f"n_jobs must be None, -1 or an integer > 0 (got {self.n_jobs!r})")

        # Candidates that differ only in C and gamma share one group: its paths.
        c_key, gamma_key = prefix + "C", prefix + "gamma"
        groups = {}
        for i, params in enumerate(candidates):
            other = {k: v for k, v in params.items() if k not in (c_key, gamma_key)}
            key = repr(sorted(other.items(), key=lambda kv: kv[0]))
            groups.setdefault(key, (other, []))[1].append(i)

        n, k = len(candidates), len(folds)
        test_scores = np.empty((n, k))
        train_scores = np.empty((n, k)) if self.return_train_score else None
        fit_time, score_time = np.zeros((n, k)), np.zeros((n, k))
        for other, members in groups.values():
            group = clone(base).set_params(**other)
            group_svr = group if not prefix else group.steps[-1][1]
            c_values = sorted({float(candidates[i].get(c_key, group_svr.C)) for i in members})
            gammas = []
            for i in members:
                g = candidates[i].get(gamma_key, group_svr.gamma)
                if not any(_same(g, h) for h in gammas):
                    gammas.append(g)
            for g in gammas:
                clone(group_svr).set_params(gamma=g)._check_params()
            group_svr._check_params()
            args = group_svr._engine_args()
            del args["gamma"]
            gamma_args = [g if isinstance(g, str) else float(g) for g in gammas]
            # Every fold's paths in one call, so that the threads share them all.
            started = time.perf_counter()
            Xe, ye, we, fit_rows, test_rows, train_rows = self._engine_data(
                group, prefix, X, y, weights, folds)
            # Train scores are over every training row, those of weight 0 too (GridSearchCV's).
            predict_rows = test_rows if train_scores is None else \
                [np.concatenate([t, r]) for t, r in zip(test_rows, train_rows)]
            per_fold = _fogdrift.svr_search(Xe, ye, we, fit_rows, test_rows, C=c_values,
                                            gamma=gamma_args, n_jobs=n_jobs,
                                            predict_rows=predict_rows, **args)
            share = (time.perf_counter() - started) / (len(members) * len(folds))
            for f, (train, test) in enumerate(folds):
                predicted = per_fold[f]
                for i in members:
                    gi = next(j for j, h in enumerate(gammas)
                              if _same(candidates[i].get(gamma_key, group_svr.gamma), h))
                    ci = c_values.index(float(candidates[i].get(c_key, group_svr.C)))
                    p = predicted[gi, ci]
                    fit_time[i, f] = share
                    started = time.perf_counter()
                    test_scores[i, f] = self.scorer_(_Predicted(p[:len(test)]),
                                                     _safe_indexing(X, test), y[test])
                    if train_scores is not None:
                        train_scores[i, f] = self.scorer_(_Predicted(p[len(test):]),
                                                          _safe_indexing(X, train), y[train])
                    score_time[i, f] = time.perf_counter() - started
        self._store_results(candidates, test_scores, train_scores, fit_time, score_time)
        self.n_splits_ = k
        if self.refit:
            started = time.perf_counter()
            best = clone(base).set_params(**self.best_params_)
            if sample_weight is None:
                best.fit(X, y)
            elif prefix:
                best.fit(X, y, **{prefix + "sample_weight": sample_weight})
            else:
                best.fit(X, y, sample_weight)
            self.best_estimator_ = best
            self.refit_time_ = time.perf_counter() - started
            if prefix and hasattr(best, "n_features_in_"):
                self.n_features_in_ = best.n_features_in_
        return self

    def predict(self, X):
        check_is_fitted(self, "best_estimator_")
        return self.best_estimator_.predict(X)

    def score(self, X, y):
        """The search's scorer on (X, y), as GridSearchCV.score."""
        check_is_fitted(self, "best_estimator_")
        return self.scorer_(self.best_estimator_, X, y)

    # -- internals -----------------------------------------------------------------------------

    @staticmethod
    def _svr_prefix(base):
        """'' for an SVR, 'name__' for a Pipeline whose last step, name, is an SVR."""
        if isinstance(base, SVR):
            return ""
        if isinstance(base, Pipeline) and isinstance(base.steps[-1][1], SVR):
            return base.steps[-1][0] + "__"
        raise ValueError("estimator must be a fogdrift.SVR or a Pipeline whose last step is one "
                         f"(got {type(base).__name__})")

    def _candidates(self, base):
        grid = self.param_grid if self.param_grid is not None else {}
        grids = [grid] if isinstance(grid, dict) else list(grid)
        if not grids or not all(isinstance(g, dict) for g in grids):
            raise ValueError("param_grid must be a dict or a non-empty list of dicts")
        valid = base.get_params(deep=True)
        for g in grids:
            for name, values in g.items():
                if name not in valid:
                    raise ValueError(f"param_grid: {name!r} is not a parameter of the estimator "
                                     f"(its parameters: {', '.join(sorted(valid))})")
                if isinstance(values, str) or not hasattr(values, "__len__") or len(values) == 0:
                    raise ValueError(f"param_grid: {name!r} needs a non-empty list of values "
                                     f"(got {values!r})")
        return list(ParameterGrid(grids))

    @staticmethod
    def _engine_data(group, prefix, X, y, weights, folds):
        """The data every fold's paths see, in the engine's terms: (X, y, weights, the rows each
        fold's SVR trains on, each fold's test rows, each fold's training rows). The SVR trains
        on a fold's training rows of weight > 0 (the engine takes positive weights only, so a
        zero-weight row is in no training set). A Pipeline's earlier steps are fitted on each
        fold's training rows, and its rows, transformed, are stacked after the folds before it."""
        if not prefix:
            w = None if weights.checked is None else np.where(weights.keep, weights.checked, 1.0)
            fit_rows = [np.asarray(train if weights.keep is None else train[weights.keep[train]],
                                   dtype=np.int64) for train, _ in folds]
            return (X, y, w, fit_rows, [np.asarray(test, dtype=np.int64) for _, test in folds],
                    [np.asarray(train, dtype=np.int64) for train, _ in folds])
        blocks, ys, ws, fit_rows, test_rows, train_rows = [], [], [], [], [], []
        offset = 0
        for train, test in folds:
            steps = clone(group[:-1])
            blocks.append(steps.fit_transform(_safe_indexing(X, train), y[train]))
            blocks.append(steps.transform(_safe_indexing(X, test)))
            ys += [y[train], y[test]]
            if weights.checked is not None:
                ws += [np.where(weights.keep[train], weights.checked[train], 1.0),
                       np.ones(len(test))]
            kept = np.arange(len(train)) if weights.keep is None else \
                np.flatnonzero(weights.keep[train])
            fit_rows.append((offset + kept).astype(np.int64))
            train_rows.append(np.arange(offset, offset + len(train), dtype=np.int64))
            test_rows.append(np.arange(offset + len(train), offset + len(train) + len(test),
                                       dtype=np.int64))
            offset += len(train) + len(test)
        Xe = np.ascontiguousarray(np.vstack(blocks), dtype=np.float64)
        return (Xe, np.concatenate(ys), np.concatenate(ws) if ws else None, fit_rows, test_rows,
                train_rows)

    def _store_results(self, candidates, test_scores, train_scores, fit_time, score_time):
        results = {
            "mean_fit_time": fit_time.mean(axis=1), "std_fit_time": fit_time.std(axis=1),
            "mean_score_time": score_time.mean(axis=1),
            "std_score_time": score_time.std(axis=1),
        }
        names = sorted({name for params in candidates for name in params})
        for name in names:
            column = np.ma.MaskedArray(np.empty(len(candidates), dtype=object),
                                       mask=True)
            for i, params in enumerate(candidates):
                if name in params:
                    column[i] = params[name]
            results["param_" + name] = column
        results["params"] = candidates
        for kind, scores in (("test", test_scores), ("train", train_scores)):
            if scores is None:
                continue
            for f in range(scores.shape[1]):
                results[f"split{f}_{kind}_score"] = scores[:, f]
            results[f"mean_{kind}_score"] = scores.mean(axis=1)
            results[f"std_{kind}_score"] = scores.std(axis=1)
            if kind == "test":
                mean = results["mean_test_score"]
                # GridSearchCV's ranks: ties share the smallest; a NaN mean ranks last.
                filled = np.where(np.isnan(mean), np.nanmin(mean) - 1 if np.any(~np.isnan(mean))
                                  else 0, mean)
                results["rank_test_score"] = np.asarray(rankdata(-filled, method="min"),
                                                        dtype=np.int32)
        self.cv_results_ = results
        self.best_index_ = int(results["rank_test_score"].argmin())
        self.best_params_ = candidates[self.best_index_]
        self.best_score_ = float(results["mean_test_score"][self.best_index_])


def _same(a, b):
    """Whether two gamma values are the same value ('scale' is not 0.1)."""
    return type(a) is type(b) and a == b if isinstance(a, str) or isinstance(b, str) else \
        float(a) == float(b)
