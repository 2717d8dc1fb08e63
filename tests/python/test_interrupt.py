# Interrupts in long calls (docs/reliability.md, "Python interrupts"): an alarm whose handler
# raises stops fogdrift.SVR.fit and fogdrift.train within a fraction of a second, the handler's
# exception reaches the caller, and the next call runs as if nothing had happened.
import signal
import time

import numpy as np
import pytest

import fogdrift


class Alarm(Exception):
    pass


def _raise(signum, frame):
    raise Alarm()


@pytest.fixture
def alarm():
    previous = signal.signal(signal.SIGALRM, _raise)

    def arm(seconds):
        signal.setitimer(signal.ITIMER_REAL, seconds)

    yield arm
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, previous)


def slow_data(n=8000):
    rng = np.random.default_rng(7)
    X = rng.uniform(-3, 3, size=(n, 3))
    y = np.sin(X[:, 0]) * np.cos(X[:, 1]) + 0.3 * X[:, 2] + 0.05 * rng.normal(size=n)
    return X, y


def test_an_alarm_stops_a_long_svr_fit(alarm):
    X, y = slow_data()
    model = fogdrift.SVR(C=100.0, epsilon=0.001, tol=1e-6)
    alarm(0.3)
    start = time.monotonic()
    with pytest.raises(Alarm):
        model.fit(X, y)
    stopped = time.monotonic() - start
    assert stopped < 0.3 + 1.0, f"stopped {stopped:.2f} s after the call began"
    # Nothing is left pending: a short fit afterwards runs whole.
    small = fogdrift.SVR(C=1.0).fit(X[:300], y[:300])
    assert np.isfinite(small.predict(X[:5])).all()


def test_an_alarm_stops_training(alarm, tmp_path, cli):
    cli("simulate", "calibration", "--out", tmp_path / "cal", "--seed", "2", "--temps",
        "-20,10,40", "--repetitions", "3")
    alarm(0.3)
    start = time.monotonic()
    with pytest.raises(Alarm):
        fogdrift.train(str(tmp_path / "cal"), method="ssa-svr", population=40, iterations=200)
    assert time.monotonic() - start < 0.3 + 1.0
