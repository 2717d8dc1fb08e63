#include "fogdrift/eval/metrics.hpp"

#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace fogdrift::eval {
namespace {

double sample_std(std::span<const double> x) {
  if (x.size() < 2) return 0;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return std::sqrt(ss / static_cast<double>(x.size() - 1));
}

}  // namespace

CompensationMetrics compensation_metrics(std::span<const double> target_dph,
                                         std::span<const double> predicted_dph) {
  if (target_dph.size() != predicted_dph.size())
    throw std::invalid_argument("compensation_metrics: target and prediction differ in length");
  CompensationMetrics m;
  m.rows = target_dph.size();
  if (m.rows == 0) return m;
  std::vector<double> residual(m.rows);
  double abs_sum = 0, sq_sum = 0, abs_before = 0, sum_before = 0, sum_after = 0;
  for (std::size_t i = 0; i < m.rows; ++i) {
    residual[i] = target_dph[i] - predicted_dph[i];
    abs_sum += std::abs(residual[i]);
    sq_sum += residual[i] * residual[i];
    abs_before += std::abs(target_dph[i]);
    sum_before += target_dph[i];
    sum_after += residual[i];
  }
  const double n = static_cast<double>(m.rows);
  m.mae_dph = abs_sum / n;
  m.mae_before_dph = abs_before / n;
  m.mean_before_dph = sum_before / n;
  m.mean_after_dph = sum_after / n;
  m.rmse_dph = std::sqrt(sq_sum / n);
  m.std_before_dph = sample_std(target_dph);
  m.std_after_dph = sample_std(residual);
  m.pooled_std_before_dph = m.std_before_dph;
  m.pooled_std_after_dph = m.std_after_dph;
  return m;
}

CompensationMetrics pool(std::span<const CompensationMetrics> recordings) {
  CompensationMetrics p;
  double abs_sum = 0, sq_sum = 0, before = 0, after = 0, abs_before = 0;
  double sum_before = 0, sum_after = 0;
  std::size_t k = 0;
  for (const auto& r : recordings) {
    if (r.rows == 0) continue;
    ++k;
    p.rows += r.rows;
    abs_sum += r.mae_dph * static_cast<double>(r.rows);
    abs_before += r.mae_before_dph * static_cast<double>(r.rows);
    sum_before += r.mean_before_dph * static_cast<double>(r.rows);
    sum_after += r.mean_after_dph * static_cast<double>(r.rows);
    sq_sum += r.rmse_dph * r.rmse_dph * static_cast<double>(r.rows);
    before += r.std_before_dph * r.std_before_dph;
    after += r.std_after_dph * r.std_after_dph;
  }
  if (p.rows == 0) return p;
  p.mae_dph = abs_sum / static_cast<double>(p.rows);
  p.mae_before_dph = abs_before / static_cast<double>(p.rows);
  p.mean_before_dph = sum_before / static_cast<double>(p.rows);
  p.mean_after_dph = sum_after / static_cast<double>(p.rows);
  // Pooled variance: within-recording sums of squares plus the offsets of the recording means.
  if (p.rows > 1) {
    double ss_before = 0, ss_after = 0;
    for (const auto& r : recordings) {
      if (r.rows == 0) continue;
      const double n = static_cast<double>(r.rows);
      ss_before +=
          (n - 1) * r.pooled_std_before_dph * r.pooled_std_before_dph +
          n * (r.mean_before_dph - p.mean_before_dph) * (r.mean_before_dph - p.mean_before_dph);
      ss_after += (n - 1) * r.pooled_std_after_dph * r.pooled_std_after_dph +
                  n * (r.mean_after_dph - p.mean_after_dph) * (r.mean_after_dph - p.mean_after_dph);
    }
    p.pooled_std_before_dph = std::sqrt(ss_before / static_cast<double>(p.rows - 1));
    p.pooled_std_after_dph = std::sqrt(ss_after / static_cast<double>(p.rows - 1));
  }
  p.rmse_dph = std::sqrt(sq_sum / static_cast<double>(p.rows));
  p.std_before_dph = std::sqrt(before / static_cast<double>(k));
  p.std_after_dph = std::sqrt(after / static_cast<double>(k));
  // The north-finding metrics pool over the recordings they apply to (n/a is NaN): n/a when
  // they apply to none.
  for (double CompensationMetrics::*v :
       {&CompensationMetrics::startup_before_dph, &CompensationMetrics::startup_after_dph,
        &CompensationMetrics::opposite_before_dph, &CompensationMetrics::opposite_after_dph}) {
    double sum = 0;
    std::size_t count = 0;
    for (const auto& r : recordings)
      if (r.rows > 0 && std::isfinite(r.*v)) sum += r.*v * r.*v, ++count;
    p.*v = count ? std::sqrt(sum / static_cast<double>(count)) : kNotApplicable;
  }
  return p;
}

