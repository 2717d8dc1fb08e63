// Temperature rates dT/dt from quantised, noisy thermometer samples (docs/method.md §2 step 2).
//
// A first difference of 1 Hz samples is mostly quantisation noise, so both differentiators fit a
// polynomial of degree p to a window of W samples by least squares and take its derivative
// (Savitzky & Golay 1964). The derivative is a fixed FIR filter, y[i] = sum_k h[k] x[i + k]:
//   centred (offline)  k = -(W-1)/2 .. (W-1)/2, derivative at the window centre; no delay.
//                      The first and last (W-1)/2 outputs use the first and last W samples,
//                      the fit evaluated off centre (SciPy's savgol_filter, mode='interp').
//   causal (online)    k = -(W-1) .. 0, only the past: derivative of the fit at the newest
//                      sample. The first W-1 outputs take the samples before the first equal
//                      to it, as if the unit had been at rest before power-on (the warm-up,
//                      docs/signal.md §2): a fit to the few samples there are would be noise.
//                      The very first output is 0.
// Delay and noise gain follow from the taps (differentiator_properties): for a signal with
// constant second derivative the output is x'(t - delay_s), with delay_s = -(dt^2/2) sum h_k k^2
// (dt = sample interval; h in 1/s), and white noise of standard deviation s gives output noise
// s * noise_gain_per_s, noise_gain_per_s = sqrt(sum h_k^2). For p = 1 or 2 the centred filter has
// h_k = k / (dt sum k^2), so delay 0 and noise gain sqrt(12 / (W (W^2 - 1))) / dt; the causal
// line fit (p = 1) has the same noise gain and a delay of (W-1)/2 samples; the causal quadratic
// (p = 2) has no delay for quadratic signals but about 4 times the noise gain.
#pragma once

#include <span>
#include <string_view>
#include <vector>

namespace fogdrift::signal {

enum class Causality {
  centred,  ///< offline: past and future samples, no delay
  causal,   ///< online: past samples only, what an instrument's processor can run
};

std::string_view to_string(Causality causality);
Causality parse_causality(std::string_view text, std::string_view option = "differentiator");
/// "centred, causal".
std::string causality_names();

struct DifferentiatorOptions {
  /// Fit window length, seconds; rounded to the nearest whole number of samples, then up to an
  /// odd number W; W >= 3 and W >= p + 2.
  /// 121 s suits 1 Hz thermometers with 0.01 °C resolution and start-up rates of 0.01-1 °C/min;
  /// see docs/signal.md.
  double window_s = 121.0;
  /// Degree p of the fitted polynomial, 1..4. Centred: p = 1 and 2 give the same filter.
  int poly_order = 2;
  Causality causality = Causality::centred;
};

/// The window and degree fogdrift uses for `causality` unless told otherwise (docs/signal.md,
/// "Which window and degree"): centred 121 s, p = 2; causal 61 s, p = 1, the causal pair that
/// came within 3 points of the centred model's north-finding share on every start-up condition.
DifferentiatorOptions recommended_rates(Causality causality);

/// Samples in the window for sample interval dt_s: round(window_s / dt_s), plus one if even.
std::size_t window_samples(const DifferentiatorOptions& options, double dt_s);

/// Throws OptionError naming the field and the rule: window_s or dt_s not positive and finite,
/// poly_order outside 1..4, a window shorter than p + 2 samples, and (for n_samples > 0) a
/// centred window longer than the signal.
void validate(const DifferentiatorOptions& options, double dt_s, std::size_t n_samples = 0);

struct DifferentiatorProperties {
  std::size_t window = 0;       ///< W, samples
  double delay_s = 0;           ///< group delay for signals of constant curvature, s
  double noise_gain_per_s = 0;  ///< output std per unit input std of white noise, 1/s
};

/// Samples at the start of a signal whose rate the causal differentiator takes from fewer than W
/// real samples, the rest of its window taken equal to the first (W − 1); 0 for the centred one,
/// whose every output is a fit to W samples.
std::size_t warmup_samples(const DifferentiatorOptions& options, double dt_s);

/// The interior filter's delay and noise gain (see the file comment).
DifferentiatorProperties differentiator_properties(const DifferentiatorOptions& options,
                                                   double dt_s);

/// dx/dt of x sampled uniformly every dt_s seconds, in x's unit per second. Same length as x.
/// Validates first.
std::vector<double> differentiate(std::span<const double> x, double dt_s,
                                  const DifferentiatorOptions& options = {});

/// The causal differentiator one sample at a time, for an instrument's processor: push(x) returns
/// what differentiate() with Causality::causal gives for that sample, bit for bit. All memory is
/// taken at construction (the taps of every start-up window length and a 2W-sample buffer);
/// push() allocates nothing.
class CausalDifferentiator {
 public:
  /// `options.causality` is ignored (the filter is causal). Validates like differentiate().
  CausalDifferentiator(const DifferentiatorOptions& options, double dt_s);
  double push(double x) noexcept;
  std::size_t window() const { return w_; }
  double dt_s() const { return dt_s_; }
  /// Whether the last push() used a full window of W samples; before that the rate comes from
  /// the window padded with the first sample (the warm-up, docs/signal.md §2).
  bool settled() const noexcept { return count_ >= w_; }
  /// The taps applied when `samples` (1 … window()) samples are available, oldest first; the
  /// derivative is their dot product with those samples, divided by dt_s().
  const std::vector<double>& taps(std::size_t samples) const { return taps_.at(samples - 1); }
  void reset() noexcept { size_ = 0, count_ = 0; }

 private:
  std::size_t w_;
  double dt_s_;
  std::vector<std::vector<double>> taps_;  // taps_[k]: window of k + 1 samples
  std::vector<double> buffer_;             // 2W; the last min(count, W) samples end at size_
  std::size_t size_ = 0;
  std::size_t count_ = 0;
};

}  // namespace fogdrift::signal
