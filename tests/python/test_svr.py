"""fogdrift.SVR against scikit-learn: its estimator checks, and sklearn.svm.SVR (LIBSVM) as the
reference for predictions, sample weights and fitted attributes."""
import pickle

import numpy as np
import pytest
from sklearn.base import clone
from sklearn.model_selection import GridSearchCV
from sklearn.pipeline import Pipeline, make_pipeline
from sklearn.preprocessing import StandardScaler
from sklearn.svm import SVR as SkSVR
from sklearn.utils.estimator_checks import parametrize_with_checks

import fogdrift
from conftest import startup_like


@parametrize_with_checks([fogdrift.SVR(), fogdrift.SVR(kernel="linear", solver="libsvm")])
def test_scikit_learn_estimator_checks(estimator, check):
    check(estimator)


def agree(a, b, y, rel):
    """Largest prediction difference, relative to the range of y."""
    return np.max(np.abs(a - b)) / np.ptp(y) <= rel


@pytest.mark.parametrize("params", [
    dict(),
    dict(C=100, epsilon=0.05),
    dict(C=0.1, gamma="auto"),
    dict(gamma=0.3, epsilon=0.0),
    dict(kernel="linear", C=3),
    dict(shrinking=False, C=10),
    dict(solver="libsvm", C=10),
])
def test_predictions_are_scikit_learns(rng, params):
    X, y = startup_like(rng, 600)
    X_new, _ = startup_like(rng, 200)
    ours = fogdrift.SVR(**params).fit(X, y)
    sk_params = {k: v for k, v in params.items() if k != "solver"}
    theirs = SkSVR(**sk_params).fit(X, y)
    # Both stop within the tolerance 1e-3 of the optimum, so predictions agree to about it; the
    # linear kernel's dual is flatter here, and the same tolerance leaves 1.6e-3 between them.
    rel = 2e-3 if params.get("kernel") == "linear" else 1e-3
    assert agree(ours.predict(X_new), theirs.predict(X_new), y, rel)
    assert abs(ours.intercept_[0] - theirs.intercept_[0]) <= 1e-3 * np.ptp(y)
    assert abs(ours.n_support_[0] - theirs.n_support_[0]) <= 0.02 * theirs.n_support_[0] + 2
    # At a tight tolerance both reach the same optimum.
    tight = fogdrift.SVR(**params, tol=1e-7).fit(X, y)
    tight_sk = SkSVR(**sk_params, tol=1e-7).fit(X, y)
    assert agree(tight.predict(X_new), tight_sk.predict(X_new), y, 1e-6)


@pytest.mark.parametrize("params", [dict(C=10), dict(kernel="linear", C=3)])
def test_the_libsvm_solver_takes_scikit_learns_steps(rng, params):
    # solver='libsvm' visits LIBSVM's working sets one for one (docs/svr.md), so it stops where
    # scikit-learn's LIBSVM stops, after as many iterations.
    X, y = startup_like(rng, 600)
    ours = fogdrift.SVR(solver="libsvm", **params).fit(X, y)
    theirs = SkSVR(**params).fit(X, y)
    assert ours.n_iter_ == theirs.n_iter_
    np.testing.assert_array_equal(ours.support_, theirs.support_)
    assert agree(ours.predict(X), theirs.predict(X), y, 1e-9)


def test_fitted_attributes_have_scikit_learns_shapes_and_meaning(rng):
    X, y = startup_like(rng, 300)
    m = fogdrift.SVR(C=5).fit(X, y)
    n_sv = m.support_.shape[0]
    assert m.support_vectors_.shape == (n_sv, X.shape[1])
    assert m.dual_coef_.shape == (1, n_sv)
    assert m.n_support_.tolist() == [n_sv] and m.n_support_.dtype == np.int32
    assert m.n_features_in_ == X.shape[1] and m.shape_fit_ == X.shape
    np.testing.assert_array_equal(m.support_vectors_, X[m.support_])
    assert np.all(np.abs(m.dual_coef_) <= 5 + 1e-12)
    # f(x) = Σ dual_coef·exp(−γ|sv − x|²) + intercept, computed here apart.
    gamma = 1.0 / (X.shape[1] * X.var())
    d2 = ((X[:20, None, :] - m.support_vectors_[None, :, :]) ** 2).sum(axis=2)
    f = np.exp(-gamma * d2) @ m.dual_coef_[0] + m.intercept_[0]
    np.testing.assert_allclose(m.predict(X[:20]), f, rtol=1e-12, atol=1e-12)
    lin = fogdrift.SVR(kernel="linear").fit(X, y)
    np.testing.assert_allclose(lin.predict(X), X @ lin.coef_[0] + lin.intercept_[0], atol=1e-10)
    with pytest.raises(AttributeError):
        m.coef_


