// Dense regression data every regressor is fitted on: `rows` samples of `cols` features,
// row-major, one target each, and optionally a weight each. The ε-SVR engine calls it svr::Data
// (svr/kernel.hpp); the other regressors take it from here.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace fogdrift {

struct Data {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<double> x;  ///< rows × cols, row-major
  std::vector<double> y;  ///< rows
  /// rows weights > 0, or empty for all 1: sample i's variables are bounded by C·weight_i
  /// instead of C, as LIBSVM's and scikit-learn's sample weights (a weight of 2 acts as the
  /// sample twice). Samples of weight 0 are to be left out of the data.
  std::vector<double> weight;

  const double* row(std::size_t i) const { return x.data() + i * cols; }
  double weight_of(std::size_t i) const { return weight.empty() ? 1.0 : weight[i]; }
  /// The rows whose indices are given, in that order (for cross-validation folds).
  Data subset(std::span<const std::size_t> indices) const;
};

/// Checks shapes, that every value is finite and every weight > 0, and that there is at least
/// one sample. Throws InputError whose file is `what` and whose line is the 1-based sample.
void validate(const Data& data, std::string_view what = "training data");

}  // namespace fogdrift
