#include "fogdrift/sim/fog_error_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fogdrift::sim {
namespace {

FogParams quiet() {
  FogParams f;
  f.arw_deg_per_rth = 0;
  f.bias_gm_sigma_dph = 0;
  f.rrw_deg_per_h_rth = 0;
  f.quantization_arcsec = 0;
  return f;
}

double stdev(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  double s = 0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size() - 1));
}

TEST(ThermalDrift, IeeeTermsInClosedForm) {
  FogParams f;
  f.reference_temp_degc = 25;
  f.static_d1_dph_per_k = 0.01;
  f.static_d2_dph_per_k2 = 0.001;
  f.static_d3_dph_per_k3 = 0.0001;
  f.rate_r0_dph_per_kps = -2;
  f.rate_r1_per_k = 0.1;
  f.shupe_s0_dph_per_kps = -5;
  f.shupe_s1_per_k = 0.01;
  f.shupe_s2_per_k2 = 0.001;
  const DriftTerms d = thermal_drift(f, 35.0, 0.01, 0.002);  // ΔT = 10
  EXPECT_NEAR(d.static_dph, 0.1 + 0.1 + 0.1, 1e-15);
  EXPECT_NEAR(d.rate_dph, -2 * 2 * 0.01, 1e-15);
  EXPECT_NEAR(d.shupe_dph, -5 * (1 + 0.1 + 0.1) * 0.002, 1e-15);
  EXPECT_NEAR(d.total_dph(), 0.3 - 0.04 - 0.012, 1e-15);
  EXPECT_EQ(thermal_drift(f, 25.0, 0, 0).total_dph(), 0.0);
}

// Angle random walk N: the mean rate over τ seconds has σ = 60·N/√τ °/h.
TEST(FogNoise, AngleRandomWalkMatchesItsDefinition) {
  FogParams f = quiet();
  f.arw_deg_per_rth = 0.002;
  FogNoise noise(f, 9);
  const double dt = 0.1, tau = 1.0;
  std::vector<double> rates;
  for (int k = 0; k < 50000; ++k) {
    double angle = 0;
    for (int j = 0; j < 10; ++j) angle += noise.angle_increment_arcsec(dt);
    rates.push_back(angle / tau);
  }
  EXPECT_NEAR(stdev(rates), 60 * 0.002 / std::sqrt(tau), 0.02 * 0.12);
}

TEST(FogNoise, GaussMarkovBiasIsStationaryWithItsSigma) {
  FogParams f = quiet();
  f.bias_gm_sigma_dph = 0.01;
  f.bias_gm_tau_s = 10.0;
  std::vector<double> samples;
  for (int run = 0; run < 4000; ++run) {
    FogNoise noise(f, 1000 + run);
    double angle = 0;
    for (int j = 0; j < 50; ++j) angle = noise.angle_increment_arcsec(0.1);
    samples.push_back(angle / 0.1);  // the bias rate after 5 s (a fraction of τ): still σ
  }
  EXPECT_NEAR(stdev(samples), 0.01, 0.0006);
}

TEST(FogNoise, RateRandomWalkGrowsWithTheSquareRootOfTime) {
  FogParams f = quiet();
  f.rrw_deg_per_h_rth = 0.06;  // after 1 h the rate has σ = 0.06 °/h
  std::vector<double> end_rates;
  for (int run = 0; run < 2000; ++run) {
    FogNoise noise(f, 5000 + run);
    double last = 0;
    for (int j = 0; j < 360; ++j) last = noise.angle_increment_arcsec(10.0) / 10.0;
    end_rates.push_back(last);
  }
  EXPECT_NEAR(stdev(end_rates), 0.06, 0.004);
}

TEST(FogNoise, QuantiserCarriesTheResidual) {
  FogParams f = quiet();
  f.quantization_arcsec = 0.05;
  FogNoise noise(f, 1);
  double in = 0, out = 0;
  for (int k = 0; k < 1000; ++k) {
    const double a = 0.0123 * k - 3.0;
    in += a;
    const double q = noise.quantize_arcsec(a);
    EXPECT_NEAR(std::remainder(q, 0.05), 0.0, 1e-9);
    out += q;
    ASSERT_GE(in - out, -1e-9);
    ASSERT_LT(in - out, 0.05 + 1e-9);
  }
}

}  // namespace
}  // namespace fogdrift::sim
