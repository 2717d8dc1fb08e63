"""What a Python user gets wrong, answered in Python's words: the keyword, the rule and the fix,
never pybind11's signature or a cast error (docs/python.md)."""
import inspect
import os
import warnings

import numpy as np
import pandas as pd
import pytest
from sklearn.model_selection import GridSearchCV, GroupKFold

import fogdrift


@pytest.fixture(scope="module")
def trained(tmp_path_factory):
    d = tmp_path_factory.mktemp("messages") / "cal"
    held = fogdrift.simulate("calibration", out=d, seed=5, temps_degc=[-20, 10, 40],
                             repetitions=2)
    model = fogdrift.train(d, population=5, iterations=2, progress=False)["model"]
    return d, held, model


def test_a_campaign_of_the_wrong_kind_is_named(trained):
    with pytest.raises(TypeError, match=r"train\(\): campaign must be a folder \(str or "
                                        r"os.PathLike\) or a campaign in memory .*, not int$"):
        fogdrift.train(12345)
    with pytest.raises(TypeError, match=r"not list; for one model per unit's campaign use "
                                        r"fogdrift.train_fleet\(campaigns\)"):
        fogdrift.train([trained[0]])


def test_an_empty_recording_says_it_has_no_rows(trained):
    _, held, model = trained
    empty = pd.DataFrame({k: [] for k in held["data"][0]})
    with pytest.raises(ValueError, match="has no rows: a recording needs at least one sample"):
        model.predict(empty)


def test_an_array_is_not_a_recording_and_warns_of_nothing(trained):
    _, held, model = trained
    frame = pd.DataFrame(held["data"][0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no FutureWarning from an elementwise comparison
        with pytest.raises(ValueError, match=r"not ndarray; an array has no column names: pass "
                                             r"the DataFrame itself"):
            model.predict(frame.to_numpy())
    assert np.array_equal(model.predict(frame)["drift_dph"],
                          model.predict(held["data"][0])["drift_dph"])


@pytest.mark.parametrize("function", [
    fogdrift.simulate, fogdrift.features, fogdrift.read_recording, fogdrift.write_recording,
    fogdrift.allan_deviation, fogdrift.noise_terms, fogdrift.save_models, fogdrift.train,
    fogdrift.evaluate, fogdrift.northfind, fogdrift.find_north, fogdrift.denoise,
    fogdrift.Model.predict, fogdrift.Model.compensate, fogdrift.Model.load,
    fogdrift.Model.from_json, fogdrift.StreamingCompensator.update,
    fogdrift.StreamingCompensator.run, fogdrift.train_fleet])
def test_every_function_has_a_signature(function):
    parameters = inspect.signature(function).parameters
    assert parameters, function


def test_the_package_is_typed():
    folder = os.path.dirname(fogdrift.__file__)
    assert os.path.exists(os.path.join(folder, "py.typed"))
    stub = open(os.path.join(folder, "_fogdrift.pyi")).read()
    compile(stub, "_fogdrift.pyi", "exec")
    for name in ("def train(", "def simulate(", "class Model:", "def predict(self: Model",
                 "class StreamingCompensator:", "def svr_fit("):
        assert name in stub, name


def test_grid_search_takes_groups_as_grid_search_cv(rng):
    X = rng.normal(size=(120, 3))
    y = np.sin(X[:, 0]) + 0.1 * rng.normal(size=120)
    groups = np.repeat(np.arange(6), 20)
    grid = {"C": [0.3, 3.0], "gamma": [0.1, 1.0]}
    ours = fogdrift.SVRGridSearchCV(fogdrift.SVR(), grid, cv=GroupKFold(3)).fit(X, y,
                                                                                  groups=groups)
    theirs = GridSearchCV(fogdrift.SVR(), grid, cv=GroupKFold(3)).fit(X, y, groups=groups)
    # Warm-started paths against cold fits: the same optimum to the solver's tolerance.
    np.testing.assert_allclose(ours.cv_results_["mean_test_score"],
                               theirs.cv_results_["mean_test_score"], atol=1e-3)
    assert ours.best_params_ == theirs.best_params_
    with pytest.raises(ValueError, match="The 'groups' parameter should not be None"):
        fogdrift.SVRGridSearchCV(fogdrift.SVR(), grid, cv=GroupKFold(3)).fit(X, y)


def test_grid_search_fit_params_are_the_svrs_weights_or_named(rng):
    from sklearn.pipeline import make_pipeline
    from sklearn.preprocessing import StandardScaler
    X = rng.normal(size=(80, 2))
    y = X[:, 0] + 0.1 * rng.normal(size=80)
    w = rng.uniform(0.5, 2, size=80)
    pipe = make_pipeline(StandardScaler(), fogdrift.SVR())
    a = fogdrift.SVRGridSearchCV(pipe, {"svr__C": [1, 10]}, cv=3).fit(X, y, svr__sample_weight=w)
    b = fogdrift.SVRGridSearchCV(pipe, {"svr__C": [1, 10]}, cv=3).fit(X, y, sample_weight=w)
    np.testing.assert_array_equal(a.cv_results_["mean_test_score"],
                                  b.cv_results_["mean_test_score"])
    with pytest.raises(ValueError, match=r"the fit parameter 'svr__verbose' is not taken"):
        fogdrift.SVRGridSearchCV(pipe, {"svr__C": [1]}, cv=3).fit(X, y, svr__verbose=True)
    with pytest.raises(ValueError, match=r"The 'refit' parameter of SVRGridSearchCV must be"):
        fogdrift.SVRGridSearchCV(pipe, {"svr__C": [1]}, refit="yes").fit(X, y)


def test_a_campaign_is_not_written_over_the_instrument_file_it_reads(tmp_path, cli):
    cli("simulate", "calibration", "--out", tmp_path / "cal", "--temps=-20,20",
        "--repetitions", "2")
    (tmp_path / "cal" / "unit.json").write_text(cli("simulate", "--print-instrument"))
    with pytest.raises(ValueError, match=r"option out: .* holds .*unit.json, which this call "
                                         r"reads"):
        fogdrift.simulate("calibration", out=tmp_path / "cal", replace=True,
                          instrument=tmp_path / "cal" / "unit.json", temps_degc=[-20, 20],
                          repetitions=2)
    assert (tmp_path / "cal" / "unit.json").exists()
