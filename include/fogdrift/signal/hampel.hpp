// Hampel outlier filter: spikes in a logged channel replaced by the local median.
//
// For each sample i, the window is the samples i − h .. i + h (truncated at the ends of the
// record, never padded). With m the window's median and MAD its median absolute deviation from m,
// the local scale is s = κ·MAD, κ = 1 / Φ⁻¹(3/4) ≈ 1.4826, which makes s the standard deviation
// for Gaussian noise. Sample i is an outlier when |x_i − m| > n_sigma·s, and is replaced by m.
// Every decision reads the original samples, so one spike never hides or creates another.
// (docs/signal.md, "Outliers".)
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fogdrift::signal {

struct HampelOptions {
  /// Half-width h of the window, samples, >= 1 (window of 2h + 1 samples).
  std::size_t half_window = 5;
  /// Threshold in local standard deviations, > 0. 3 is the customary choice.
  double n_sigma = 3.0;
};

/// κ = 1 / Φ⁻¹(3/4): the MAD of a Gaussian times κ is its standard deviation.
inline constexpr double kMadToSigma = 1.4826022185056018;

struct HampelResult {
  std::vector<double> signal;         ///< the input with every outlier replaced
  std::vector<std::size_t> replaced;  ///< indices of the replaced samples, ascending
};

/// Throws OptionError("half_window" / "n_sigma", ...) for an impossible option.
HampelResult hampel(std::span<const double> x, const HampelOptions& options = {});

}  // namespace fogdrift::signal
