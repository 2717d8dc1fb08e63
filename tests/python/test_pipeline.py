"""The gyro pipeline in Python against the command line and independent references: simulate,
denoise (PyWavelets), features (SciPy's Savitzky-Golay filter), evaluate (Table 2), northfind
(Table 3), the Allan deviation (its defining formula) and the streaming compensator."""
import csv
import json
import math
import warnings

import numpy as np
import pytest
import pywt
from scipy.signal import lfilter, savgol_filter

import fogdrift


@pytest.fixture(scope="module")
def campaign(tmp_path_factory, cli):
    """A small calibration campaign from Python and the same from the command line, a model the
    command line trained on it, and a north-finding campaign."""
    d = tmp_path_factory.mktemp("pipeline")
    py = fogdrift.simulate("calibration", out=d / "cal", seed=3, temps_degc=[-20, 10, 40],
                           repetitions=2)
    cli("simulate", "calibration", "--out", d / "cal_cli", "--seed", "3", "--temps", "-20,10,40",
        "--repetitions", "2")
    cli("train", d / "cal", "--method", "svr", "-o", d / "m.json", "-q")
    cli("simulate", "northfind", "--out", d / "nf", "--temps", "-16,28", "--findings", "2")
    return d, py


def test_simulate_writes_the_command_lines_files(campaign):
    d, py = campaign
    manifest = json.loads((d / "cal" / "campaign.json").read_text())
    assert manifest == json.loads((d / "cal_cli" / "campaign.json").read_text())
    assert [r["file"] for r in py["recordings"]] == [r["file"] for r in manifest["recordings"]]
    assert py["latitude_deg"] == manifest["latitude_deg"]
    for entry, data in zip(manifest["recordings"], py["data"]):
        text = (d / "cal" / entry["file"]).read_bytes()
        assert text == (d / "cal_cli" / entry["file"]).read_bytes()
        # The arrays returned are the numbers written (shortest round-trip text).
        on_disk = fogdrift.read_recording(d / "cal" / entry["file"])
        assert set(on_disk) == set(data)
        for name, values in on_disk.items():
            np.testing.assert_array_equal(data[name], values)
    assert "drift_true_dph" in py["data"][0]


def test_simulate_options_are_the_librarys_and_checked():
    nf = fogdrift.simulate("northfind", temps_degc=[25], findings=1, approach="soaked", seed=2)
    assert len(nf["data"]) == 1 and nf["recordings"][0]["scenario"] == "northfind"
    assert "table_deg" in nf["data"][0]
    for kwargs, message in [
            (dict(scenario="storm"), "option scenario: must be 'calibration'"),
            (dict(repetitions=0), "option repetitions: 0 must be between 1 and 100"),
            (dict(temps_degc="warm"), "option temps_degc: 'warm' in 'warm' is not a finite"),
            (dict(temps_degc=[200]), "option temps_degc: 200 °C must be between -70 and 100"),
            (dict(approaches="sunny"), "option approaches"),
            (dict(scenario="stable", findings=0), "option findings: 0 must be between 1 and 1000"),
            (dict(instrument={"fog": {"bias_dph": "x"}}), "instrument"),
            (dict(instrument="/nonexistent/unit.json"), "unit.json: cannot open"),
    ]:
        with pytest.raises(ValueError, match=message):
            fogdrift.simulate(**kwargs)
    # A keyword the scenario does not have, or a value of a type the option does not take.
    for kwargs, message in [
            (dict(temps_degc=[20], speed=2), "unexpected keyword argument 'speed'; the "
                                             "calibration simulation's options are temps_degc"),
            (dict(scenario="northfind", repetitions=2), "unexpected keyword argument"),
            (dict(temps_degc={"a": 1}), "temps_degc must be a list of numbers or a str"),
            (dict(temps_degc=["20"]), "temps_degc must be a list of numbers or a str"),
            (dict(findings=2.5, scenario="northfind"), "findings must be an int"),
    ]:
        with pytest.raises(TypeError, match=message):
            fogdrift.simulate(**kwargs)


