// Turntable and platform geometry, and the Earth-rate projection on the FOG axis
// (docs/simulator.md §3).
//
// Frames: ENU navigation frame (x east, y north, z up). The platform frame P has x_p = the FOG
// sensitive axis at table angle 0, z_p = the table's rotation axis (the platform normal, tilted
// slightly from up), y_p = z_p × x_p. At table angle θ (clockwise seen from above) the body axes
// are x_b = cos θ·x_p − sin θ·y_p (FOG and accelerometer 1) and y_b = −sin θ·x_p − cos θ·y_p
// (accelerometer 2, 90° clockwise from x_b). Angles are radians inside, degrees in names `_deg`.
#pragma once

#include <array>
#include <vector>

namespace fogdrift::sim {

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b);
Vec3 cross(const Vec3& a, const Vec3& b);

/// Earth's rotation vector in ENU at `latitude_deg`, °/h.
Vec3 earth_rate_enu_dph(double latitude_deg);

class Platform {
 public:
  /// `azimuth_deg`: heading of x_p before tilting, clockwise from north. The tilt is a small
  /// rotation about the east axis (`tilt_east_deg`) and the north axis (`tilt_north_deg`).
  Platform(double azimuth_deg, double tilt_east_deg, double tilt_north_deg);

  Vec3 body_x(double table_deg) const;  ///< FOG / accelerometer 1 axis in ENU
  Vec3 body_y(double table_deg) const;  ///< accelerometer 2 axis in ENU
  Vec3 normal() const { return z_; }

  /// Azimuth of the horizontal projection of x_p (the FOG axis at table 0), degrees in [0, 360).
  double true_azimuth_deg() const;

 private:
  Vec3 x_{}, y_{}, z_{};
};

/// A table that holds or rotates between positions at a constant rate.
class TurntableSchedule {
 public:
  /// Holds `angle_deg` from t = 0 on.
  explicit TurntableSchedule(double angle_deg = 0.0) : start_angle_deg_(angle_deg) {}

  /// Rotates by `delta_deg` starting at `start_s` at `rate_deg_per_s`; moves must be added in time
  /// order and must not overlap.
  void add_move(double start_s, double delta_deg, double rate_deg_per_s);

  /// Table angle at time `t_s`, degrees, unwrapped (may exceed 360).
  double angle_deg(double t_s) const;
  /// True while the table is rotating at `t_s`.
  bool moving(double t_s) const;

 private:
  struct Move {
    double start_s, end_s, from_deg, delta_deg;
  };
  double start_angle_deg_;
  std::vector<Move> moves_;
};

}  // namespace fogdrift::sim
