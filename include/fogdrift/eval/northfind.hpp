// Four-position north-finding (docs/method.md §3, paper §4.2).
//
// The FOG and two accelerometers are read at turntable angles 0°, 90°, 180° and 270°. With
// θ the table angle, the platform frame P (x_p: FOG axis at 0°, z_p: table axis) gives
//   ω(θ) = ω_x cos θ − ω_y sin θ + b,     a_x(θ) = u_x cos θ − u_y sin θ + b_x,
//   a_y(θ) = −u_x sin θ − u_y cos θ + b_y,
// so opposite-position differences cancel every constant bias:
//   ω_x = (ω₀ − ω₁₈₀)/2,  ω_y = −(ω₉₀ − ω₂₇₀)/2,  u_x, u_y from both accelerometers,
//   u_z = √(1 − u_x² − u_y²)  (u: local up in P).
// North n in P follows from ω = Ω_N·n + Ω_U·u with n ⟂ u, and the azimuth of the FOG axis at 0°
// is atan2(x_p·e, x_p·n), e = n × u. This is the exact geometry: tilt enters through u, not
// through a small-angle formula. Earth's rate magnitude cancels in the ratio.
#pragma once

#include <array>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift::eval {

/// Mean readings at the four positions, in the order 0°, 90°, 180°, 270°.
struct FourPositionReadings {
  std::array<double, 4> gyro_dph{};
  std::array<double, 4> accel_x_g{};
  std::array<double, 4> accel_y_g{};
  std::array<double, 4> start_s{};  ///< first sample used at each position, s since power-on
  std::array<double, 4> end_s{};    ///< last sample used
  std::array<int, 4> samples{};     ///< samples averaged
};

struct FourPositionSolution {
  double azimuth_deg = 0;          ///< azimuth of the FOG axis at table 0°, degrees in [0, 360)
  double pitch_deg = 0;            ///< tilt of x_p from horizontal (up positive), degrees
  double roll_deg = 0;             ///< tilt of y_p from horizontal, degrees
  double horizontal_rate_dph = 0;  ///< |(ω_x, ω_y) − Ω_U(u_x, u_y)|, expected Ω·cos(latitude)
};

/// Solves one finding. `latitude_deg` gives the vertical Earth rate removed from the readings.
FourPositionSolution solve_four_position(const FourPositionReadings& readings, double latitude_deg);

struct SegmentationOptions {
  double tolerance_deg = 0.05;  ///< a sample is at a position when table_deg is this close to it
  double settle_s = 2.0;        ///< samples this soon after arriving at a position are skipped
  double min_dwell_s = 10.0;    ///< positions held for less time than this are not used
};

/// Throws OptionError naming the field ("tolerance_deg", …) unless 0 < tolerance_deg < 45 (a
/// sample is then near one position at most), settle_s ≥ 0 and min_dwell_s > 0, all finite.
void validate(const SegmentationOptions& options);

/// Splits a recording into findings: runs of samples held at 0°, 90°, 180°, 270° in that order
/// (rotation segments and the settle time excluded). `gyro_dph`, when given, replaces the
/// recording's gyro column (e.g. a compensated output of the same length). Throws InputError if
/// table_deg, accel_x_g or accel_y_g is missing.
std::vector<FourPositionReadings> segment_findings(const Recording& recording,
                                                   const SegmentationOptions& options = {},
                                                   const std::vector<double>* gyro_dph = nullptr);

/// a − b wrapped into (−180, 180], degrees.
double angle_difference_deg(double a_deg, double b_deg);

/// Root mean square of `errors_deg`.
double rms(const std::vector<double>& errors_deg);

}  // namespace fogdrift::eval
