#!/usr/bin/env python3
"""Writes the scikit-learn reference the Gaussian-process tests compare fogdrift against.

Run by the build (tests/CMakeLists.txt) with Debian's python3-sklearn; the output goes to the
build folder, not the repository. Each case is a smooth function of a few standardised inputs
plus noise, and scikit-learn's GaussianProcessRegressor with the kernel fogdrift uses,
ConstantKernel(s2) * RBF(length_scale) + WhiteKernel(noise), alpha = 0 and normalize_y = False:
  fixed     at given hyperparameters: the log marginal likelihood and its gradient with respect to
            the log hyperparameters, and the predictive mean and standard deviation at test rows;
  optimised from fogdrift's start (s2 = 1, length scales sqrt(d), noise 0.1) within fogdrift's
            bounds, with scikit-learn's L-BFGS-B and no restarts: the hyperparameters and the log
            marginal likelihood it reaches.

Usage: make_gp_reference.py OUTPUT.json
"""
import json
import sys
import warnings

import numpy as np
from sklearn.gaussian_process import GaussianProcessRegressor
from sklearn.gaussian_process.kernels import RBF, ConstantKernel, WhiteKernel


def kernel(s2, length, noise, fixed):
    if fixed:
        return (ConstantKernel(s2, "fixed") * RBF(length, "fixed") + WhiteKernel(noise, "fixed"))
    return (ConstantKernel(s2, (1e-3, 1e3)) * RBF(length, (1e-2, 1e3)) +
            WhiteKernel(noise, (1e-6, 10.0)))


def case(rng, name, n, d, n_test, ard):
    x = rng.normal(size=(n, d))
    y = np.sin(1.3 * x[:, 0]) + 0.5 * x[:, -1] ** 2 / (1 + x[:, -1] ** 2) + 0.05 * rng.normal(size=n)
    if d > 2:
        y += 0.3 * np.cos(x[:, 1] * x[:, 2])
    y = (y - y.mean()) / y.std()
    x_test = rng.normal(size=(n_test, d)) * 1.5
    length = list(np.linspace(0.7, 2.1, d)) if ard else [1.3]
    s2, noise = 0.8, 0.02
    fixed = GaussianProcessRegressor(kernel(s2, length if ard else length[0], noise, True),
                                     alpha=0.0, optimizer=None).fit(x, y)
    # The gradient needs free hyperparameters: the same kernel with bounds, not optimised.
    free = kernel(s2, length if ard else length[0], noise, False)
    gp_free = GaussianProcessRegressor(free, alpha=0.0, optimizer=None).fit(x, y)
    value, gradient = gp_free.log_marginal_likelihood(gp_free.kernel_.theta, eval_gradient=True)
    mean, std = fixed.predict(x_test, return_std=True)
    start = [np.sqrt(d)] * d if ard else np.sqrt(d)
    opt = GaussianProcessRegressor(kernel(1.0, start, 0.1, False), alpha=0.0,
                                   n_restarts_optimizer=0).fit(x, y)
    theta = np.exp(opt.kernel_.theta)
    return {
        "name": name, "ard": ard, "rows": n, "cols": d,
        "x": x.ravel().tolist(), "y": y.tolist(), "x_test": x_test.ravel().tolist(),
        "signal_variance": s2, "length_scale": length if ard else length * d,
        "noise_variance": noise,
        "log_likelihood": float(value), "gradient": gradient.tolist(),
        "mean": mean.tolist(), "std_with_noise": std.tolist(),
        "optimised": {"signal_variance": float(theta[0]),
                      "length_scale": theta[1:-1].tolist() if ard else [float(theta[1])] * d,
                      "noise_variance": float(theta[-1]),
                      "log_likelihood": float(opt.log_marginal_likelihood_value_)},
    }


def main():
    warnings.simplefilter("ignore")  # a bound reached is part of the reference
    rng = np.random.default_rng(20261126)
    cases = [case(rng, "ard, 3 inputs", 80, 3, 25, True),
             case(rng, "ard, 5 inputs", 150, 5, 40, True),
             case(rng, "one length scale, 2 inputs", 60, 2, 20, False)]
    with open(sys.argv[1], "w") as f:
        json.dump({"cases": cases}, f)


if __name__ == "__main__":
    main()
