#include "fogdrift/eval/northfind.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fogdrift/base/earth.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/sim/turntable.hpp"

namespace fogdrift::eval {
namespace {

// Exact readings of a noiseless instrument, computed from the simulator's platform geometry.
FourPositionReadings exact_readings(const sim::Platform& p, double latitude_deg, double gyro_bias,
                                    double bias_x, double bias_y) {
  const sim::Vec3 earth = sim::earth_rate_enu_dph(latitude_deg);
  FourPositionReadings r;
  for (int k = 0; k < 4; ++k) {
    r.gyro_dph[k] = sim::dot(earth, p.body_x(90.0 * k)) + gyro_bias;
    r.accel_x_g[k] = p.body_x(90.0 * k)[2] + bias_x;
    r.accel_y_g[k] = p.body_y(90.0 * k)[2] + bias_y;
  }
  return r;
}

TEST(FourPosition, ExactGeometryRecoversTheTrueAzimuthWithTiltAndBiases) {
  Rng rng(2024);
  for (int trial = 0; trial < 2000; ++trial) {
    const double azimuth = rng.uniform(0, 360);
    const double latitude = rng.uniform(-70, 70);
    const sim::Platform p(azimuth, rng.uniform(-2, 2), rng.uniform(-2, 2));
    const auto readings = exact_readings(p, latitude, rng.uniform(-5, 5), rng.uniform(-0.01, 0.01),
                                         rng.uniform(-0.01, 0.01));
    const auto s = solve_four_position(readings, latitude);
    ASSERT_NEAR(angle_difference_deg(s.azimuth_deg, p.true_azimuth_deg()), 0.0, 1e-9)
        << "trial " << trial << " azimuth " << azimuth << " latitude " << latitude;
    ASSERT_NEAR(s.horizontal_rate_dph, kEarthRateDph * std::cos(latitude * std::numbers::pi / 180),
                1e-9);
  }
}

TEST(FourPosition, IgnoringTiltWouldBeWrong) {
  // Guard against a solver that drops the vertical Earth-rate term: with a 0.5° tilt that costs
  // Ω_U·sin(0.5°)/Ω_N, about 0.29° of azimuth at 30° latitude.
  const sim::Platform p(90.0, 0.0, 0.5);
  FourPositionReadings r = exact_readings(p, 30.0, 0, 0, 0);
  const double good = solve_four_position(r, 30.0).azimuth_deg;
  r.accel_x_g.fill(0.0);
  r.accel_y_g.fill(0.0);
  const double level_assumed = solve_four_position(r, 30.0).azimuth_deg;
  EXPECT_NEAR(good, p.true_azimuth_deg(), 1e-9);
  EXPECT_GT(std::abs(angle_difference_deg(level_assumed, p.true_azimuth_deg())), 0.2);
}

TEST(FourPosition, RateErrorToAzimuthErrorMatchesTheSmallAngleRule) {
  // docs/method.md: δψ ≈ δω / (Ω_ie cos φ); here a rate error δ on the 0° reading alone, at ψ =
  // 90°, changes ω0 − ω180 by δ, so δψ = δ / (2 Ω_N) rad.
  const double latitude = 30.0, delta = 0.0027;
  const sim::Platform p(90.0, 0, 0);
  FourPositionReadings r = exact_readings(p, latitude, 0, 0, 0);
  r.gyro_dph[0] += delta;
  const double err = angle_difference_deg(solve_four_position(r, latitude).azimuth_deg, 90.0);
  const double omega_n = kEarthRateDph * std::cos(latitude * std::numbers::pi / 180);
  EXPECT_NEAR(std::abs(err), delta / (2 * omega_n) * 180 / std::numbers::pi, 1e-6);
}

TEST(Segmentation, FindsOrderedFourPositionRunsAndSkipsRotations) {
  Recording rec;
  const double schedule[] = {0,   0,   0,   0,   0,   0,   45,  90,  90,  90,
                             90,  90,  90,  135, 180, 180, 180, 180, 180, 180,
                             225, 270, 270, 270, 270, 270, 270, 315, 0,   0};
  for (int i = 0; i < 30; ++i) {
    rec.time_s.push_back(10.0 * (i + 1));
    rec.gyro_dph.push_back(schedule[i] == 45 || schedule[i] == 135 ? 99.0 : schedule[i] / 90.0);
    rec.temp_fog_degc.push_back(0);
    rec.temp_acc1_degc.push_back(0);
    rec.temp_acc2_degc.push_back(0);
  }
  rec.table_deg = std::vector<double>(std::begin(schedule), std::end(schedule));
  rec.accel_x_g = std::vector<double>(30, 0.0);
  rec.accel_y_g = std::vector<double>(30, 0.0);
  SegmentationOptions o;
  o.settle_s = 5;
  o.min_dwell_s = 20;
  const auto findings = segment_findings(rec, o);
  ASSERT_EQ(findings.size(), 1u);  // the trailing 0° run has no partners
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(findings[0].gyro_dph[k], k);  // rotation samples (99) excluded
    EXPECT_EQ(findings[0].samples[k], 5);          // first sample of each run skipped
  }
  rec.table_deg.reset();
  EXPECT_THROW(segment_findings(rec, o), InputError);
}

TEST(AngleDifference, WrapsIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(angle_difference_deg(359.0, 1.0), -2.0);
  EXPECT_DOUBLE_EQ(angle_difference_deg(1.0, 359.0), 2.0);
  EXPECT_DOUBLE_EQ(angle_difference_deg(180.0, 0.0), 180.0);
  EXPECT_DOUBLE_EQ(angle_difference_deg(0.0, 180.0), 180.0);
}

}  // namespace
}  // namespace fogdrift::eval