def test_sample_weights_are_scikit_learns(rng):
    X, y = startup_like(rng, 400)
    w = rng.uniform(0.2, 4, size=400)
    ours = fogdrift.SVR(C=4, tol=1e-7).fit(X, y, sample_weight=w)
    theirs = SkSVR(C=4, tol=1e-7).fit(X, y, sample_weight=w)
    assert agree(ours.predict(X), theirs.predict(X), y, 1e-6)
    assert set(ours.support_) == set(theirs.support_)
    # A weight of 0 leaves the sample out. (scikit-learn 1.2's SVR gives such samples
    # coefficients beyond their bound C·0, a failure its own estimator checks expect; so the
    # reference here is scikit-learn without them.)
    w[::7] = 0
    kept = np.flatnonzero(w > 0)
    ours = fogdrift.SVR(C=4, tol=1e-7).fit(X, y, sample_weight=w)
    theirs = SkSVR(C=4, tol=1e-7).fit(X[kept], y[kept], sample_weight=w[kept])
    assert agree(ours.predict(X), theirs.predict(X), y, 1e-6)
    assert set(ours.support_) == set(kept[theirs.support_])
    assert not set(ours.support_) & set(range(0, 400, 7))
    alone = fogdrift.SVR(C=4, tol=1e-7).fit(X[kept], y[kept], sample_weight=w[kept])
    np.testing.assert_array_equal(ours.predict(X), alone.predict(X))
    # A warm-started path leaves them out too, its support indices into the whole X.
    path = fogdrift.SVR(tol=1e-7).fit_path(X, y, C=[1, 4], sample_weight=w)
    assert not set(path[1].support_) & set(range(0, 400, 7))
    assert agree(path[1].predict(X), ours.predict(X), y, 1e-6)
    # In another order the solver takes another path to the same optimum.
    order = rng.permutation(400)
    shuffled = fogdrift.SVR(C=4, tol=1e-9).fit(X[order], y[order], sample_weight=w[order])
    assert agree(shuffled.predict(X), fogdrift.SVR(C=4, tol=1e-9).fit(X, y, w).predict(X), y, 1e-8)
    np.testing.assert_array_equal(fogdrift.SVR().fit(X, y, np.ones(400)).predict(X),
                                  fogdrift.SVR().fit(X, y).predict(X))
    # A negative weight leaves the sample out as 0 does (scikit-learn masks both), and with
    # nothing left scikit-learn's message.
    negative = np.where(w > 0, w, -0.5)
    np.testing.assert_array_equal(fogdrift.SVR(C=4, tol=1e-7).fit(X, y, negative).predict(X),
                                  ours.predict(X))
    for none_left in (np.zeros(400), -w):
        with pytest.raises(ValueError, match="all samples have zero or negative weights"):
            fogdrift.SVR().fit(X, y, sample_weight=none_left)


def test_same_model_from_any_memory_order_dtype_and_thread_count(rng):
    X, y = startup_like(rng, 500)
    base = fogdrift.SVR(C=10).fit(X, y)
    fortran = fogdrift.SVR(C=10).fit(np.asfortranarray(X), y)
    np.testing.assert_array_equal(base.dual_coef_, fortran.dual_coef_)
    assert base.intercept_[0] == fortran.intercept_[0]
    p = base.predict(X)
    np.testing.assert_array_equal(p, base.predict(np.asfortranarray(X)))
    np.testing.assert_array_equal(p, base.predict(X[::-1])[::-1])  # a strided view
    for n_jobs in (2, -1):
        np.testing.assert_array_equal(p, clone(base).set_params(n_jobs=n_jobs).fit(X, y).predict(X))
    # float32 data is other data (rounded to 1e-7), so another path to within the tolerance.
    f32 = fogdrift.SVR(C=10).fit(X.astype(np.float32), y)
    assert agree(f32.predict(X), p, y, 1e-3)


