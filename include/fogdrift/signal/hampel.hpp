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

// The defaults are chosen so that plain Gaussian noise loses (almost) nothing. The MAD of a short
// window is a noisy scale, so the customary 3σ replaces many good samples. Share of samples of
// white Gaussian noise replaced, measured over 40,000 samples (docs/signal.md):
//   h = 5:  3σ 2.7 %, 5σ 0.53 %, 6σ 0.27 %
//   h = 10: 3σ 1.6 %, 5σ 0.10 %, 6σ 0.03 %
//   h = 25: 3σ 0.67 %, 5σ 0.01 %, 6σ 0
// A logger's spikes (bus glitches, a register's error value) are tens of σ and are caught either
// way.
struct HampelOptions {
  /// Half-width h of the window, samples, >= 1 (window of 2h + 1 samples).
  std::size_t half_window = 25;
  /// Threshold in local standard deviations, > 0.
  double n_sigma = 6.0;
};

/// κ = 1 / Φ⁻¹(3/4): the MAD of a Gaussian times κ is its standard deviation.
inline constexpr double kGaussianMadScale = 1.4826022185056018;

struct HampelResult {
  std::vector<double> signal;         ///< the input with every outlier replaced
  std::vector<std::size_t> replaced;  ///< indices of the replaced samples, ascending
};

/// Throws OptionError("half_window" / "n_sigma", ...) for an impossible option.
HampelResult hampel(std::span<const double> x, const HampelOptions& options = {});

}  // namespace fogdrift::signal
