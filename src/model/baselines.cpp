// The training rows' input ranges and line in T (baselines.hpp).
#include "fogdrift/model/baselines.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

bool is_temperature(const std::string& name) {
  return name.size() > 7 && name.starts_with("T_") && name.ends_with("_degc");
}

}  // namespace

std::string temperature_input_of(std::span<const std::string> feature_names) {
  for (const std::string& n : feature_names)
    if (n == "T_fog_degc") return n;
  for (const std::string& n : feature_names)
    if (is_temperature(n)) return n;
  return "";
}

TrainingBaselines fit_training_baselines(const Dataset& data) {
  TrainingBaselines b;
  const std::size_t d = data.cols();
  if (data.rows == 0) return b;
  b.input_min.assign(d, std::numeric_limits<double>::infinity());
  b.input_max.assign(d, -std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < data.rows; ++i)
    for (std::size_t k = 0; k < d; ++k) {
      b.input_min[k] = std::min(b.input_min[k], data.x[i * d + k]);
      b.input_max[k] = std::max(b.input_max[k], data.x[i * d + k]);
    }
  const std::string input = temperature_input_of(data.feature_names);
  if (input.empty()) return b;
  const auto k = static_cast<std::size_t>(
      std::find(data.feature_names.begin(), data.feature_names.end(), input) -
      data.feature_names.begin());
  // Least squares about the means, for accuracy at temperatures far from 0 °C.
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < data.rows; ++i) {
    mx += data.x[i * d + k];
    my += data.y[i];
  }
  const double n = static_cast<double>(data.rows);
  mx /= n;
  my /= n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < data.rows; ++i) {
    const double dx = data.x[i * d + k] - mx;
    sxy += dx * (data.y[i] - my);
    sxx += dx * dx;
  }
  if (!(sxx > 0)) return b;
  const double slope = sxy / sxx;
  b.line = BaselineLine{data.feature_names[k], my - slope * mx, slope};
  return b;
}

std::vector<double> line_drift(const BaselineLine& line, const Dataset& data,
                               const std::string& source) {
  const auto it = std::find(data.feature_names.begin(), data.feature_names.end(), line.input);
  if (it == data.feature_names.end())
    throw InputError(source, 0, 0,
                     fmt::format("baselines.line.input: '{}' is not one of the model's inputs ({})",
                                 line.input, fmt::join(data.feature_names, ", ")));
  const auto k = static_cast<std::size_t>(it - data.feature_names.begin());
  std::vector<double> out(data.rows);
  for (std::size_t i = 0; i < data.rows; ++i)
    out[i] = line.intercept + line.slope * data.x[i * data.cols() + k];
  return out;
}

std::vector<InputExtrapolation> extrapolation(const TrainingBaselines& baselines,
                                              const Dataset& data,
                                              std::span<const std::size_t> rows) {
  std::vector<InputExtrapolation> out;
  if (!baselines.has_ranges() || rows.empty()) return out;
  const std::size_t d = data.cols();
  for (std::size_t k = 0; k < d && k < baselines.input_min.size(); ++k) {
    InputExtrapolation e;
    e.input = data.feature_names[k];
    e.train_min = baselines.input_min[k];
    e.train_max = baselines.input_max[k];
    e.min = std::numeric_limits<double>::infinity();
    e.max = -e.min;
    std::size_t outside = 0;
    for (std::size_t i : rows) {
      const double v = data.x[i * d + k];
      e.min = std::min(e.min, v);
      e.max = std::max(e.max, v);
      const double beyond = std::max(e.train_min - v, v - e.train_max);
      if (beyond > 0) {
        ++outside;
        e.farthest_outside = std::max(e.farthest_outside, beyond);
      }
    }
    e.share_outside = static_cast<double>(outside) / static_cast<double>(rows.size());
    out.push_back(std::move(e));
  }
  return out;
}

double share_outside_any(const TrainingBaselines& baselines, const Dataset& data,
                         std::span<const std::size_t> rows) {
  if (!baselines.has_ranges() || rows.empty()) return 0.0;
  const std::size_t d = data.cols();
  std::size_t outside = 0;
  for (std::size_t i : rows) {
    for (std::size_t k = 0; k < d && k < baselines.input_min.size(); ++k) {
      const double v = data.x[i * d + k];
      if (v < baselines.input_min[k] || v > baselines.input_max[k]) {
        ++outside;
        break;
      }
    }
  }
  return static_cast<double>(outside) / static_cast<double>(rows.size());
}

}  // namespace fogdrift
