// Regression data sets for the SVR engine's tests and benchmarks, generated from a seed.
#pragma once

#include <cmath>
#include <cstddef>

#include "fogdrift/base/random.hpp"
#include "fogdrift/svr/kernel.hpp"

namespace fogdrift::svr::testing {

/// Scales every feature and the target to zero mean and unit standard deviation (constant
/// columns are only centred).
inline void standardise(Data& d) {
  auto fix = [&](auto get, std::size_t count) {
    double mean = 0, sq = 0;
    for (std::size_t i = 0; i < count; ++i) mean += get(i);
    mean /= static_cast<double>(count);
    for (std::size_t i = 0; i < count; ++i) sq += (get(i) - mean) * (get(i) - mean);
    const double sd = std::sqrt(sq / static_cast<double>(count));
    for (std::size_t i = 0; i < count; ++i) get(i) = sd > 0 ? (get(i) - mean) / sd : get(i) - mean;
  };
  for (std::size_t k = 0; k < d.cols; ++k)
    fix([&](std::size_t i) -> double& { return d.x[i * d.cols + k]; }, d.rows);
  fix([&](std::size_t i) -> double& { return d.y[i]; }, d.rows);
}

/// Start-up-like features of the fogdrift problem: recordings of 180 ten-second samples from
/// random initial temperatures; three thermometers warming with different time constants, their
/// rates and the three gradients (9 features); a drift that depends non-linearly on them, plus
/// noise. Standardised. Structured and correlated like the real features, which makes the
/// kernel matrix nearly low-rank and the SMO iterations many, as on real calibration data.
inline Data startup_like(std::size_t n, std::uint64_t seed = 1) {
  Rng rng(seed);
  Data d;
  d.rows = n;
  d.cols = 9;
  d.x.reserve(n * 9);
  d.y.reserve(n);
  while (d.y.size() < n) {
    const double t0 = rng.uniform(-40, 60);
    double tau[3], amp[3];
    const double tau0[3] = {300, 600, 900}, amp0[3] = {12, 9, 6};
    for (int k = 0; k < 3; ++k) {
      tau[k] = tau0[k] * rng.uniform(0.8, 1.2);
      amp[k] = amp0[k] * rng.uniform(0.8, 1.2);
    }
    for (int s = 0; s < 180 && d.y.size() < n; ++s) {
      const double t = 10.0 * s;
      double temp[3], rate[3];
      for (int k = 0; k < 3; ++k) {
        const double e = std::exp(-t / tau[k]);
        temp[k] = t0 + amp[k] * (1 - e) + rng.normal(0, 0.02);
        rate[k] = amp[k] / tau[k] * e + rng.normal(0, 1e-4);
      }
      const double grad[3] = {temp[0] - temp[1], temp[1] - temp[2], temp[0] - temp[2]};
      for (double v : temp) d.x.push_back(v);
      for (double v : rate) d.x.push_back(v);
      for (double v : grad) d.x.push_back(v);
      d.y.push_back(0.02 * std::tanh((temp[0] - 10) / 30) + 3.0 * rate[0] * (1 + 0.01 * temp[0]) -
                    0.002 * grad[1] + rng.normal(0, 0.003));
    }
  }
  standardise(d);
  return d;
}

/// y = sin(x₁) + ½cos(2x₂) + … on uniform features, with optional Gaussian noise.
inline Data smooth(std::size_t n, std::size_t dims, double noise_sd, std::uint64_t seed) {
  Rng rng(seed);
  Data d;
  d.rows = n;
  d.cols = dims;
  for (std::size_t i = 0; i < n; ++i) {
    double y = 0;
    for (std::size_t k = 0; k < dims; ++k) {
      const double v = rng.uniform(-2, 2);
      d.x.push_back(v);
      y +=
          (k % 2 == 0 ? std::sin((k + 1) * v) : std::cos((k + 1) * v)) / static_cast<double>(k + 1);
    }
    d.y.push_back(y + (noise_sd > 0 ? rng.normal(0, noise_sd) : 0.0));
  }
  return d;
}

}  // namespace fogdrift::svr::testing
