"""fogdrift.Model and recordings in Python, against the command line: the same model file, the
same drift and compensated gyro, to the bit, as `fogdrift train` and `fogdrift compensate`."""
import csv
import warnings

import numpy as np
import pytest

import fogdrift


@pytest.fixture(scope="module")
def trained(tmp_path_factory, cli):
    """A simulated calibration campaign and an SVR model trained on it by the command line."""
    d = tmp_path_factory.mktemp("model")
    cli("simulate", "calibration", "--out", d / "cal", "--seed", "2")
    cli("train", d / "cal", "--method", "svr", "-o", d / "m.json", "-q")
    recording = d / "cal" / "cal_r1_20C.csv"
    cli("compensate", d / "m.json", recording, "-o", d / "comp.csv", "-q")
    with open(d / "comp.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    expected = {k: np.array([float(r[k]) for r in rows])
                for k in ("drift_dph", "gyro_comp_dph", "novelty", "guard_weight")}
    return d, recording, expected


@pytest.fixture(scope="module")
def small(tmp_path_factory, cli):
    """A smaller calibration campaign (three temperatures, three sweeps) for the tests that train
    to check train's interface (both paths give the same model, options, errors), not its
    models: a fifth of the recordings, and the searches on them run in seconds."""
    cal = tmp_path_factory.mktemp("small") / "cal"
    cli("simulate", "calibration", "--out", cal, "--seed", "2", "--temps", "-20,10,40",
        "--repetitions", "3")
    return cal


def test_a_model_file_reads_and_writes_byte_for_byte(trained):
    d, _, _ = trained
    text = (d / "m.json").read_text()
    m = fogdrift.Model.load(d / "m.json")
    assert m.method == "svr"
    assert m.hyperparameters["C"] == 1.0 and m.hyperparameters["epsilon"] == 0.1
    assert len(m.feature_names) == 12 and m.training_rows > 0
    assert all(len(sha) == 64 for _, sha in m.training_files)
    assert m.to_json() == text
    m.save(d / "again.json")
    assert (d / "again.json").read_text() == text
    assert fogdrift.Model.from_json(text).to_json() == text
    assert "fogdrift.Model svr" in repr(m)


def test_a_model_set_loads_one_axis_by_its_target(trained, tmp_path):
    # A model set holds model files verbatim (docs/tuning.md): written here by hand, as any tool
    # may write one.
    d, _, _ = trained
    text = (d / "m.json").read_text()
    (tmp_path / "set.json").write_text(
        '{\n "format": "fogdrift-model-set",\n "version": 1,\n "targets": ["gyro_dph"],\n'
        ' "models": [\n' + text.rstrip("\n") + "\n ]\n}\n")
    m = fogdrift.Model.load(tmp_path / "set.json")
    assert m.target == "gyro_dph"
    assert m.to_json() == text
    assert fogdrift.Model.load(tmp_path / "set.json", target="gyro_dph").to_json() == text
    with pytest.raises(ValueError, match="target: the model has no axis 'gyro_y_dph' "
                                         "\\(it compensates gyro_dph\\)"):
        fogdrift.Model.load(tmp_path / "set.json", target="gyro_y_dph")


def test_drift_and_compensation_are_the_command_lines(trained):
    d, recording, expected = trained
    m = fogdrift.Model.load(str(d / "m.json"))
    columns = fogdrift.read_recording(recording)
    for source in (recording, str(recording), columns):
        p = m.predict(source)
        for k in ("drift_dph", "novelty", "guard_weight"):
            np.testing.assert_array_equal(p[k], expected[k])
        np.testing.assert_array_equal(m.compensate(source), expected["gyro_comp_dph"])
    # Unguarded: the model's own drift everywhere.
    np.testing.assert_array_equal(m.predict(columns, guarded=False)["drift_dph"],
                                  m.predict(columns)["model_drift_dph"])
    # Column order, extra columns and other sequence types do not matter.
    shuffled = {k: list(columns[k]) for k in reversed(list(columns))}
    shuffled["operator_note"] = np.zeros(len(columns["time_s"]))
    np.testing.assert_array_equal(m.compensate(shuffled), expected["gyro_comp_dph"])


