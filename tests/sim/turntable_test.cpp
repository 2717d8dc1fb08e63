#include "fogdrift/sim/turntable.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fogdrift/base/earth.hpp"

namespace fogdrift::sim {
namespace {

void expect_vec(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}

TEST(Platform, LevelAxesFollowTheTable) {
  const Platform p(0.0, 0.0, 0.0);
  expect_vec(p.body_x(0), {0, 1, 0});   // north
  expect_vec(p.body_x(90), {1, 0, 0});  // east: the table turns clockwise seen from above
  expect_vec(p.body_y(0), {1, 0, 0});   // accelerometer 2 is 90° clockwise of the FOG axis
  expect_vec(p.body_x(180), {0, -1, 0});
  EXPECT_NEAR(p.true_azimuth_deg(), 0.0, 1e-12);
  EXPECT_NEAR(Platform(123.4, 0, 0).true_azimuth_deg(), 123.4, 1e-12);
}

TEST(Platform, TiltKeepsAxesOrthonormalAndTiltsThem) {
  const Platform p(40.0, 0.5, -0.3);
  for (double th : {0.0, 37.0, 90.0, 211.0}) {
    const Vec3 x = p.body_x(th), y = p.body_y(th), n = p.normal();
    EXPECT_NEAR(dot(x, x), 1.0, 1e-14);
    EXPECT_NEAR(dot(y, y), 1.0, 1e-14);
    EXPECT_NEAR(dot(x, y), 0.0, 1e-14);
    EXPECT_NEAR(dot(x, n), 0.0, 1e-14);
  }
  EXPECT_NEAR(std::acos(p.normal()[2]) * 180 / std::numbers::pi, std::hypot(0.5, 0.3), 1e-9);
  EXPECT_NEAR(p.true_azimuth_deg(), 40.0, 0.01);
}

TEST(EarthRate, ProjectionOnALevelAxis) {
  const Vec3 w = earth_rate_enu_dph(30.0);
  EXPECT_NEAR(w[1], kEarthRateDph * std::sqrt(3.0) / 2, 1e-12);
  EXPECT_NEAR(w[2], kEarthRateDph / 2, 1e-12);
  EXPECT_NEAR(dot(w, Platform(60.0, 0, 0).body_x(0)), kEarthRateDph * std::sqrt(3.0) / 4, 1e-12);
}

TEST(TurntableSchedule, HoldsRotatesAndHolds) {
  TurntableSchedule s(0.0);
  s.add_move(90.0, 90.0, 10.0);
  s.add_move(180.0, 90.0, 10.0);
  EXPECT_EQ(s.angle_deg(0.0), 0.0);
  EXPECT_FALSE(s.moving(89.9));
  EXPECT_TRUE(s.moving(94.5));
  EXPECT_NEAR(s.angle_deg(94.5), 45.0, 1e-12);
  EXPECT_EQ(s.angle_deg(99.0), 90.0);
  EXPECT_EQ(s.angle_deg(500.0), 180.0);
}

}  // namespace
}  // namespace fogdrift::sim
