#include "fogdrift/eval/metrics.hpp"

#include <cmath>
#include <stdexcept>

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
  double abs_sum = 0, sq_sum = 0;
  for (std::size_t i = 0; i < m.rows; ++i) {
    residual[i] = target_dph[i] - predicted_dph[i];
    abs_sum += std::abs(residual[i]);
    sq_sum += residual[i] * residual[i];
  }
  const double n = static_cast<double>(m.rows);
  m.mae_dph = abs_sum / n;
  m.rmse_dph = std::sqrt(sq_sum / n);
  m.std_before_dph = sample_std(target_dph);
  m.std_after_dph = sample_std(residual);
  return m;
}

CompensationMetrics pool(std::span<const CompensationMetrics> recordings) {
  CompensationMetrics p;
  double abs_sum = 0, sq_sum = 0, before = 0, after = 0;
  std::size_t k = 0;
  for (const auto& r : recordings) {
    if (r.rows == 0) continue;
    ++k;
    p.rows += r.rows;
    abs_sum += r.mae_dph * static_cast<double>(r.rows);
    sq_sum += r.rmse_dph * r.rmse_dph * static_cast<double>(r.rows);
    before += r.std_before_dph * r.std_before_dph;
    after += r.std_after_dph * r.std_after_dph;
  }
  if (p.rows == 0) return p;
  p.mae_dph = abs_sum / static_cast<double>(p.rows);
  p.rmse_dph = std::sqrt(sq_sum / static_cast<double>(p.rows));
  p.std_before_dph = std::sqrt(before / static_cast<double>(k));
  p.std_after_dph = std::sqrt(after / static_cast<double>(k));
  return p;
}

std::vector<CompensationMetrics> metrics_per_recording(const Dataset& data,
                                                       std::span<const double> predicted_dph) {
  if (predicted_dph.size() != data.rows)
    throw std::invalid_argument("metrics_per_recording: one prediction per row is needed");
  std::vector<std::vector<double>> y(data.groups.size()), p(data.groups.size());
  for (std::size_t i = 0; i < data.rows; ++i) {
    y[data.group[i]].push_back(data.y[i]);
    p[data.group[i]].push_back(predicted_dph[i]);
  }
  std::vector<CompensationMetrics> out;
  for (std::size_t g = 0; g < data.groups.size(); ++g)
    out.push_back(compensation_metrics(y[g], p[g]));
  return out;
}

}  // namespace fogdrift::eval