def test_recordings_round_trip_and_open_in_pandas(trained, tmp_path):
    _, recording, _ = trained
    columns = fogdrift.read_recording(recording)
    assert list(columns)[:3] == ["time_s", "gyro_dph", "temp_fog_degc"]
    assert all(v.dtype == np.float64 for v in columns.values())
    fogdrift.write_recording(tmp_path / "copy.csv", columns)
    again = fogdrift.read_recording(tmp_path / "copy.csv")
    assert list(again) == list(columns) and "drift_true_dph" in again  # others kept, in order
    for k in columns:
        np.testing.assert_array_equal(again[k], columns[k])
    # A text column is written as it is and read back as text.
    n = columns["time_s"].size
    fogdrift.write_recording(tmp_path / "noted.csv", dict(columns, note=["ok"] * (n - 1) + ["x"]))
    assert fogdrift.read_recording(tmp_path / "noted.csv")["note"][-2:] == ["ok", "x"]
    with pytest.raises(ValueError, match="column note: has 3 values, time_s"):
        fogdrift.write_recording(tmp_path / "bad.csv", dict(columns, note=["a", "b", "c"]))
    pandas = pytest.importorskip("pandas")
    frame = pandas.read_csv(tmp_path / "copy.csv")
    np.testing.assert_array_equal(frame["gyro_dph"].to_numpy(), columns["gyro_dph"])
    fogdrift.write_recording(tmp_path / "frame.csv", frame)
    np.testing.assert_array_equal(fogdrift.read_recording(tmp_path / "frame.csv")["time_s"],
                                  columns["time_s"])


def test_bad_input_is_a_value_error_naming_the_file_and_rule(trained, tmp_path):
    d, recording, _ = trained
    m = fogdrift.Model.load(d / "m.json")
    columns = fogdrift.read_recording(recording)
    missing = {k: v for k, v in columns.items() if k != "temp_fog_degc"}
    with pytest.raises(ValueError, match="missing required column temp_fog_degc"):
        m.predict(missing)
    backwards = dict(columns, time_s=columns["time_s"][::-1].copy())
    with pytest.raises(ValueError, match="time_s"):
        m.compensate(backwards)
    with pytest.raises(ValueError, match="must be a 1-D array"):
        m.predict(dict(columns, gyro_dph=np.zeros((2, 2))))
    bad = tmp_path / "bad.csv"
    bad.write_text("time_s,gyro_dph,temp_fog_degc\n0,1,20\n1,x,20\n")
    with pytest.raises(ValueError, match=r"bad\.csv:3:2"):
        fogdrift.read_recording(bad)
    edited = (d / "m.json").read_text().replace('"epsilon": 0.1', '"epsilon": 0.2', 1)
    assert edited != (d / "m.json").read_text()
    with pytest.raises(ValueError, match="checksum"):
        fogdrift.Model.from_json(edited)
    assert fogdrift.Model.from_json(edited, allow_edited=True).method == "svr"
    # A file of format version 2 has no checksum: it loads only when asked for.
    import json
    old = json.loads((d / "m.json").read_text())
    old["version"] = 2
    del old["checksum"]
    with pytest.raises(ValueError, match="version: format version 2 carries no checksum"):
        fogdrift.Model.from_json(json.dumps(old))
    assert fogdrift.Model.from_json(json.dumps(old), allow_old_format=True).method == "svr"
    with pytest.raises(ValueError, match="nothing.json"):
        fogdrift.Model.load(tmp_path / "nothing.json")


def test_train_gives_the_command_lines_model_byte_for_byte(trained, small, tmp_path, cli):
    d, _, _ = trained
    r = fogdrift.train(d / "cal", method="svr")
    assert r["model"].to_json() == (d / "m.json").read_text()
    assert r["summary"]["method"] == "svr" and r["summary"]["recordings"] > 0
    # On the smaller campaign: a tuned model, its search reported through the progress callback.
    # On the paper's target (denoise): the search, not the target, is under test, and its models
    # are smaller and faster.
    seen = []
    tuned = fogdrift.train(str(small), population=8, iterations=3, seed=5, threads=2,
                           denoise=True,
                           progress=lambda p: seen.append((p["iteration"], p["best_rmse"])))
    # How sure train is, as the command line's --json says it, from the same run.
    held = cli("train", small, "--population", "8", "--iterations", "3", "--seed", "5",
               "--denoise", "-o", tmp_path / "t.json", "--json")
    assert tuned["model"].to_json() == (tmp_path / "t.json").read_text()
    assert [i for i, _ in seen] == [0, 1, 2, 3]
    assert all(b >= a for (_, a), (_, b) in zip(seen[1:], seen))  # best so far never worsens
    assert tuned["summary"]["fitness_rmse"] == seen[-1][1]
    import json
    expected = json.loads(held)["held_out"]
    assert tuned["summary"]["held_out"]["expected_share"] == expected["expected_share"]
    assert tuned["summary"]["held_out"]["expected_startup_share"] == \
        expected["expected_startup_share"]
    assert [b["name"] for b in tuned["summary"]["held_out"]["baselines"]][0] == "mean"
    # The search as the command line's --json reports it, under the same keys (issue 35).
    got = json.loads(held)
    assert tuned["summary"]["cv"] == got["cv"]
    assert len(tuned["summary"]["boxes_searched"]) == len(got["boxes_searched"])
    assert [e["parameter"] for e in tuned["summary"]["box_edges"]] == \
        [e["parameter"] for e in got["box_edges"]]
    assert tuned["summary"]["search"]["evaluations"] == got["search"]["evaluations"]
    # racing=False is --no-racing: every fold fitted, no candidate stopped, the same model.
    every = fogdrift.train(str(small), population=8, iterations=3, seed=5, racing=False,
                           denoise=True)
    cli("train", small, "--population", "8", "--iterations", "3", "--seed", "5",
        "--no-racing", "--denoise", "-o", tmp_path / "every.json", "-q")
    assert every["model"].to_json() == (tmp_path / "every.json").read_text()
    assert every["summary"]["search"]["raced"] == 0
    assert every["summary"]["search"]["fits"] >= tuned["summary"]["search"]["fits"]
    assert set(got) - {"model"} <= set(tuned["summary"])  # every key but the file written
    for method, key in (("poly", "poly_cv_rmse_by_degree"), ("bp", "bp")):
        line = json.loads(cli("train", small, "--method", method, "-o", tmp_path / "b.json",
                              "--json"))
        with warnings.catch_warnings():  # how sure train is; not what this test checks
            warnings.simplefilter("ignore", UserWarning)
            summary = fogdrift.train(small, method=method)["summary"]
        assert set(line) - {"model"} <= set(summary), method
        assert summary[key] == line[key], method
    # A box too small: the edge warning the command line prints, in this function's words.
    with pytest.warns(UserWarning, match=r"C = .* upper edge .* a wider box may do better: "
                                         r"c_max or auto_box=True"):
        edged = fogdrift.train(str(small), population=6, iterations=2, seed=5, c_max=0.02)
    assert edged["summary"]["box_edges"][0]["parameter"] == "C"
    assert any("c_max or auto_box=True" in w for w in edged["summary"]["warnings"])