def test_denoise_is_pywavelets_universal_soft_thresholding():
    rng = np.random.default_rng(7)
    t = np.arange(1800.0)
    # A step leaves detail coefficients above the threshold, which soft shrinkage moves.
    x = 0.02 * np.exp(-t / 400) + 0.05 * (t > 900) + 0.003 * rng.normal(size=t.size)
    ours, summary = fogdrift.denoise(x, wavelet="sym4", level=4, threshold="universal",
                                     summary=True)
    coeffs = pywt.wavedec(x, "sym4", mode="symmetric", level=4)
    sigma = np.median(np.abs(coeffs[-1])) / 0.6745
    lam = sigma * math.sqrt(2 * math.log(x.size))
    ref = pywt.waverec([coeffs[0]] + [pywt.threshold(c, lam, mode="soft") for c in coeffs[1:]],
                       "sym4", mode="symmetric")[:x.size]
    np.testing.assert_allclose(ours, ref, rtol=0, atol=1e-15)
    assert 0 < sum(b["kept"] for b in summary["bands"]) < x.size // 4
    assert summary["level"] == 4 and summary["noise_sigma"] == pytest.approx(sigma, rel=1e-14)
    assert [b["threshold"] for b in summary["bands"]] == pytest.approx([lam] * 4, rel=1e-14)
    # Hard shrinkage and another extension, as pywt names them.
    hard = fogdrift.denoise(x, wavelet="db2", level=3, threshold="universal", mode="hard",
                            extension="periodization")
    c = pywt.wavedec(x, "db2", mode="periodization", level=3)
    lam = np.median(np.abs(c[-1])) / 0.6745 * math.sqrt(2 * math.log(x.size))
    ref = pywt.waverec([c[0]] + [pywt.threshold(b, lam, mode="hard") for b in c[1:]], "db2",
                       mode="periodization")
    np.testing.assert_allclose(hard, ref, atol=1e-15)
    # Any float sequence, either memory order, is the same signal.
    np.testing.assert_array_equal(fogdrift.denoise(list(x)), fogdrift.denoise(x))
    with pytest.raises(ValueError, match="not a finite number"):
        fogdrift.denoise(np.r_[x[:10], np.nan, x[11:]])
    with pytest.raises(ValueError, match="option wavelet"):
        fogdrift.denoise(x, wavelet="morlet")
    with pytest.raises(ValueError, match="option mode"):
        fogdrift.denoise(x, mode="medium")
    with pytest.raises(ValueError, match="option data: must be a 1-D array"):
        fogdrift.denoise(np.zeros((4, 400)))