def test_fit_path_warm_starts_to_the_cold_fits(rng):
    X, y = startup_like(rng, 500)
    cs = [0.1, 1, 10, 100]
    path = fogdrift.SVR(tol=1e-6).fit_path(X, y, C=cs)
    assert [m.C for m in path] == cs
    for c, m in zip(cs, path):
        cold = fogdrift.SVR(C=c, tol=1e-6).fit(X, y)
        assert agree(m.predict(X), cold.predict(X), y, 1e-5)
        assert m.n_features_in_ == X.shape[1]
    with pytest.raises(ValueError, match="option C: every value must be a finite number > 0"):
        fogdrift.SVR().fit_path(X, y, C=[1, -1])


def test_works_in_pipelines_searches_and_pickles(rng):
    X, y = startup_like(rng, 300)
    grid = {"svr__C": [0.3, 3, 30], "svr__gamma": [0.05, 0.2]}
    ours = GridSearchCV(make_pipeline(StandardScaler(), fogdrift.SVR()), grid, cv=3).fit(X, y)
    theirs = GridSearchCV(make_pipeline(StandardScaler(), SkSVR()), grid, cv=3).fit(X, y)
    np.testing.assert_allclose(ours.cv_results_["mean_test_score"],
                               theirs.cv_results_["mean_test_score"], atol=1e-3)
    assert ours.best_params_ == theirs.best_params_
    model = ours.best_estimator_
    again = pickle.loads(pickle.dumps(model))
    np.testing.assert_array_equal(again.predict(X), model.predict(X))


@pytest.mark.parametrize("params, message", [
    (dict(kernel="poly"), "kernel must be 'rbf' or 'linear'"),
    (dict(kernel=lambda a, b: a @ b.T), "Gram matrix to sklearn.svm.SVR(kernel='precomputed')"),
    # scikit-learn's own words for every other parameter (its parameter constraints).
    (dict(C="ten"), "The 'C' parameter of SVR must be a float in the range (0.0, inf). Got 'ten' "
                    "instead."),
    (dict(C=0.0), "The 'C' parameter of SVR must be a float in the range (0.0, inf). Got 0.0"),
    (dict(tol="x"), "The 'tol' parameter of SVR must be a float in the range (0.0, inf). Got 'x'"),
    (dict(tol=float("nan")), "The 'tol' parameter of SVR must be a float in the range (0.0, inf)"),
    (dict(shrinking="yes"), "The 'shrinking' parameter of SVR must be an instance of 'bool'"),
    (dict(gamma="wide"), "The 'gamma' parameter of SVR must be a str among"),
    (dict(gamma=-1.0), "The 'gamma' parameter of SVR must be a str among"),
    (dict(epsilon=-0.1), "The 'epsilon' parameter of SVR must be a float in the range [0.0, inf)"),
    (dict(cache_size=-5.0), "The 'cache_size' parameter of SVR must be a float in the range"),
    (dict(degree=1.5), "The 'degree' parameter of SVR must be an int in the range [0, inf)"),
    (dict(max_iter=0), "The 'max_iter' parameter of SVR must be -1 (no limit) or an int > 0"),
    (dict(solver="smo"), "The 'solver' parameter of SVR must be a str among"),
    (dict(n_jobs=0), "The 'n_jobs' parameter of SVR must be None, -1 or an int > 0"),
])
def test_impossible_parameters_are_value_errors_naming_them(rng, params, message):
    X, y = startup_like(rng, 50)
    with pytest.raises(ValueError) as e:
        fogdrift.SVR(**params).fit(X, y)
    assert message in str(e.value)
    # Short, whatever the data's size: not pybind11's signature with X and y printed.
    assert len(str(e.value)) < 300


def test_iteration_limit_warns_as_scikit_learn_does(rng):
    from sklearn.exceptions import ConvergenceWarning
    X, y = startup_like(rng, 300)
    with pytest.warns(ConvergenceWarning, match="max_iter=5"):
        m = fogdrift.SVR(C=100, max_iter=5).fit(X, y)
    assert m.fit_status_ == 1 and m.n_iter_ == 5