def test_train_options_and_errors_use_the_librarys_names(small):
    r = fogdrift.train(small, method="poly", features="T(fog),dT(fog)", block_s=20,
                       max_degree=2)
    assert r["model"].feature_names == ["T_fog_degc", "dT_fog_degc_per_s"]
    assert r["summary"]["block_s"] == 20
    for kwargs, message in [
            (dict(method="svm"), "option method: 'svm' is not a method"),
            (dict(population=1), "option population: 1 must be ≥ 2"),
            (dict(block_s="soon"), "option block_s: 'soon' is neither auto nor a number of seconds"),
            (dict(features="T(gps)"), "gps"),
            # The library's fields under this function's keywords, not degree or window_s.
            (dict(method="poly", max_degree=99), "option max_degree: 99 must be between 1 and 6"),
            (dict(rate_window_s=3.0), "option rate_window_s: a window of 3"),
            (dict(threads=-1), "option threads: '-1' is not a whole number ≥ 0"),
            # The epsilon search's own bounds, not --epsilon's (issue 34).
            (dict(search_epsilon=True, epsilon_min=0.0), "option epsilon_min: 0 must be > 0"),
    ]:
        with pytest.raises(ValueError, match=message):
            fogdrift.train(small, **kwargs)
    with pytest.raises(ValueError, match="campaign.json"):
        fogdrift.train(small.parent / "no such campaign")

    def stop(progress):
        raise KeyboardInterrupt("stopped by the user")

    with pytest.raises(KeyboardInterrupt, match="stopped by the user"):
        fogdrift.train(small, population=8, iterations=3, progress=stop)


def test_a_gaussian_process_trains_as_the_command_line_does(small, tmp_path, cli):
    budget = dict(population=5, iterations=3, seed=2)
    with warnings.catch_warnings():  # how sure train is; not what this test checks
        warnings.simplefilter("ignore", UserWarning)
        r = fogdrift.train(small, method="gp", gp_points=150, **budget)
    import json
    line = json.loads(cli("train", small, "--method", "gp", "--gp-points", "150",
                          "--population", "5", "--iterations", "3", "--seed", "2", "-o",
                          tmp_path / "gp.json", "--json"))
    assert r["model"].to_json() == (tmp_path / "gp.json").read_text()
    assert r["model"].method == "gp"
    assert r["summary"]["gp"] == line["gp"] and r["summary"]["gp"]["points"] == 150
    assert set(r["summary"]["hyperparameters"]) == {"signal_variance", "noise_variance", "points",
                                                    "length_scale"}
    for kwargs, message in [
            (dict(gp_fit="ml"), "option gp_fit: 'ml' is not a way to choose the hyperparameters"),
            (dict(gp_kernel="ard"), "option gp_kernel: ard .* needs the likelihood fit"),
            (dict(gp_kernel="matern"), "option gp_kernel: 'matern' is not rbf or ard"),
            (dict(gp_points=5), "option gp_points: 5 must be between 10 and 4000"),
    ]:
        with pytest.raises(ValueError, match=message):
            fogdrift.train(small, method="gp", **kwargs)


