# pytest's configuration for the Python package's tests (tests/python, run by CTest with
# PYTHONPATH pointing at BUILD/python).
import os
import subprocess

import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20261123)


def startup_like(rng, n, d=6):
    """Smooth, correlated, noisy regression data of the kind fogdrift's features make."""
    t = rng.uniform(0, 1, size=(n, 1))
    X = np.hstack([np.exp(-t * rng.uniform(1, 5)) + 0.05 * rng.normal(size=(n, 1))
                   for _ in range(d)])
    X = (X - X.mean(axis=0)) / X.std(axis=0)
    y = np.sin(2 * X[:, 0]) + 0.5 * X[:, 1] * X[:, 2] + 0.1 * rng.normal(size=n)
    return X, y


@pytest.fixture(scope="session")
def cli():
    """Runs the fogdrift command line (FOGDRIFT_CLI, set by CTest) and returns its standard
    output; a non-zero exit fails the test with the command's error."""
    path = os.environ.get("FOGDRIFT_CLI", "build/apps/fogdrift/fogdrift")

    def run(*args):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        if done.returncode != 0:
            pytest.fail(f"fogdrift {' '.join(map(str, args))}: {done.stderr}")
        return done.stdout

    return run