def test_fits_reuse_memory_until_it_is_released(rng):
    X, y = startup_like(rng, 2000)
    fogdrift.release_memory()
    a = fogdrift.SVR(C=10).fit(X, y).predict(X)
    held = fogdrift.release_memory()
    assert held > 2000 * 4 * 100  # at least the rows of a hundred kernel rows were kept
    assert fogdrift.release_memory() == 0
    b = fogdrift.SVR(C=10).fit(X, y).predict(X)
    np.testing.assert_array_equal(a, b)


def test_a_training_runs_row_memory_is_released_too(tmp_path):
    # train's search ends its workspaces; their row blocks stay in the process for later fits
    # until release_memory gives them back.
    d = tmp_path / "cal"
    fogdrift.simulate("calibration", out=d, seed=5, temps_degc=[-20, 10, 40], repetitions=2)
    fogdrift.release_memory()
    fogdrift.train(d, population=5, iterations=2, progress=False)
    assert fogdrift.release_memory() > 1 << 20
    assert fogdrift.release_memory() == 0


def test_grid_search_scores_and_chooses_as_grid_search_cv(rng):
    from sklearn.model_selection import KFold
    X, y = startup_like(rng, 500)
    grid = {"C": [0.5, 5, 50], "gamma": ["scale", 0.05, 0.5]}
    folds = KFold(4, shuffle=True, random_state=1)
    ours = fogdrift.SVRGridSearchCV(fogdrift.SVR(epsilon=0.05), grid, cv=folds).fit(X, y)
    cold = GridSearchCV(fogdrift.SVR(epsilon=0.05), grid, cv=folds).fit(X, y)
    theirs = GridSearchCV(SkSVR(epsilon=0.05), grid, cv=folds).fit(X, y)
    assert ours.cv_results_["params"] == theirs.cv_results_["params"]
    for k in ["mean_test_score"] + [f"split{i}_test_score" for i in range(4)]:
        # Warm starts and cold fits stop at different points within the tolerance.
        np.testing.assert_allclose(ours.cv_results_[k], cold.cv_results_[k], atol=2e-3)
        np.testing.assert_allclose(ours.cv_results_[k], theirs.cv_results_[k], atol=2e-3)
    np.testing.assert_array_equal(ours.cv_results_["rank_test_score"],
                                  theirs.cv_results_["rank_test_score"])
    assert ours.best_params_ == theirs.best_params_ and ours.n_splits_ == 4
    np.testing.assert_array_equal(
        ours.predict(X), fogdrift.SVR(epsilon=0.05, **ours.best_params_).fit(X, y).predict(X))
    threads = fogdrift.SVRGridSearchCV(fogdrift.SVR(epsilon=0.05), grid, cv=folds, n_jobs=2)
    np.testing.assert_array_equal(threads.fit(X, y).cv_results_["mean_test_score"],
                                  ours.cv_results_["mean_test_score"])


def test_grid_search_scorings_weights_and_errors(rng):
    X, y = startup_like(rng, 300)
    grid = {"C": [1, 10], "gamma": [0.1, 0.3]}
    w = rng.uniform(0.5, 2, size=300)
    w[::9] = 0
    for scoring in ("neg_mean_squared_error", "neg_root_mean_squared_error"):
        ours = fogdrift.SVRGridSearchCV(param_grid=grid, scoring=scoring, cv=3).fit(X, y, w)
        theirs = GridSearchCV(fogdrift.SVR(), grid, scoring=scoring, cv=3).fit(
            X, y, sample_weight=w)
        np.testing.assert_allclose(ours.cv_results_["mean_test_score"],
                                   theirs.cv_results_["mean_test_score"], rtol=2e-3)
    with pytest.raises(ValueError, match="'alpha' is not a parameter of the estimator"):
        fogdrift.SVRGridSearchCV(param_grid={"C": [1], "alpha": [3]}).fit(X, y)
    with pytest.raises(ValueError, match="'C' needs a non-empty list of values"):
        fogdrift.SVRGridSearchCV(param_grid={"C": []}).fit(X, y)
    with pytest.raises(ValueError, match="estimator must be a fogdrift.SVR or a Pipeline"):
        fogdrift.SVRGridSearchCV(SkSVR(), {"C": [1]}).fit(X, y)
    with pytest.raises(ValueError, match="estimator must be a fogdrift.SVR or a Pipeline"):
        fogdrift.SVRGridSearchCV(make_pipeline(fogdrift.SVR(), StandardScaler()), {}).fit(X, y)
    with pytest.raises(ValueError, match="continuous is not supported"):
        fogdrift.SVRGridSearchCV(param_grid={"C": [1]}, scoring="accuracy").fit(X, y)
    with pytest.raises(ValueError, match="The 'gamma' parameter of SVR must be"):
        fogdrift.SVRGridSearchCV(param_grid={"C": [1], "gamma": [-1.0]}).fit(X, y)
    with pytest.raises(ValueError, match="option C: every value must be a finite number > 0"):
        fogdrift.SVRGridSearchCV(param_grid={"C": [1, 0]}).fit(X, y)


