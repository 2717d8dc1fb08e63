#include "fogdrift/eval/northfind.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fogdrift/base/earth.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift::eval {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

}  // namespace

FourPositionSolution solve_four_position(const FourPositionReadings& r, double latitude_deg) {
  const auto& w = r.gyro_dph;
  const auto& ax = r.accel_x_g;
  const auto& ay = r.accel_y_g;
  const double phi = latitude_deg / kRadToDeg;
  const double omega_up = kEarthRateDph * std::sin(phi);

  // Up vector in P from both accelerometers (each gives u_x and u_y once).
  const double ux = 0.5 * ((ax[0] - ax[2]) / 2.0 - (ay[1] - ay[3]) / 2.0);
  const double uy = 0.5 * (-(ax[1] - ax[3]) / 2.0 - (ay[0] - ay[2]) / 2.0);
  const double uz = std::sqrt(std::max(0.0, 1.0 - ux * ux - uy * uy));

  const double wx = (w[0] - w[2]) / 2.0;
  const double wy = -(w[1] - w[3]) / 2.0;
  // Horizontal Earth rate along P's axes: remove the vertical component's projection.
  const double hx = wx - omega_up * ux;
  const double hy = wy - omega_up * uy;
  const double hz = -(hx * ux + hy * uy) / uz;  // n ⟂ u
  // x_p·n ∝ hx; x_p·e = (n × u)_x ∝ hy·uz − hz·uy.
  double azimuth = std::atan2(hy * uz - hz * uy, hx) * kRadToDeg;
  if (azimuth < 0.0) azimuth += 360.0;
  if (azimuth >= 360.0) azimuth -= 360.0;

  FourPositionSolution s;
  s.azimuth_deg = azimuth;
  s.pitch_deg = std::asin(std::clamp(ux, -1.0, 1.0)) * kRadToDeg;
  s.roll_deg = std::asin(std::clamp(uy, -1.0, 1.0)) * kRadToDeg;
  s.horizontal_rate_dph = std::sqrt(hx * hx + hy * hy + hz * hz);
  return s;
}

void validate(const SegmentationOptions& o) {
  if (!(o.tolerance_deg > 0 && o.tolerance_deg < 45))
    throw OptionError("tolerance_deg",
                      fmt::format("{} ° is outside (0, 45): a sample must be near one position "
                                  "at most",
                                  o.tolerance_deg));
  if (!(o.settle_s >= 0) || !std::isfinite(o.settle_s))
    throw OptionError("settle_s", fmt::format("{} s must be finite and ≥ 0", o.settle_s));
  if (!(o.min_dwell_s > 0) || !std::isfinite(o.min_dwell_s))
    throw OptionError("min_dwell_s", fmt::format("{} s must be finite and > 0", o.min_dwell_s));
}

std::vector<FourPositionReadings> segment_findings(const Recording& rec,
                                                   const SegmentationOptions& o,
                                                   const std::vector<double>* gyro_dph) {
  validate(o);
  const std::string file = rec.source.empty() ? "<recording>" : rec.source;
  for (const char* name : {"table_deg", "accel_x_g", "accel_y_g"}) {
    if (!rec.has_column(name)) {
      throw InputError(file, 1, 0,
                       fmt::format("north-finding needs column '{}' (turntable angle and both "
                                   "accelerometers)",
                                   name));
    }
  }
  const std::vector<double>& gyro = gyro_dph ? *gyro_dph : rec.gyro_dph;
  if (gyro.size() != rec.size()) {
    throw InputError(file, 0, 0,
                     "the gyro series to segment has another length than the recording");
  }
  const auto& table = *rec.table_deg;

  // Runs of consecutive samples at the same nominal position.
  struct Run {
    int position;
    std::size_t first, last;  // inclusive sample indices
  };
  std::vector<Run> runs;
  for (std::size_t i = 0; i < rec.size(); ++i) {
    int position = -1;
    for (int p = 0; p < 4; ++p) {
      if (std::abs(angle_difference_deg(table[i], 90.0 * p)) <= o.tolerance_deg) position = p;
    }
    if (position < 0) continue;
    if (!runs.empty() && runs.back().position == position && runs.back().last + 1 == i) {
      runs.back().last = i;
    } else {
      runs.push_back({position, i, i});
    }
  }

  std::vector<FourPositionReadings> findings;
  FourPositionReadings current;
  int expected = 0;
  for (const Run& run : runs) {
    // Skip the first sample (its interval may include the end of the rotation) and the settle time.
    std::size_t first = run.first + 1;
    while (first <= run.last && rec.time_s[first] < rec.time_s[run.first] + o.settle_s) ++first;
    const bool long_enough =
        first <= run.last && rec.time_s[run.last] - rec.time_s[first] >= o.min_dwell_s;
    if (!long_enough || run.position != expected) {
      expected = 0;
      if (!long_enough || run.position != 0) continue;
    }
    double g = 0, x = 0, y = 0;
    for (std::size_t i = first; i <= run.last; ++i) {
      g += gyro[i];
      x += (*rec.accel_x_g)[i];
      y += (*rec.accel_y_g)[i];
    }
    const double n = static_cast<double>(run.last - first + 1);
    current.gyro_dph[expected] = g / n;
    current.accel_x_g[expected] = x / n;
    current.accel_y_g[expected] = y / n;
    current.start_s[expected] = rec.time_s[first];
    current.end_s[expected] = rec.time_s[run.last];
    current.samples[expected] = static_cast<int>(n);
    if (++expected == 4) {
      findings.push_back(current);
      expected = 0;
    }
  }
  return findings;
}

double angle_difference_deg(double a, double b) {
  double d = std::fmod(a - b, 360.0);
  if (d <= -180.0) d += 360.0;
  if (d > 180.0) d -= 360.0;
  return d;
}

double rms(const std::vector<double>& errors) {
  if (errors.empty()) return 0.0;
  double s = 0.0;
  for (double e : errors) s += e * e;
  return std::sqrt(s / static_cast<double>(errors.size()));
}

}  // namespace fogdrift::eval
