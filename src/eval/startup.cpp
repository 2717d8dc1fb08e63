#include "fogdrift/eval/startup.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "fogdrift/io/inspect.hpp"

namespace fogdrift::eval {

std::vector<double> moving_average(const std::vector<double>& v, std::size_t window) {
  const std::size_t n = v.size();
  const std::size_t half = window / 2;
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + v[i];
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t h = std::min({half, i, n - 1 - i});
    out[i] = (prefix[i + h + 1] - prefix[i - h]) / static_cast<double>(2 * h + 1);
  }
  return out;
}

StartupStats startup_stats(const std::vector<double>& time_s, const std::vector<double>& values,
                           std::size_t window) {
  StartupStats s;
  if (values.empty()) return s;
  const std::vector<double> smooth = moving_average(values, window);
  const ColumnRange r = column_range("", smooth);
  s.std_dph = r.std;
  s.peak_to_peak_dph = r.max - r.min;
  const auto it = std::min_element(smooth.begin(), smooth.end());
  s.min_time_s = time_s[static_cast<std::size_t>(it - smooth.begin())];
  s.start_dph = smooth.front() - r.mean;
  s.end_dph = smooth.back() - r.mean;
  return s;
}

namespace {

std::vector<double> errors_of(const Recording& rec, const std::vector<double>* gyro_dph,
                              double latitude_deg, double true_azimuth_deg,
                              const SegmentationOptions& options) {
  std::vector<double> errors;
  for (const auto& finding : segment_findings(rec, options, gyro_dph)) {
    const auto solution = solve_four_position(finding, latitude_deg);
    errors.push_back(angle_difference_deg(solution.azimuth_deg, true_azimuth_deg));
  }
  return errors;
}

}  // namespace

std::vector<double> northfind_errors_deg(const Recording& rec, double latitude_deg,
                                         double true_azimuth_deg,
                                         const SegmentationOptions& options) {
  return errors_of(rec, nullptr, latitude_deg, true_azimuth_deg, options);
}

std::vector<double> northfind_errors_deg(const Recording& rec, const std::vector<double>& drift_dph,
                                         double latitude_deg, double true_azimuth_deg,
                                         const SegmentationOptions& options) {
  if (drift_dph.size() != rec.gyro_dph.size())
    throw std::invalid_argument("northfind_errors_deg: " + std::to_string(drift_dph.size()) +
                                " drift values for " + std::to_string(rec.gyro_dph.size()) +
                                " samples");
  std::vector<double> gyro(rec.gyro_dph.size());
  for (std::size_t i = 0; i < gyro.size(); ++i) gyro[i] = rec.gyro_dph[i] - drift_dph[i];
  return errors_of(rec, &gyro, latitude_deg, true_azimuth_deg, options);
}

}  // namespace fogdrift::eval