def test_the_engine_entry_points_check_their_own_inputs(rng):
    # fogdrift.SVR validates before it calls the engine; the module's functions check again, for
    # any other caller, and name the rule broken.
    from fogdrift import _fogdrift as engine
    X, y = startup_like(rng, 40)
    args = dict(kernel="rbf", gamma=0.5, C=1.0, epsilon=0.1, tol=1e-3, cache_size=10,
                max_iter=0, shrinking=True, solver="pairs")
    args["rows"] = None
    with pytest.raises(ValueError, match="X must be a 2-D array"):
        engine.svr_fit(X[:, 0], y, None, **args)
    with pytest.raises(ValueError, match="y must be a 1-D array with one value per row of X"):
        engine.svr_fit(X, y[:-1], None, **args)
    with pytest.raises(ValueError, match="sample_weight must be a 1-D array"):
        engine.svr_fit(X, y, np.ones(3), **args)
    with pytest.raises(ValueError, match="sample 2: weight is 0"):
        engine.svr_fit(X, y, np.where(np.arange(40) == 1, 0.0, 1.0), **args)
    # Rows taken from X: one weight each, every index inside X.
    with pytest.raises(ValueError, match="one value per row of X taken"):
        engine.svr_fit(X, y, np.ones(40), **dict(args, rows=np.arange(10)))
    with pytest.raises(ValueError, match="rows: an index outside X"):
        engine.svr_fit(X, y, np.ones(2), **dict(args, rows=np.array([3, 40])))
    with pytest.raises(ValueError, match="option kernel: must be 'rbf' or 'linear'"):
        engine.svr_fit(X, y, None, **dict(args, kernel="poly"))
    with pytest.raises(ValueError, match="option solver: must be 'pairs' or 'libsvm'"):
        engine.svr_fit(X, y, None, **dict(args, solver="smo"))
    with pytest.raises(ValueError, match="option gamma: must be 'scale', 'auto' or a number"):
        engine.svr_fit(X, y, None, **dict(args, gamma="wide"))
    path_args = {k: v for k, v in args.items() if k != "C"}
    search_only = {k: v for k, v in path_args.items() if k != "rows"}
    with pytest.raises(ValueError, match="option C: needs at least one value"):
        engine.svr_fit_path(X, y, None, C=[], **path_args)
    with pytest.raises(ValueError, match="option C: needs at least one value"):
        fogdrift.SVR().fit_path(X, y, C=[])
    folds = [np.arange(30, dtype=np.int64)], [np.arange(30, 40, dtype=np.int64)]
    search_args = dict(search_only, gamma=[0.5], n_jobs=1)
    with pytest.raises(ValueError, match="a fold's row index is out of range"):
        engine.svr_search(X, y, None, [np.array([0, 99], dtype=np.int64)], folds[1], C=[1.0],
                          **search_args)
    with pytest.raises(ValueError, match="needs values of gamma, and train and test folds"):
        engine.svr_search(X, y, None, folds[0], [], C=[1.0], **search_args)
    m = fogdrift.SVR().fit(X, y)
    with pytest.raises(ValueError, match="inconsistent model or data shapes"):
        engine.svr_predict(m.support_vectors_, m.dual_coef_[0][:-1], 0.0, "rbf", 0.5, X, 1)
    with pytest.raises(ValueError, match="X has another number of features than the model"):
        engine.svr_predict(m.support_vectors_, m.dual_coef_[0], 0.0, "rbf", 0.5, X[:, :2], 1)


