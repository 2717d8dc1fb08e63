#include "fogdrift/signal/resample.hpp"

#include <cmath>
#include <string>

#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {

std::size_t block_samples(const BlockAverageOptions& options, double dt_s) {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) {
    throw OptionError("dt_s", "the sample interval must be positive and finite");
  }
  if (!(options.block_s > 0) || !std::isfinite(options.block_s)) {
    throw OptionError("block_s", "the averaging block must be positive and finite, got " +
                                     std::to_string(options.block_s));
  }
  const double ratio = options.block_s / dt_s;
  const double whole = std::round(ratio);
  if (whole < 1 || std::fabs(ratio - whole) > 1e-6 * whole) {
    throw OptionError("block_s", std::to_string(options.block_s) +
                                     " s is not a whole multiple of the sample interval (" +
                                     std::to_string(dt_s) + " s)");
  }
  return static_cast<std::size_t>(whole);
}

std::vector<double> block_average(std::span<const double> x, std::size_t block) {
  if (block == 0) throw OptionError("block_s", "a block must hold at least one sample");
  std::vector<double> out(x.size() / block);
  for (std::size_t b = 0; b < out.size(); ++b) {
    double sum = 0.0;
    for (std::size_t j = 0; j < block; ++j) sum += x[b * block + j];
    out[b] = sum / static_cast<double>(block);
  }
  return out;
}

}  // namespace fogdrift::signal
