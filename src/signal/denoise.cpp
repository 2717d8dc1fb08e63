#include "fogdrift/signal/denoise.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

constexpr double kMadToSigma =
    0.6745;  // the normal distribution's quartile, as in the paper's field

constexpr std::array<EnumName<ThresholdRule>, 4> kThresholdRuleNames = {
    {{ThresholdRule::universal, "universal"},
     {ThresholdRule::level, "level"},
     {ThresholdRule::sure, "sure"},
     {ThresholdRule::bayes, "bayes"}}};
constexpr std::array<EnumName<Shrinkage>, 2> kShrinkageNames = {
    {{Shrinkage::soft, "soft"}, {Shrinkage::hard, "hard"}}};

}  // namespace

std::string_view to_string(ThresholdRule rule) {
  return name_in(kThresholdRuleNames, rule);
}

std::string_view to_string(Shrinkage shrinkage) {
  return name_in(kShrinkageNames, shrinkage);
}

ThresholdRule parse_threshold_rule(std::string_view text, std::string_view option) {
  return parse_in(kThresholdRuleNames, text, option, "a threshold rule");
}

Shrinkage parse_shrinkage(std::string_view text, std::string_view option) {
  return parse_in(kShrinkageNames, text, option, "a shrinkage mode");
}

std::string threshold_rule_names() {
  return names_in(kThresholdRuleNames);
}

std::string shrinkage_names() {
  return names_in(kShrinkageNames);
}

void validate(const DenoiseOptions& options, std::size_t n_samples) {
  const Wavelet w = wavelet(options.wavelet);  // throws for an unknown name
  const int max_level = dwt_max_level(n_samples, w.filter_length());
  const std::size_t need_one = static_cast<std::size_t>(2 * (w.filter_length() - 1));
  if (max_level < 1) {
    throw OptionError("level", "a signal of " + std::to_string(n_samples) +
                                   " samples is too short to denoise with " + w.name +
                                   " (at least " + std::to_string(need_one) +
                                   " samples are needed for one level)");
  }
  if (options.level) {
    const int level = *options.level;
    if (level < 1) throw OptionError("level", std::to_string(level) + " must be at least 1");
    if (level > max_level) {
      const std::size_t need = static_cast<std::size_t>(w.filter_length() - 1) << level;
      throw OptionError("level", std::to_string(level) + " is too high for " +
                                     std::to_string(n_samples) + " samples with " + w.name +
                                     ": the maximum is " + std::to_string(max_level) + " (level " +
                                     std::to_string(level) + " needs " + std::to_string(need) +
                                     " samples)");
    }
  }
}

double mad_sigma(std::span<const double> detail) {
  if (detail.empty()) return 0.0;
  std::vector<double> a(detail.size());
  std::transform(detail.begin(), detail.end(), a.begin(), [](double v) { return std::fabs(v); });
  const std::size_t mid = a.size() / 2;
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(mid), a.end());
  double median = a[mid];
  if (a.size() % 2 == 0) {  // numpy's median: the mean of the two middle values
    const double below = *std::max_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(mid));
    median = 0.5 * (median + below);
  }
  return median / kMadToSigma;
}

double sure_threshold(std::span<const double> detail, double sigma) {
  if (detail.empty() || !(sigma > 0)) return 0.0;
  // SURE(t) for soft thresholding of w = d / sigma at t = |w|_(k) (k-th smallest):
  //   n - 2k + sum_{i<=k} w_(i)^2 + (n - k) w_(k)^2   (Donoho & Johnstone 1995, eq. 11)
  std::vector<double> w2(detail.size());
  for (std::size_t i = 0; i < detail.size(); ++i) {
    const double w = detail[i] / sigma;
    w2[i] = w * w;
  }
  std::sort(w2.begin(), w2.end());
  const double n = static_cast<double>(w2.size());
  double cumulative = 0.0;
  double best_risk = n;  // t = 0: nothing shrunk, risk n
  double best_t2 = 0.0;
  for (std::size_t k = 1; k <= w2.size(); ++k) {
    cumulative += w2[k - 1];
    const double risk =
        n - 2.0 * static_cast<double>(k) + cumulative + (n - static_cast<double>(k)) * w2[k - 1];
    if (risk < best_risk) {
      best_risk = risk;
      best_t2 = w2[k - 1];
    }
  }
  return sigma * std::sqrt(best_t2);
}

std::size_t shrink(std::span<double> coefficients, double lambda, Shrinkage shrinkage) {
  std::size_t kept = 0;
  for (double& c : coefficients) {
    const double mag = std::fabs(c);
    if (shrinkage == Shrinkage::soft) {
      c = mag > lambda ? std::copysign(mag - lambda, c) : 0.0;
    } else if (mag < lambda) {
      c = 0.0;
    }
    if (c != 0.0) ++kept;
  }
  return kept;
}

DenoiseResult denoise(std::span<const double> x, const DenoiseOptions& options) {
  validate(options, x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw OptionError("signal", "sample " + std::to_string(i) + " is not a finite number");
    }
  }
  const Wavelet w = wavelet(options.wavelet);
  WaveletCoeffs coeffs = wavedec(x, w, options.extension, options.level);
  const int levels = coeffs.level();
  const double n_log = std::sqrt(2.0 * std::log(static_cast<double>(x.size())));

  DenoiseResult result;
  result.summary.level = levels;
  const double sigma = mad_sigma(coeffs.bands[static_cast<std::size_t>(levels)]);
  result.summary.noise_sigma = sigma;
  for (int j = 1; j <= levels; ++j) {  // j = 1 is the finest band, stored last
    auto& band = coeffs.bands[static_cast<std::size_t>(levels - j + 1)];
    double lambda = 0.0;
    switch (options.threshold) {
      case ThresholdRule::universal:
        lambda = sigma * n_log;
        break;
      case ThresholdRule::level:
        lambda = mad_sigma(band) * n_log;
        break;
      case ThresholdRule::sure:
        lambda = sure_threshold(band, sigma);
        break;
      case ThresholdRule::bayes: {
        double mean_square = 0.0;
        for (double v : band) mean_square += v * v;
        mean_square /= static_cast<double>(band.size());
        const double signal_var = mean_square - sigma * sigma;
        if (signal_var > 0) {
          lambda = sigma * sigma / std::sqrt(signal_var);
        } else {
          lambda = 0.0;
          for (double v : band) lambda = std::max(lambda, std::fabs(v));
          lambda = std::nextafter(lambda, INFINITY);  // zero the whole band, hard or soft
        }
        break;
      }
    }
    BandSummary b;
    b.level = j;
    b.size = band.size();
    b.threshold = lambda;
    b.kept = shrink(band, lambda, options.shrinkage);
    result.summary.bands.push_back(b);
  }
  result.signal = waverec_to_length(coeffs, w, options.extension);
  return result;
}

}  // namespace fogdrift::signal
