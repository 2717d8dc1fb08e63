#include "fogdrift/signal/hampel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

/// Median of `v` (reordered in place); the mean of the two middle values for an even size.
double median_of(std::vector<double>& v) {
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  const double upper = v[mid];
  if (v.size() % 2 == 1) return upper;
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid));
  return 0.5 * (lower + upper);
}

}  // namespace

HampelResult hampel(std::span<const double> x, const HampelOptions& options) {
  if (options.half_window < 1)
    throw OptionError("half_window", "the Hampel window's half-width must be at least 1 sample");
  if (!(options.n_sigma > 0) || !std::isfinite(options.n_sigma))
    throw OptionError("n_sigma",
                      fmt::format("{} is not a positive threshold (3 is usual)", options.n_sigma));
  HampelResult out;
  out.signal.assign(x.begin(), x.end());
  const std::size_t n = x.size(), h = options.half_window;
  std::vector<double> window, deviation;
  window.reserve(2 * h + 1);
  deviation.reserve(2 * h + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i >= h ? i - h : 0, hi = std::min(n - 1, i + h);
    window.assign(x.begin() + static_cast<std::ptrdiff_t>(lo),
                  x.begin() + static_cast<std::ptrdiff_t>(hi + 1));
    const double m = median_of(window);
    deviation.clear();
    for (std::size_t j = lo; j <= hi; ++j) deviation.push_back(std::fabs(x[j] - m));
    const double sigma = kGaussianMadScale * median_of(deviation);
    if (std::fabs(x[i] - m) > options.n_sigma * sigma) {
      out.signal[i] = m;
      out.replaced.push_back(i);
    }
  }
  return out;
}

}  // namespace fogdrift::signal
