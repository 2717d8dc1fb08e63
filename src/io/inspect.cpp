#include "fogdrift/io/inspect.hpp"

#include <algorithm>
#include <cmath>

#include "fogdrift/io/regrid.hpp"

namespace fogdrift {

ColumnRange column_range(const std::string& name, const std::vector<double>& v) {
  ColumnRange r;
  r.name = name;
  if (v.empty()) return r;
  r.min = *std::min_element(v.begin(), v.end());
  r.max = *std::max_element(v.begin(), v.end());
  // Two-pass mean and variance: exact enough for the long, offset-heavy series loggers write.
  double sum = 0.0;
  for (double x : v) sum += x;
  r.mean = sum / static_cast<double>(v.size());
  if (v.size() > 1) {
    double ss = 0.0;
    for (double x : v) ss += (x - r.mean) * (x - r.mean);
    r.std = std::sqrt(ss / static_cast<double>(v.size() - 1));
  }
  return r;
}

RecordingSummary summarize(const Recording& rec) {
  RecordingSummary s;
  s.samples = rec.size();
  if (rec.size() == 0) return s;
  s.start_s = rec.time_s.front();
  s.end_s = rec.time_s.back();
  s.duration_s = s.end_s - s.start_s;
  std::vector<double> steps;
  steps.reserve(rec.size());
  for (std::size_t i = 1; i < rec.size(); ++i) steps.push_back(rec.time_s[i] - rec.time_s[i - 1]);
  if (!steps.empty()) {
    s.sample_interval_s = median_time_step_s(rec.time_s);
    s.sample_rate_hz = s.sample_interval_s > 0 ? 1.0 / s.sample_interval_s : 0.0;
    std::vector<double> starts = {rec.time_s.front()};  // of the runs the gaps separate
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (steps[i] > 1.5 * s.sample_interval_s) {
        ++s.gaps;
        starts.push_back(rec.time_s[i + 1]);
      }
      s.longest_gap_s = std::max(s.longest_gap_s, steps[i]);
    }
    if (s.gaps >= 2) {
      // The median start-to-start period, as the median step of the burst starts.
      const double period = median_time_step_s(starts);
      bool regular = true;
      // A lost burst makes one period twice as long: a whole number of periods still counts.
      for (std::size_t k = 1; k < starts.size(); ++k) {
        const double p = starts[k] - starts[k - 1];
        const double n = std::round(p / period);
        regular = regular && n >= 1 && std::abs(p - n * period) <= 0.1 * period;
      }
      if (regular) s.bursts = starts.size(), s.burst_period_s = period;
    }
  }
  s.uniformly_sampled = is_uniformly_sampled(rec);
  s.missing = missing_required(rec);
  s.partial = rec.partial && (!s.missing.empty() || (!rec.time_s.empty() && rec.time_s[0] < 0));
  // A log to join may lack the gyro and the FOG thermometer (recording.hpp).
  if (!rec.gyro_dph.empty()) s.columns.push_back(column_range("gyro_dph", rec.gyro_dph));
  if (!rec.temp_fog_degc.empty())
    s.columns.push_back(column_range("temp_fog_degc", rec.temp_fog_degc));
  if (!rec.temp_acc1_degc.empty())
    s.columns.push_back(column_range("temp_acc1_degc", rec.temp_acc1_degc));
  if (!rec.temp_acc2_degc.empty())
    s.columns.push_back(column_range("temp_acc2_degc", rec.temp_acc2_degc));
  if (rec.accel_x_g) s.columns.push_back(column_range("accel_x_g", *rec.accel_x_g));
  if (rec.accel_y_g) s.columns.push_back(column_range("accel_y_g", *rec.accel_y_g));
  if (rec.table_deg) s.columns.push_back(column_range("table_deg", *rec.table_deg));
  if (rec.chamber_degc) s.columns.push_back(column_range("chamber_degc", *rec.chamber_degc));
  for (const auto& e : rec.extra) {
    s.extra_columns.push_back(e.name);
    if (const auto values = numbers_of(e); values && !values->empty())
      s.columns.push_back(column_range(e.name, *values));
  }
  return s;
}

}  // namespace fogdrift
