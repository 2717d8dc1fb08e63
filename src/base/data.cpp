// Regression data's subsets and checks (data.hpp).
#include "fogdrift/base/data.hpp"

#include <fmt/format.h>

#include <cassert>
#include <cmath>
#include <string>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

Data Data::subset(std::span<const std::size_t> indices) const {
  Data out;
  out.rows = indices.size();
  out.cols = cols;
  out.x.reserve(indices.size() * cols);
  out.y.reserve(indices.size());
  if (!weight.empty()) out.weight.reserve(indices.size());
  for (std::size_t i : indices) {
    assert(i < rows);
    out.x.insert(out.x.end(), row(i), row(i) + cols);
    out.y.push_back(y[i]);
    if (!weight.empty()) out.weight.push_back(weight[i]);
  }
  return out;
}

void validate(const Data& data, std::string_view what) {
  const std::string file(what);
  if (data.rows == 0) throw InputError(file, 0, 0, "no samples");
  if (data.x.size() != data.rows * data.cols || data.y.size() != data.rows)
    throw InputError(file, 0, 0,
                     fmt::format("{} samples of {} features need {} values and {} targets, "
                                 "got {} and {}",
                                 data.rows, data.cols, data.rows * data.cols, data.rows,
                                 data.x.size(), data.y.size()));
  if (!data.weight.empty() && data.weight.size() != data.rows)
    throw InputError(file, 0, 0,
                     fmt::format("{} samples need {} weights (or none), got {}", data.rows,
                                 data.rows, data.weight.size()));
  for (std::size_t i = 0; i < data.rows; ++i) {
    if (!data.weight.empty() && !(std::isfinite(data.weight[i]) && data.weight[i] > 0))
      throw InputError(file, i + 1, 0,
                       fmt::format("sample {}: weight is {}; weights must be finite and > 0 "
                                   "(leave out samples of weight 0)",
                                   i + 1, data.weight[i]));
    if (!std::isfinite(data.y[i]))
      throw InputError(file, i + 1, 0, fmt::format("sample {}: target is {}", i + 1, data.y[i]));
    for (std::size_t k = 0; k < data.cols; ++k) {
      const double v = data.x[i * data.cols + k];
      if (!std::isfinite(v))
        throw InputError(file, i + 1, 0,
                         fmt::format("sample {}: feature {} is {}", i + 1, k + 1, v));
    }
  }
}

}  // namespace fogdrift