def test_train_rejects_a_block_that_is_not_a_positive_number(trained):
    d, _, _ = trained
    with pytest.raises(ValueError,
                       match="option rate_window_s: '-5' is neither auto nor a number of seconds"):
        fogdrift.train(d / "cal", method="svr", rate_window_s=-5)
    for bad, message in [(0, "0 is outside 1 … 4"), (5, "5 is outside 1 … 4"),
                         ("two", "'two' is neither auto nor a whole number")]:
        with pytest.raises(ValueError, match="option rate_degree: " + message):
            fogdrift.train(d / "cal", method="svr", rate_degree=bad)
    with pytest.raises(TypeError, match=r"train\(\): rate_degree must be 'auto' \(or None\) or an "
                                        r"int, not float \(1.5\)"):
        fogdrift.train(d / "cal", method="svr", rate_degree=1.5)


def test_causal_rates_default_to_a_line_over_61_s(small):
    causal = fogdrift.train(small, method="poly", differentiator="causal")["summary"]
    assert (causal["rate_window_s"], causal["rate_degree"]) == (61, 1)
    centred = fogdrift.train(small, method="poly")["summary"]
    assert (centred["rate_window_s"], centred["rate_degree"]) == (121, 2)
    given = fogdrift.train(small, method="poly", differentiator="causal", rate_degree=2,
                           rate_window_s=91)["summary"]
    assert (given["rate_window_s"], given["rate_degree"]) == (91, 2)


def test_a_model_pickles_as_its_file(trained):
    """A model crosses to another process (a Dask worker) as its file's text, checked again."""
    import pickle
    d, _, _ = trained
    m = fogdrift.Model.load(d / "m.json")
    again = pickle.loads(pickle.dumps(m))
    assert again.to_json() == m.to_json() and again.feature_names == m.feature_names


@pytest.mark.filterwarnings("ignore:the model was trained with centred")
def test_a_wrong_type_is_a_type_error_naming_the_keyword(trained):
    d, recording, _ = trained
    m = fogdrift.Model.load(d / "m.json")
    for call, message in [
            (lambda: fogdrift.train(d / "cal", folds="three"),
             r"train\(\): folds must be an int, not str \('three'\)"),
            (lambda: fogdrift.train(d / "cal", c_max="big"),
             r"train\(\): c_max must be a number, not str"),
            (lambda: fogdrift.train(d / "cal", foldz=3),
             r"train\(\) got an unexpected keyword argument 'foldz'; its keywords are campaign, "),
            # Each type of option, and the keywords only Python has.
            (lambda: fogdrift.train(d / "cal", racing="no"),
             r"train\(\): racing must be a bool, not str \('no'\)"),
            (lambda: fogdrift.train(d / "cal", thermometers=["fog", 3]),
             r"train\(\): thermometers must be a str or a list of str, not list"),
            (lambda: fogdrift.train(d / "cal", method=2),
             r"train\(\): method must be a str, not int"),
            (lambda: fogdrift.train(d / "cal", block_s=[10]),
             r"train\(\): block_s must be 'auto' \(or None\) or a number of seconds, not list"),
            (lambda: fogdrift.train(d / "cal", population=True),
             r"train\(\): population must be an int, not bool"),
            (lambda: fogdrift.train(d / "cal", threads=1.5),
             r"train\(\): threads must be an int, not float"),
            (lambda: fogdrift.train(d / "cal", validate_only=1),
             r"train\(\): validate_only must be a bool, not int"),
            (lambda: fogdrift.train(d / "cal", progress=3),
             r"train\(\): progress must be .auto., True, False, .lines., None or a callable, not int \(3\)"),
            (lambda: fogdrift.simulate("calibration", seed="1"),
             r"simulate\(\): seed must be an int, not str"),
            (lambda: fogdrift.denoise(np.ones(64), level=1.5),
             r"denoise\(\): level must be 'auto' \(or None\) or an int, not float \(1.5\)"),
            (lambda: fogdrift.Model.load(3), r"Model.load\(\): path must be a path, not int"),
            (lambda: m.predict(recording, guarded="no"),
             r"Model.predict\(\): guarded must be a bool, not str"),
            (lambda: fogdrift.StreamingCompensator(m, "1 s"),
             r"StreamingCompensator\(\): dt_s must be a number, not str"),
            (lambda: fogdrift.StreamingCompensator(m, 1.0).update(0.0, "0", 20.0),
             r"StreamingCompensator.update\(\): gyro_dph must be a number, not str"),
    ]:
        with pytest.raises(TypeError, match=message):
            call()
    # Right types still pass through, NumPy scalars included.
    assert fogdrift.StreamingCompensator(m, np.float64(1.0)).update(
        np.float64(1.0), 0.0, 20.0, 20.0, 20.0)[2] == 0