std::pair<double, double> finding_metrics(std::span<const double> time_s, std::span<const double> r,
                                          const FindingWindows& w) {
  const std::size_t n = r.size();
  if (n < 2 || time_s.size() != n) return {kNotApplicable, kNotApplicable};
  double mean = 0;
  for (double v : r) mean += v;
  mean /= static_cast<double>(n);
  // Start-up residual: the rows within startup_s of the first, when the first is within
  // startup_s of power-on (time 0); a recording that starts later has no start-up to show.
  double startup = kNotApplicable;
  if (time_s[0] < w.startup_s) {
    double ss = 0;
    std::size_t m = 0;
    for (std::size_t i = 0; i < n && time_s[i] - time_s[0] < w.startup_s; ++i, ++m)
      ss += (r[i] - mean) * (r[i] - mean);
    startup = std::sqrt(ss / static_cast<double>(m));
  }
  // Opposite difference over windows of P rows, 2P apart, by prefix sums: n/a when a window
  // holds no row (rows more than 2 positions apart) or the recording is shorter than 3 windows.
  const double dt = (time_s[n - 1] - time_s[0]) / static_cast<double>(n - 1);
  const auto p = static_cast<std::size_t>(std::lround(w.position_s / dt));
  if (p == 0 || 3 * p > n) return {startup, kNotApplicable};
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + r[i];
  double dd = 0;
  const std::size_t starts = n - 3 * p + 1;
  for (std::size_t t = 0; t < starts; ++t) {
    const double a = (prefix[t + p] - prefix[t]) / static_cast<double>(p);
    const double b = (prefix[t + 3 * p] - prefix[t + 2 * p]) / static_cast<double>(p);
    dd += (a - b) * (a - b);
  }
  return {startup, std::sqrt(dd / static_cast<double>(starts))};
}

std::vector<CompensationMetrics> metrics_per_recording(const Dataset& data,
                                                       std::span<const double> predicted_dph,
                                                       const FindingWindows& windows) {
  if (predicted_dph.size() != data.rows)
    throw std::invalid_argument("metrics_per_recording: one prediction per row is needed");
  std::vector<std::vector<double>> y(data.groups.size()), p(data.groups.size()),
      t(data.groups.size());
  const bool timed = data.time_s.size() == data.rows;  // a hand-made dataset may have no times
  for (std::size_t i = 0; i < data.rows; ++i) {
    y[data.group[i]].push_back(data.y[i]);
    p[data.group[i]].push_back(predicted_dph[i]);
    if (timed) t[data.group[i]].push_back(data.time_s[i]);
  }
  std::vector<CompensationMetrics> out;
  for (std::size_t g = 0; g < data.groups.size(); ++g) {
    CompensationMetrics m = compensation_metrics(y[g], p[g]);
    std::vector<double> after(y[g].size());
    for (std::size_t i = 0; i < after.size(); ++i) after[i] = y[g][i] - p[g][i];
    std::tie(m.startup_before_dph, m.opposite_before_dph) = finding_metrics(t[g], y[g], windows);
    std::tie(m.startup_after_dph, m.opposite_after_dph) = finding_metrics(t[g], after, windows);
    out.push_back(m);
  }
  return out;
}

}  // namespace fogdrift::eval
