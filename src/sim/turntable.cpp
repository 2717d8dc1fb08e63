#include "fogdrift/sim/turntable.hpp"

#include <cassert>
#include <cmath>
#include <numbers>

#include "fogdrift/base/earth.hpp"

namespace fogdrift::sim {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Rotation of v about the unit axis k by angle a (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& k, double a) {
  const Vec3 kxv = cross(k, v);
  const double kv = dot(k, v);
  Vec3 r;
  for (int i = 0; i < 3; ++i) {
    r[i] = v[i] * std::cos(a) + kxv[i] * std::sin(a) + k[i] * kv * (1.0 - std::cos(a));
  }
  return r;
}

}  // namespace

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec3 earth_rate_enu_dph(double latitude_deg) {
  const double phi = latitude_deg * kDegToRad;
  return {0.0, fogdrift::kEarthRateDph * std::cos(phi), fogdrift::kEarthRateDph * std::sin(phi)};
}

Platform::Platform(double azimuth_deg, double tilt_east_deg, double tilt_north_deg) {
  const double psi = azimuth_deg * kDegToRad;
  x_ = {std::sin(psi), std::cos(psi), 0.0};
  z_ = {0.0, 0.0, 1.0};
  // Tilt: rotation vector (east, north, 0); small angles, applied exactly.
  const Vec3 w = {tilt_east_deg * kDegToRad, tilt_north_deg * kDegToRad, 0.0};
  const double angle = std::sqrt(dot(w, w));
  if (angle > 0.0) {
    const Vec3 axis = {w[0] / angle, w[1] / angle, 0.0};
    x_ = rotate(x_, axis, angle);
    z_ = rotate(z_, axis, angle);
  }
  y_ = cross(z_, x_);
}

Vec3 Platform::body_x(double table_deg) const {
  const double th = table_deg * kDegToRad;
  const double c = std::cos(th), s = std::sin(th);
  return {c * x_[0] - s * y_[0], c * x_[1] - s * y_[1], c * x_[2] - s * y_[2]};
}

Vec3 Platform::body_y(double table_deg) const {
  const double th = table_deg * kDegToRad;
  const double c = std::cos(th), s = std::sin(th);
  return {-s * x_[0] - c * y_[0], -s * x_[1] - c * y_[1], -s * x_[2] - c * y_[2]};
}

double Platform::true_azimuth_deg() const {
  double az = std::atan2(x_[0], x_[1]) / kDegToRad;
  if (az < 0.0) az += 360.0;
  if (az >= 360.0) az -= 360.0;
  return az;
}

void TurntableSchedule::add_move(double start_s, double delta_deg, double rate_deg_per_s) {
  assert(rate_deg_per_s > 0.0);
  const double from =
      moves_.empty() ? start_angle_deg_ : moves_.back().from_deg + moves_.back().delta_deg;
  assert(moves_.empty() || start_s >= moves_.back().end_s);
  moves_.push_back({start_s, start_s + std::abs(delta_deg) / rate_deg_per_s, from, delta_deg});
}

double TurntableSchedule::angle_deg(double t) const {
  double angle = start_angle_deg_;
  for (const Move& m : moves_) {
    if (t < m.start_s) break;
    if (t >= m.end_s) {
      angle = m.from_deg + m.delta_deg;
    } else {
      return m.from_deg + m.delta_deg * (t - m.start_s) / (m.end_s - m.start_s);
    }
  }
  return angle;
}

bool TurntableSchedule::moving(double t) const {
  for (const Move& m : moves_) {
    if (t >= m.start_s && t < m.end_s) return true;
  }
  return false;
}

}  // namespace fogdrift::sim