def test_features_are_block_means_of_the_temperatures_and_their_rates(campaign):
    d, py = campaign
    rec = py["data"][0]
    f = fogdrift.features(rec)
    assert f["spec"] == "T,dT,grad,dT@300" and len(f["names"]) == 12 and f["block"] == 10
    x = f["x"]
    assert x.shape == (rec["time_s"].size // 10, 12) and x.flags.c_contiguous
    blocks = lambda v: v[:x.shape[0] * 10].reshape(-1, 10).mean(axis=1)  # noqa: E731
    col = {n: x[:, i] for i, n in enumerate(f["names"])}
    np.testing.assert_allclose(col["T_fog_degc"], blocks(rec["temp_fog_degc"]), rtol=1e-13)
    np.testing.assert_allclose(col["grad_fog_acc1_degc"],
                               blocks(rec["temp_fog_degc"] - rec["temp_acc1_degc"]), atol=1e-12)
    # The centred rate: SciPy's Savitzky-Golay derivative (121 samples, degree 2) inside the
    # recording, where neither filter reaches an end.
    rate = savgol_filter(rec["temp_fog_degc"], 121, 2, deriv=1, delta=1.0)
    inner = slice(7, x.shape[0] - 7)
    np.testing.assert_allclose(col["dT_fog_degc_per_s"][inner], blocks(rate)[inner], atol=1e-12)
    np.testing.assert_allclose(f["time_s"], blocks(rec["time_s"]))
    # The rate through a 300 s lag: SciPy's first-order IIR s = g·T + (1 − g)·s, from rest at
    # the first sample, and (T − s)/τ (docs/signal.md §4).
    g = -np.expm1(-1.0 / 300)
    temp = rec["temp_acc2_degc"]
    s, _ = lfilter([g], [1.0, g - 1.0], temp, zi=[(1.0 - g) * temp[0]])
    np.testing.assert_allclose(col["dT300s_acc2_degc_per_s"], blocks((temp - s) / 300), atol=1e-14)
    # A model's own features: the rows it predicts from.
    m = fogdrift.Model.load(d / "m.json")
    fm = fogdrift.features(rec, model=m)
    assert fm["names"] == m.feature_names
    np.testing.assert_array_equal(fm["x"], x)
    one = fogdrift.features(rec, "T(fog),dT(fog)", block_s=20, rate_window_s=61)
    assert one["names"] == ["T_fog_degc", "dT_fog_degc_per_s"] and one["block"] == 20
    with pytest.raises(ValueError, match="option block_s"):
        fogdrift.features(rec, block_s=15.5)
    with pytest.raises(ValueError, match="give a feature spec or a model"):
        fogdrift.features(rec, "T", model=m)
    with pytest.raises(ValueError, match="option model: its own preprocessing is used"):
        fogdrift.features(rec, model=m, block_s=20)


def without(d, *keys):
    return {k: v for k, v in d.items() if k not in keys}


def test_evaluate_is_the_command_lines_table_2(campaign, cli):
    d, py = campaign
    m = fogdrift.Model.load(d / "m.json")
    for flags, kwargs in [((), {}), (("--allan", "--no-guard"), dict(allan=True, guarded=False))]:
        expected = json.loads(cli("evaluate", d / "m.json", d / "cal", "--json", *flags))
        got = fogdrift.evaluate(m, d / "cal", **kwargs)
        assert without(got, "source") == without(expected, "model", "source")
    # Recordings given as arrays: the same figures as the files.
    files = [d / "cal" / r["file"] for r in py["recordings"] if r["role"] == "test"]
    expected = json.loads(cli("evaluate", d / "m.json", *files, "--json"))
    got = fogdrift.evaluate(m, [py["data"][i] for i, r in enumerate(py["recordings"])
                                if r["role"] == "test"])
    for a, b in zip(got["recordings"], expected["recordings"]):
        assert without(a, "file") == without(b, "file")
    assert got["overall"] == expected["overall"]
    assert got["overall"]["std_compensated_dph"] < got["overall"]["std_denoised_dph"]
    # The rate the gyro sensed, for recordings without a manifest: as --input-rate-dph.
    expected = json.loads(cli("evaluate", d / "m.json", *files, "--json", "--input-rate-dph", "7.5"))
    got = fogdrift.evaluate(m, files, input_rate_dph=7.5)
    assert got["overall"] == expected["overall"]
    with pytest.warns(UserWarning, match="the turn-on bias is lost") as lost:
        without_rate = fogdrift.evaluate(m, files)
    assert lost[0].filename == __file__  # the user's line, not the package's
    assert [str(w.message) for w in lost][:len(without_rate["warnings"])] == without_rate["warnings"]
    assert got["overall"]["mae_before_dph"] != without_rate["overall"]["mae_before_dph"]
    # The keyword's type, number or none: None is the keyword not given, a word is refused.
    with pytest.warns(UserWarning, match="the turn-on bias is lost"):
        assert fogdrift.evaluate(m, files, input_rate_dph=None)["overall"] == \
            without_rate["overall"]
    with pytest.raises(TypeError, match=r"evaluate\(\): input_rate_dph must be None or a number"):
        fogdrift.evaluate(m, files, input_rate_dph=[7.5])
    with pytest.raises(ValueError, match="input_rate_dph: applies to recordings"):
        fogdrift.evaluate(m, d / "cal", input_rate_dph=0.0)
    with pytest.raises(ValueError, match="no calibration recordings with role test"):
        fogdrift.evaluate(m, d / "nf")
    # The campaign fogdrift.simulate returned, as train takes it (issue 35: it was refused).
    in_memory = fogdrift.evaluate(m, py)
    assert without(in_memory, "source") == without(fogdrift.evaluate(m, d / "cal"), "source")


def test_northfind_is_the_command_lines_table_3(campaign, cli):
    d, _ = campaign
    m = fogdrift.Model.load(d / "m.json")
    expected = json.loads(cli("northfind", d / "nf", "--json"))
    assert without(fogdrift.northfind(d / "nf"), "campaign") == without(expected, "campaign")
    expected = json.loads(cli("northfind", d / "nf", "--model", d / "m.json", "--json"))
    got = fogdrift.northfind(d / "nf", m)
    assert without(got, "campaign") == without(expected, "campaign", "model")
    assert got["table3"]["temps_degc"] == [-16, 28]
    assert len(got["recordings"][0]["compensated_error_deg"]) == 2
    with pytest.raises(ValueError, match="no northfind or stable recordings"):
        fogdrift.northfind(d / "cal")
    # The campaign simulate returns, in memory (issue 35): the folder's findings.
    held = fogdrift.simulate("northfind", out=d / "nf_py", temps_degc=[-16, 28], findings=2)
    assert without(fogdrift.northfind(held, m), "campaign") == \
        without(fogdrift.northfind(d / "nf_py", m), "campaign")
    # One recording on its own, as in the field: the same findings, raw and compensated.
    entry = got["recordings"][0]
    manifest = json.loads((d / "nf" / "campaign.json").read_text())
    recording = d / "nf" / entry["file"]
    for model, key in [(None, "raw_error_deg"), (m, "compensated_error_deg")]:
        findings = fogdrift.find_north(recording, manifest["latitude_deg"], model)
        assert len(findings) == 2
        for f, error in zip(findings, entry[key]):
            off = (f["azimuth_deg"] - entry["true_azimuth_deg"] + 180) % 360 - 180
            assert off == pytest.approx(error, abs=1e-9)
            assert f["start_s"] < f["end_s"] and len(f["gyro_dph"]) == 4
    columns = fogdrift.read_recording(recording)
    del columns["table_deg"]
    with pytest.raises(ValueError, match="needs the columns table_deg"):
        fogdrift.find_north(columns, 30.0)
    with pytest.raises(ValueError, match="option latitude_deg"):
        fogdrift.find_north(recording, 95.0)


def overlapping_adev(rate, dt, m):
    """IEEE Std 952's overlapping Allan deviation at cluster size m, from the angle."""
    theta = np.concatenate([[0.0], np.cumsum(rate) * dt])
    tau = m * dt
    d = theta[2 * m:] - 2 * theta[m:-m] + theta[:-2 * m]
    return math.sqrt(np.sum(d * d) / (2 * tau * tau * (rate.size - 2 * m + 1)))


def test_allan_deviation_is_the_overlapping_estimator():
    rng = np.random.default_rng(11)
    dt = 0.5
    rate = 0.01 * rng.normal(size=20000) + 1e-4 * np.cumsum(rng.normal(size=20000))
    tau, adev, m = fogdrift.allan_deviation(rate, dt)
    assert list(m[:5]) == [1, 2, 4, 8, 16] and m[-1] <= rate.size // 2
    np.testing.assert_allclose(tau, m * dt)
    for k in range(len(m)):
        assert adev[k] == pytest.approx(overlapping_adev(rate, dt, int(m[k])), rel=1e-10)
    # White rate noise of σ per sample: σ(τ) = σ·√(dt/τ); the ARW is σ·√dt in °/√h units.
    white = 0.05 * rng.normal(size=200000)
    terms = fogdrift.noise_terms(white, dt_s=1.0)
    assert terms["arw_deg_per_rt_h"] == pytest.approx(0.05 / 60, rel=0.05)
    with pytest.raises(ValueError, match="option rate: sample 3 is not a finite number"):
        fogdrift.allan_deviation([1.0, 2.0, 3.0, np.inf, 5.0])


def test_the_stream_is_the_command_lines_stream(campaign, cli, tmp_path):
    d, _ = campaign
    m = fogdrift.Model.load(d / "m.json")
    recording = d / "cal" / "cal_r2_10C.csv"
    cli("stream", d / "m.json", recording, "--rate-hz", "1")  # prints; read it back below
    with open(tmp_path / "s.csv", "w") as f:
        f.write(cli("stream", d / "m.json", recording, "--rate-hz", "1"))
    with open(tmp_path / "s.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    with pytest.warns(UserWarning, match="trained with centred temperature rates"):
        s = fogdrift.StreamingCompensator(m, 1.0)
    out = s.run(recording)
    for name in ("drift_dph", "gyro_comp_dph", "novelty", "guard_weight"):
        np.testing.assert_array_equal(out[name], [float(r[name]) for r in rows])
    np.testing.assert_array_equal(out["fault_flags"], [int(r["fault_flags"]) for r in rows])
    # One sample at a time gives the same; a NaN reading is flagged, not an error.
    columns = fogdrift.read_recording(recording)
    s.reset()
    for i in range(50):
        drift, comp, flags = s.update(columns["time_s"][i], columns["gyro_dph"][i],
                                      columns["temp_fog_degc"][i], columns["temp_acc1_degc"][i],
                                      columns["temp_acc2_degc"][i])
        assert (drift, comp, flags) == (out["drift_dph"][i], out["gyro_comp_dph"][i], 0)
    drift, comp, flags = s.update(50.0, float("nan"), 20.0, 20.0, 20.0)
    assert math.isfinite(drift) and flags != 0
    assert "gyro" in fogdrift.StreamingCompensator.describe_flags(flags)
    columns["temp_fog_degc"][100] = np.nan
    with pytest.warns(UserWarning):
        flagged = fogdrift.StreamingCompensator(m, 1.0).run(columns)["fault_flags"]
    assert flagged[100] != 0 and np.count_nonzero(flagged) < 10
    with pytest.raises(ValueError, match="option temp_acc1_degc: the model reads"):
        s.update(51.0, 0.0, 20.0)
    with pytest.raises(ValueError, match="option bridge_s"):
        fogdrift.StreamingCompensator(m, 1.0, bridge_s=-1)
    with pytest.raises(ValueError, match="option hold_s: 1 s must be finite and no shorter"):
        fogdrift.StreamingCompensator(m, 1.0, hold_s=1)
    with pytest.raises(ValueError, match="option dt_s"):
        fogdrift.StreamingCompensator(m, 0.0)
    for kwargs, message in [(dict(bridge_ms=5), "unexpected keyword argument 'bridge_ms'"),
                            (dict(bridge_s="5"), "bridge_s must be a number, not str"),
                            (dict(guarded="yes"), "guarded must be a bool, not str")]:
        with pytest.raises(TypeError, match=message):
            fogdrift.StreamingCompensator(m, 1.0, **kwargs)


def test_a_causal_model_streams_its_batch_drift_without_a_warning(campaign, recwarn):
    d, _ = campaign
    causal = fogdrift.train(d / "cal", method="svr", differentiator="causal")["model"]
    recwarn.clear()  # train's own warnings (how sure it is) are not the stream's
    columns = fogdrift.read_recording(d / "cal" / "cal_r2_40C.csv")
    streamed = fogdrift.StreamingCompensator(causal, 1.0).run(columns)
    np.testing.assert_array_equal(streamed["drift_dph"], causal.predict(columns)["drift_dph"])
    assert not [w for w in recwarn if issubclass(w.category, UserWarning)]
    # The model records its 1 s interval: 2 s data are refused, naming the keyword.
    with pytest.raises(ValueError, match="option dt_s: the data come every 2 s"):
        fogdrift.StreamingCompensator(causal, 2.0)


def test_a_campaign_in_memory_trains_the_folders_model(campaign):
    d, py = campaign
    on_disk = fogdrift.train(d / "cal", method="svr")["model"].to_json()
    assert fogdrift.train(py, method="svr")["model"].to_json() == on_disk
    # Recordings as DataFrames, as a user's own loading code gives them.
    pandas = pytest.importorskip("pandas")
    frames = dict(py, data=[pandas.DataFrame(r) for r in py["data"]])
    assert fogdrift.train(frames, method="svr")["model"].to_json() == on_disk
    with pytest.raises(ValueError, match="data: required in a campaign given as a dict"):
        fogdrift.train({k: v for k, v in py.items() if k != "data"})
    with pytest.raises(ValueError, match="has 6 recordings in its manifest and 5 given"):
        fogdrift.train(dict(py, data=py["data"][:5]))
    broken = [dict(r) for r in py["data"]]
    del broken[2]["temp_fog_degc"]
    with pytest.raises(ValueError, match=r"campaign data\[2\] \(cal_r1_40C.csv\): missing"):
        fogdrift.train(dict(py, data=broken))


def test_every_axis_trains_its_own_model_and_saves_as_one_file(campaign, cli, tmp_path):
    d, py = campaign
    # A second axis that reads as the first turned over: the same drift, negated.
    data = [dict(r, gyro_y_dph=-r["gyro_dph"]) for r in py["data"]]
    # The Earth rate of a true azimuth is the FOG axis's; another axis needs its input rate.
    with pytest.raises(ValueError, match="the Earth rate a true azimuth gives is the FOG axis's"):
        fogdrift.train(dict(py, data=data), method="poly", target="gyro_y_dph")
    static = dict(py, data=data, recordings=[dict(r, input_rate_dph=0.0) for r in py["recordings"]])
    x = fogdrift.train(static, method="poly")["model"]
    y = fogdrift.train(static, method="poly", target="gyro_y_dph")["model"]
    assert (x.target, y.target) == ("gyro_dph", "gyro_y_dph")
    rec = data[-1]
    assert np.allclose(y.predict(rec)["drift_dph"], -x.predict(rec)["drift_dph"], rtol=1e-9,
                       atol=1e-12)
    assert np.allclose(y.compensate(rec), -x.compensate(rec), rtol=1e-9, atol=1e-12)
    ex = fogdrift.evaluate(x, [rec], input_rate_dph=0.0)["overall"]
    ey = fogdrift.evaluate(y, [rec], input_rate_dph=0.0)["overall"]
    assert math.isclose(ey["mae_dph"], ex["mae_dph"], rel_tol=1e-9)
    fogdrift.save_models(tmp_path / "imu.json", [x, y])
    assert fogdrift.Model.load(tmp_path / "imu.json", target="gyro_y_dph").to_json() == y.to_json()
    # The command line reads the file as train --targets writes it: a table per axis.
    fogdrift.write_recording(tmp_path / "rec.csv", rec)
    got = json.loads(cli("evaluate", tmp_path / "imu.json", tmp_path / "rec.csv", "--json",
                         "--input-rate-dph", "0"))
    assert [a["target"] for a in got["axes"]] == ["gyro_dph", "gyro_y_dph"]
    with pytest.raises(ValueError, match="target: 'gyroY' is not a target: a gyro"):
        fogdrift.train(static, method="poly", target="gyroY")
    with pytest.raises(ValueError, match="has no column 'gyro_z_dph'"):
        fogdrift.train(static, method="poly", target="gyro_z_dph")


def test_an_accelerometer_is_a_target_with_its_own_reference(campaign):
    d, py = campaign
    # The simulated unit is level: its x accelerometer senses no gravity, only its bias.
    level = dict(py, recordings=[dict(r, references={"accel_x_g": 0.0}) for r in py["recordings"]])
    with pytest.warns(UserWarning, match=r"a straight line in it \(method poly, max_degree 1, "
                                         r"features 'T\(acc1\)'\) is simpler to trust"):
        m = fogdrift.train(level, method="poly", target="accel_x_g")["model"]
    assert m.target == "accel_x_g"
    rec = py["data"][-1]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        got = fogdrift.evaluate(m, [rec], references={"accel_x_g": 0.0})["overall"]
    assert "mae_g" in got and "mae_dph" not in got
    assert got["mae_g"] < 0.5 * got["mae_before_g"]
    assert np.allclose(m.compensate(rec), np.asarray(rec["accel_x_g"]) - m.predict(rec)["drift_g"])
    with pytest.warns(UserWarning, match=r"no reference for accel_x_g is known.*give it as "
                                         r"references=\{'accel_x_g': VALUE\}, g\)"):
        fogdrift.evaluate(m, [rec])
    with pytest.raises(ValueError, match="references: 'temp_fog_degc' is not a target"):
        fogdrift.evaluate(m, [rec], references={"temp_fog_degc": 0.0})
    with pytest.raises(ValueError, match="references: accel_x_g: 'nan' is not a finite number"):
        fogdrift.evaluate(m, [rec], references={"accel_x_g": float("nan")})
    # The keyword's type, assignments: a dict, or a list of "NAME=VALUE" as --reference takes.
    assert fogdrift.evaluate(m, [rec], references=["accel_x_g=0"])["overall"] == got
    with pytest.raises(ValueError, match="references: accel_x_g is given twice"):
        fogdrift.evaluate(m, [rec], references=["accel_x_g=0", "accel_x_g=0.1"])
    with pytest.raises(TypeError, match=r"evaluate\(\): references must be a dict or a list"):
        fogdrift.evaluate(m, [rec], references=0.0)


def test_malformed_inputs_are_value_errors_naming_the_rule(campaign):
    d, py = campaign
    m = fogdrift.Model.load(d / "m.json")
    rec = py["data"][0]
    with pytest.raises(ValueError, match="option data: no recordings to evaluate on"):
        fogdrift.evaluate(m, [])
    with pytest.raises(ValueError, match="a recording must be a path or a mapping"):
        fogdrift.evaluate(m, [42])
    with pytest.raises(ValueError, match="option campaign: must be a campaign folder"):
        fogdrift.northfind(d / "cal" / py["recordings"][0]["file"])
    with pytest.raises(ValueError, match="option rate: must be a 1-D array"):
        fogdrift.allan_deviation(np.zeros((10, 2)))
    with pytest.raises(ValueError, match="option rate: must be a 1-D array"):
        fogdrift.noise_terms(np.zeros((10, 2)))
    with pytest.warns(UserWarning):
        stream = fogdrift.StreamingCompensator(m, 1.0)
    with pytest.raises(ValueError, match="missing column time_s"):
        stream.run({"gyro_dph": rec["gyro_dph"]})
    with pytest.raises(ValueError, match=r"column gyro_dph: has 10 values, time_s \d+"):
        stream.run(dict(rec, gyro_dph=rec["gyro_dph"][:10]))


def test_a_fourth_thermometer_is_trained_on_and_streamed(campaign):
    """docs/logs.md, "More thermometers": a case thermometer each recording logs, with a drift
    term the other three do not see (as scripts/add_case_thermometer.py writes it)."""
    _, py = campaign
    data = []
    for i, rec in enumerate(py["data"]):
        rec = dict(rec)
        excess = 3.0 * np.sin(2 * np.pi * rec["time_s"] / 400.0 + 0.9 * i)
        rec["temp_case_degc"] = rec["temp_fog_degc"] + excess
        rec["gyro_dph"] = rec["gyro_dph"] + 4.0 * excess / 3.0
        data.append(rec)
    cal = dict(py, data=data)
    with pytest.warns(UserWarning, match="no better than the training mean"):
        three = fogdrift.train(cal, method="poly", differentiator="causal")
    assert any(field == "thermometers" and "temp_case_degc not read by the features" in text
               for field, text in three["summary"]["notes"])
    four = fogdrift.train(cal, method="poly", differentiator="causal",
                          thermometers=["fog", "acc1", "acc2", "case"])
    m = four["model"]
    assert len(four["summary"]["features"]) == 18
    assert "T_case_degc" in four["summary"]["features"]
    assert four["summary"]["held_out"]["model_rmse"] < 0.1 * three["summary"]["held_out"]["model_rmse"]
    same = fogdrift.train(cal, method="poly", differentiator="causal",
                          thermometers="fog,acc1,acc2,case")["model"]
    assert same.to_json() == m.to_json()

    columns = data[-1]
    batch = m.predict(columns)["drift_dph"]
    np.testing.assert_array_equal(fogdrift.StreamingCompensator(m, 1.0).run(columns)["drift_dph"],
                                  batch)
    s = fogdrift.StreamingCompensator(m, 1.0)
    for i in range(50):
        drift, _, flags = s.update(columns["time_s"][i], columns["gyro_dph"][i],
                                   columns["temp_fog_degc"][i], columns["temp_acc1_degc"][i],
                                   columns["temp_acc2_degc"][i],
                                   temp_case_degc=columns["temp_case_degc"][i])
        assert drift == batch[i] and flags == 0
    with pytest.raises(ValueError, match="option temp_case_degc: the model reads this"):
        s.update(60.0, 0.0, 20.0, 20.0, 20.0)
    with pytest.raises(TypeError, match="temp_case_degc must be a number, not str"):
        s.update(60.0, 0.0, 20.0, 20.0, 20.0, temp_case_degc="warm")
    with pytest.raises(TypeError, match="unexpected keyword argument 'temp_top_degc'"):
        s.update(60.0, 0.0, 20.0, 20.0, 20.0, temp_case_degc=20.0, temp_top_degc=20.0)
    with pytest.raises(ValueError, match="missing column temp_case_degc"):
        fogdrift.StreamingCompensator(m, 1.0).run(
            {k: v for k, v in columns.items() if k != "temp_case_degc"})
    with pytest.raises(ValueError, match="option thermometers: 'Case' is not a thermometer"):
        fogdrift.train(cal, thermometers=["fog", "Case"])
