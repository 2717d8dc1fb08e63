// The Allan deviation estimator against closed forms and synthetic noise of known parameters.
#include "fogdrift/eval/allan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/sim/fog_error_model.hpp"

namespace fogdrift::eval {
namespace {

// A rate ramp ω = R·t has σ(τ) = R·τ/√2 exactly for the overlapping estimator (the second
// difference of a quadratic angle is constant).
TEST(AllanDeviation, RampIsExact) {
  const double r = 0.37, dt = 0.5;
  std::vector<double> rate(1000);
  for (std::size_t i = 0; i < rate.size(); ++i) rate[i] = 5 + r * dt * static_cast<double>(i);
  const AllanDeviation c = allan_deviation(rate, dt);
  ASSERT_EQ(c.m.size(), 9u);  // 1 … 256 (2·512 > 1000)
  for (std::size_t i = 0; i < c.m.size(); ++i) {
    EXPECT_EQ(c.tau_s[i], dt * static_cast<double>(c.m[i]));
    EXPECT_NEAR(c.adev[i], r * c.tau_s[i] / std::sqrt(2.0), 1e-11 * r * c.tau_s[i]);
  }
  // A constant rate has no Allan deviation.
  const AllanDeviation flat = allan_deviation(std::vector<double>(100, 12.5), 1.0);
  for (double v : flat.adev) EXPECT_LT(v, 1e-12);
}

// White rate noise of known ARW: σ(τ) = N/√τ, and noise_terms reads N back.
TEST(AllanDeviation, RecoversAngleRandomWalk) {
  const double arw = 0.01, dt = 1.0;                  // °/√h, s
  const double sigma = arw * std::sqrt(3600.0 / dt);  // rate noise per sample, °/h
  Rng rng(11);
  std::vector<double> rate(200000);
  for (double& v : rate) v = 3.0 + sigma * rng.normal();
  const AllanDeviation c = allan_deviation(rate, dt);
  for (std::size_t i = 0; i < c.m.size() && c.m[i] <= 1000; ++i)
    EXPECT_NEAR(c.adev[i], arw / std::sqrt(c.tau_s[i] / 3600.0),
                0.05 * arw / std::sqrt(c.tau_s[i] / 3600.0))
        << "tau " << c.tau_s[i];
  EXPECT_NEAR(noise_terms(c).arw_deg_per_rt_h, arw, 0.03 * arw);
}

// A random walk of the rate with known RRW: σ(τ) = K·√(τ/3).
TEST(AllanDeviation, RecoversRateRandomWalk) {
  const double rrw = 0.05, dt = 1.0;  // °/h/√h
  const double step = rrw * std::sqrt(dt / 3600.0);
  Rng rng(12);
  std::vector<double> rate(400000);
  double w = 0;
  for (double& v : rate) v = (w += step * rng.normal());
  const AllanDeviation c = allan_deviation(rate, dt, 10);
  // Where clusters are still many (τ ≤ 2,000 s), the curve follows the law closely.
  for (std::size_t i = 0; i < c.m.size() && c.tau_s[i] <= 2000; ++i)
    if (c.tau_s[i] >= 100) {
      EXPECT_NEAR(c.adev[i], rrw * std::sqrt(c.tau_s[i] / 3600.0 / 3),
                  0.15 * rrw * std::sqrt(c.tau_s[i] / 3600.0 / 3))
          << "tau " << c.tau_s[i];
    }
  EXPECT_NEAR(noise_terms(c).rrw_dph_per_rt_h, rrw, 0.35 * rrw);
}

// The read-off on a curve of known N, B and K (the IEEE 952 sum of the three terms).
TEST(NoiseTerms, ReadsTheDatasheetTermsOffACurve) {
  const double n = 0.002, b = 0.01, k = 0.0005;
  AllanDeviation c;
  for (double tau = 0.01; tau < 1e10; tau *= 1.25) {
    const double th = tau / 3600.0;
    c.tau_s.push_back(tau);
    c.adev.push_back(std::sqrt(n * n / th + 0.664 * 0.664 * b * b + k * k * th / 3));
    c.m.push_back(static_cast<std::size_t>(tau));
  }
  const NoiseTerms t = noise_terms(c);
  EXPECT_NEAR(t.arw_deg_per_rt_h, n, 0.05 * n);
  EXPECT_NEAR(t.bias_instability_dph, b, 0.03 * b);
  EXPECT_NEAR(t.rrw_dph_per_rt_h, k, 0.05 * k);
  EXPECT_LT(t.arw_tau_s, t.bias_instability_tau_s);
  EXPECT_LT(t.bias_instability_tau_s, t.rrw_tau_s);
}

TEST(AllanDeviation, RejectsImpossibleInput) {
  EXPECT_THROW(allan_deviation(std::vector<double>{1, 2, 3}, 1.0), OptionError);
  EXPECT_THROW(allan_deviation(std::vector<double>(10, 1.0), 0.0), OptionError);
}

}  // namespace
}  // namespace fogdrift::eval

namespace fogdrift::eval {
namespace {

// The simulator's FOG noise (sim/fog_error_model.hpp), quantiser off, read back as datasheet
// terms: its angle random walk to 10 %, and a bias instability of the Gauss–Markov σ's order.
TEST(AllanDeviation, ReadsTheSimulatorsNoiseTerms) {
  sim::FogParams fog;
  fog.quantization_arcsec = 0;
  sim::FogNoise noise(fog, 5);
  std::vector<double> rate(200000);
  for (double& v : rate) v = noise.angle_increment_arcsec(1.0);  // ″ per s = °/h
  const NoiseTerms t = noise_terms(allan_deviation(rate, 1.0, 10));
  EXPECT_NEAR(t.arw_deg_per_rt_h, fog.arw_deg_per_rth, 0.10 * fog.arw_deg_per_rth);
  EXPECT_GT(t.bias_instability_dph, 0.3 * fog.bias_gm_sigma_dph);
  EXPECT_LT(t.bias_instability_dph, 1.5 * fog.bias_gm_sigma_dph);
  EXPECT_GT(t.bias_instability_tau_s, fog.bias_gm_tau_s / 3);
}

}  // namespace
}  // namespace fogdrift::eval
