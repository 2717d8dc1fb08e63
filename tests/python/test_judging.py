"""fogdrift.evaluate judges a model beside its baselines and draws its figures, as `fogdrift
evaluate --json --figures` does (docs/compensation.md, "Judging a model", "Figures"), on the
fixture of tests/data/unit_logs: an x gyro that follows its thermometer and a z gyro with no
temperature signal."""
import json
import pathlib
import warnings

import pytest

import fogdrift

UNIT = pathlib.Path(__file__).resolve().parents[1] / "data" / "unit_logs" / "unit.csv"


@pytest.fixture(scope="module")
def trained(tmp_path_factory, cli):
    d = tmp_path_factory.mktemp("judging")
    cli("campaign", d / "camp", UNIT, "--cut-window-s", "3600", "--input-rate-dph", "0",
        "--test", "5", "-q")
    cli("train", d / "camp", "-o", d / "m.json", "--targets", "gyro_dph,gyro_z_dph")
    return d


def test_the_axis_without_temperature_signal_is_flagged_as_it_harms(trained, cli):
    # The z gyro has no temperature signal: its model removes the bias, as the line does, and
    # leaves a few millionths of a °/h more variation than the recording mean, which is a harm
    # and is said with the digits that show it.
    z = fogdrift.Model.load(trained / "m.json", target="gyro_z_dph")
    with pytest.warns(UserWarning, match=r"the model harms .*unit_05.csv: adds variation: STD "
                                         r"0\.04948 °/h after against 0\.04947 before"):
        got = fogdrift.evaluate(z, trained / "camp")
    assert got["verdict"] == "harms"
    assert len(got["harmed"]) == 1 and got["no_better"] == []
    b = got["baselines"]
    assert b["line_input"] == "T_fog_degc"
    assert b["model_rmse_dph"] < 0.1 * b["raw_rmse_dph"]  # it removes the bias, as the line does
    assert b["model_rmse_dph"] > 0.95 * b["line_rmse_dph"]
    # The same dict the command line prints for that axis.
    axes = json.loads(cli("evaluate", trained / "m.json", trained / "camp", "--json"))["axes"]
    assert axes[1]["target"] == "gyro_z_dph"
    assert axes[1]["baselines"] == got["baselines"]
    assert axes[1]["verdict"] == got["verdict"]


def test_the_axis_with_signal_beats_them_and_draws_its_figures(trained, tmp_path):
    x = fogdrift.Model.load(trained / "m.json", target="gyro_dph")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no harm, nothing "no better": no warning
        got = fogdrift.evaluate(x, trained / "camp", figures=tmp_path / "figs")
    assert got["verdict"] == "beats its baselines"
    assert got["baselines"]["model_rmse_dph"] < 0.5 * got["baselines"]["line_rmse_dph"]
    assert got["figures"] == ["recordings", "residual_vs_T", "region"]
    for name in got["figures"]:
        drawn = json.loads((tmp_path / "figs" / f"{name}.json").read_text())
        assert drawn["name"] == name and drawn["panels"]
    # The held-out hour is the warmest: its temperatures lie beyond the training rows'.
    rec = got["recordings"][0]
    t = next(e for e in rec["extrapolation"] if e["input"] == "T_fog_degc")
    assert t["share_outside"] > 0.5 and t["farthest_outside"] > 0.5
    # The folder is written whole or not at all: an existing one is refused, untouched.
    with pytest.raises(Exception, match="figs"):
        fogdrift.evaluate(x, trained / "camp", figures=tmp_path / "figs")
