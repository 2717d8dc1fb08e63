"""fogdrift.train's progress (docs/python.md, "Progress"): a tqdm bar when tqdm is installed, a
line every 5 s otherwise, nothing when asked, a callable as given; and Ctrl-C stops the search
whatever is shown."""
import os
import signal
import threading
import time

import pytest

import fogdrift
from fogdrift import _progress


@pytest.fixture(scope="module")
def campaign(tmp_path_factory):
    d = tmp_path_factory.mktemp("progress") / "cal"
    fogdrift.simulate("calibration", out=d, seed=3, temps_degc=[-20, 10, 40], repetitions=2)
    return d


def test_lines_report_the_search_and_its_end(campaign, capsys):
    fogdrift.train(campaign, population=5, iterations=3, progress="lines")
    err = capsys.readouterr().err
    assert "fogdrift.train: iteration 3/3, best RMSE " in err and " evaluations, " in err


def test_a_bar_when_tqdm_is_installed(campaign, capsys):
    pytest.importorskip("tqdm")
    fogdrift.train(campaign, population=5, iterations=3, progress=True)
    err = capsys.readouterr().err
    assert "fogdrift.train" in err and "3/3" in err


def test_auto_is_a_bar_with_tqdm_and_lines_only_on_a_terminal_without(monkeypatch):
    monkeypatch.setattr(_progress, "_has_tqdm", lambda: False)
    monkeypatch.setattr("sys.stderr.isatty", lambda: False, raising=False)
    assert _progress.reporter("auto", "fogdrift.train") is None
    assert isinstance(_progress.reporter(True, "fogdrift.train"), _progress._Lines)
    monkeypatch.setattr(_progress, "_has_tqdm", lambda: True)
    pytest.importorskip("tqdm")
    assert isinstance(_progress.reporter("auto", "fogdrift.train"), _progress._Bar)


def test_false_shows_nothing_and_a_callable_is_called(campaign, capsys):
    seen = []
    fogdrift.train(campaign, population=5, iterations=3, progress=False)
    fogdrift.train(campaign, population=5, iterations=3, progress=lambda r: seen.append(r))
    assert capsys.readouterr().err == ""
    assert [r["iteration"] for r in seen] == [0, 1, 2, 3]  # 0: the first population
    with pytest.raises(TypeError, match=r"train\(\): progress must be 'auto', True, False, "
                                        r"'lines', None or a callable, not str \('bar'\)"):
        fogdrift.train(campaign, progress="bar")


def test_ctrl_c_stops_a_search_with_the_default_progress(campaign):
    # SIGINT as the terminal sends it, to this process, a second into a search of minutes: the
    # whole budget (no stall rule) and every distinct candidate fitted, so that no default that
    # shortens a search can end it before the signal arrives.
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            fogdrift.train(campaign, population=100, iterations=500, stall_iterations=0,
                           candidate_resolution=0)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 1.0 + 1.5
