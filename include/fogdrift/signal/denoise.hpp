// Wavelet-threshold denoising of the FOG output (docs/method.md §2 step 1): decompose with wavedec,
// shrink every detail band towards zero, keep the approximation, reconstruct with waverec.
//
// The noise level sigma is the median absolute detail coefficient of the finest band divided by
// 0.6745 (Donoho & Johnstone 1994; the median, not the mean, absolute deviation, so the few large
// coefficients of the drift do not inflate it). Threshold rules, per detail band j of n_j
// coefficients, for a signal of N samples:
//   universal  lambda   = sigma * sqrt(2 ln N)                  (VisuShrink, the same for all
//   bands) level      lambda_j = sigma_j * sqrt(2 ln N), sigma_j = median(|d_j|) / 0.6745 of band j
//              (for noise that is not white, e.g. a FOG's flicker and random-walk terms)
//   sure       lambda_j = sigma * t*, t* minimising Stein's unbiased risk estimate of soft
//              thresholding on d_j / sigma (Donoho & Johnstone 1995; MATLAB's 'rigrsure')
//   bayes      lambda_j = sigma^2 / sigma_x,j, sigma_x,j = sqrt(max(mean(d_j^2) - sigma^2, 0))
//              (BayesShrink, Chang, Yu & Vetterli 2000); a band with sigma_x,j = 0 is zeroed
// Shrinkage: soft  d -> sign(d) max(|d| - lambda, 0);  hard  d -> d if |d| >= lambda, else 0
// (pywt.threshold's conventions).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/signal/dwt.hpp"

namespace fogdrift::signal {

enum class ThresholdRule { universal, level, sure, bayes };
enum class Shrinkage { soft, hard };

std::string_view to_string(ThresholdRule rule);
std::string_view to_string(Shrinkage shrinkage);
/// Parse the names above; throw OptionError(option, ...) listing the valid names.
ThresholdRule parse_threshold_rule(std::string_view text, std::string_view option = "threshold");
Shrinkage parse_shrinkage(std::string_view text, std::string_view option = "mode");
/// "universal, level, sure, bayes" and "soft, hard".
std::string threshold_rule_names();
std::string shrinkage_names();

/// The defaults were chosen by measurement on simulated start-up recordings (docs/signal.md,
/// bench/denoise_study.cpp): of 170 settings, sym4 with BayesShrink and soft shrinkage at the
/// maximum level left the least noise (0.0034 °/h in 10 s means, against 0.0041 for the
/// universal threshold and 0.0096 undenoised) and kept 99.5 % of the known drift.
struct DenoiseOptions {
  std::string wavelet = "sym4";  ///< any name of wavelet_names()
  /// Decomposition levels, 1 .. dwt_max_level(N, F); nullopt = the maximum (PyWavelets' default).
  std::optional<int> level;
  ThresholdRule threshold = ThresholdRule::bayes;
  Shrinkage shrinkage = Shrinkage::soft;
  Extension extension = Extension::symmetric;
};

/// Throws OptionError naming the option and the rule, also when `n_samples` is too short for
/// the level (or for one level of the wavelet at all).
void validate(const DenoiseOptions& options, std::size_t n_samples);

struct BandSummary {
  int level = 0;         ///< 1 = finest detail band
  std::size_t size = 0;  ///< coefficients in the band
  double threshold = 0;  ///< lambda_j applied, same unit as the signal
  std::size_t kept = 0;  ///< coefficients left non-zero
};

struct DenoiseSummary {
  int level = 0;                   ///< levels used
  double noise_sigma = 0;          ///< sigma from the finest band, same unit as the signal
  std::vector<BandSummary> bands;  ///< finest first
};

struct DenoiseResult {
  std::vector<double> signal;  ///< denoised, same length as the input
  DenoiseSummary summary;
};

/// Denoises x. Validates first (throws OptionError); a non-finite sample throws OptionError
/// naming its index.
DenoiseResult denoise(std::span<const double> x, const DenoiseOptions& options = {});

/// median(|d|) / 0.6745, the robust noise estimate of a detail band (0 for an empty band).
double mad_sigma(std::span<const double> detail);

/// The SURE-optimal soft threshold of `detail` for noise level sigma (sigma times t* above).
double sure_threshold(std::span<const double> detail, double sigma);

/// Applies soft or hard shrinkage with threshold lambda >= 0 in place; returns the number of
/// coefficients left non-zero.
std::size_t shrink(std::span<double> coefficients, double lambda, Shrinkage shrinkage);

}  // namespace fogdrift::signal