def test_grid_search_of_a_pipeline_with_any_scorer_as_grid_search_cv(rng):
    """A Pipeline ending in fogdrift.SVR, a list of grids with epsilon and a scaler's setting in
    them, a scorer that is not a squared error, and train scores: every cv_results_ key that
    GridSearchCV fills, the same candidates, scores and choice."""
    from sklearn.metrics import make_scorer, median_absolute_error
    from sklearn.model_selection import KFold
    X, y = startup_like(rng, 400)
    X = X * np.array([1, 10, 100, 0.1, 1, 5])  # features of unlike scales, as a scaler expects
    pipe = Pipeline([("scale", StandardScaler()), ("svr", fogdrift.SVR())])
    grids = [{"svr__C": [0.5, 5, 50], "svr__gamma": ["scale", 0.2], "svr__epsilon": [0.05, 0.2]},
             {"svr__C": [2.0], "scale__with_mean": [False], "svr__kernel": ["linear"]}]
    folds = KFold(3, shuffle=True, random_state=2)
    for scoring in ("neg_mean_absolute_error",
                    make_scorer(median_absolute_error, greater_is_better=False)):
        ours = fogdrift.SVRGridSearchCV(pipe, grids, scoring=scoring, cv=folds,
                                        return_train_score=True).fit(X, y)
        theirs = GridSearchCV(pipe, grids, scoring=scoring, cv=folds,
                              return_train_score=True).fit(X, y)
        assert set(ours.cv_results_) == set(theirs.cv_results_)
        assert ours.cv_results_["params"] == theirs.cv_results_["params"]
        for key in theirs.cv_results_:
            if key.startswith("param_"):
                assert list(ours.cv_results_[key].mask) == list(theirs.cv_results_[key].mask), key
                assert [v for v in ours.cv_results_[key].compressed()] == \
                    [v for v in theirs.cv_results_[key].compressed()], key
            elif "score" in key and "time" not in key and key != "rank_test_score":
                # Warm starts and cold fits stop at different points within the tolerance.
                np.testing.assert_allclose(ours.cv_results_[key], theirs.cv_results_[key],
                                           atol=5e-3, err_msg=key)
        np.testing.assert_array_equal(ours.cv_results_["rank_test_score"],
                                      theirs.cv_results_["rank_test_score"])
        assert ours.best_params_ == theirs.best_params_
        assert ours.n_features_in_ == 6 and ours.n_splits_ == 3
        np.testing.assert_array_equal(
            ours.predict(X), clone(pipe).set_params(**ours.best_params_).fit(X, y).predict(X))
        assert ours.score(X, y) == pytest.approx(theirs.score(X, y), abs=5e-3)
    # Weights reach the Pipeline's SVR, in the search and in the refit; a row of weight 0 is in
    # no fit but is scored, in its test fold and in the train scores.
    w = rng.uniform(0.5, 2, size=400)
    w[::7] = 0
    for estimator, grid, weight in ((pipe, grids[0], "svr__sample_weight"),
                                    (fogdrift.SVR(), {"C": [0.5, 5], "gamma": [0.2]},
                                     "sample_weight")):
        ours = fogdrift.SVRGridSearchCV(estimator, grid, cv=folds, return_train_score=True).fit(
            X, y, sample_weight=w)
        theirs = GridSearchCV(estimator, grid, cv=folds, return_train_score=True).fit(
            X, y, **{weight: w})
        for key in ("mean_test_score", "mean_train_score"):
            np.testing.assert_allclose(ours.cv_results_[key], theirs.cv_results_[key],
                                       atol=5e-3, err_msg=key)
    ours = fogdrift.SVRGridSearchCV(pipe, grids[0], cv=folds).fit(X, y, sample_weight=w)
    np.testing.assert_array_equal(ours.predict(X), clone(pipe).set_params(
        **ours.best_params_).fit(X, y, svr__sample_weight=w).predict(X))
