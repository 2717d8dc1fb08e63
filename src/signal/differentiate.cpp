#include "fogdrift/signal/differentiate.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

// Taps h (in 1/sample) such that sum_j h[j] x[first + j] is the derivative at offset 0 of the
// degree-p least-squares polynomial through the samples at offsets first .. first + count - 1.
std::vector<double> derivative_taps(std::ptrdiff_t first, std::size_t count, int order) {
  const int p = std::min<int>(order, static_cast<int>(count) - 1);
  if (p < 1) return std::vector<double>(count, 0.0);
  // Offsets scaled to [-1, 1] keep the Vandermonde matrix well conditioned.
  double scale = 1.0;
  for (std::size_t j = 0; j < count; ++j) {
    scale = std::max(scale, std::fabs(static_cast<double>(first + static_cast<std::ptrdiff_t>(j))));
  }
  Eigen::MatrixXd v(static_cast<Eigen::Index>(count), p + 1);
  for (std::size_t j = 0; j < count; ++j) {
    const double u = static_cast<double>(first + static_cast<std::ptrdiff_t>(j)) / scale;
    double power = 1.0;
    for (int c = 0; c <= p; ++c) {
      v(static_cast<Eigen::Index>(j), c) = power;
      power *= u;
    }
  }
  // Coefficient c_1 of the fit is row 1 of the pseudo-inverse; d/dk = c_1 / scale.
  const Eigen::MatrixXd pinv = v.completeOrthogonalDecomposition().pseudoInverse();
  std::vector<double> taps(count);
  for (std::size_t j = 0; j < count; ++j) taps[j] = pinv(1, static_cast<Eigen::Index>(j)) / scale;
  return taps;
}

// The causal taps for a start-up's first `count` samples (count < w): the full window's fit to
// the signal with the samples before power-on taken equal to the first one, as if the unit had
// been at rest (docs/signal.md §2, "Warm-up"). The missing samples' weights fall on the first
// sample; it is given the weight that makes the taps sum to zero, as the full window's do, so
// that a constant signal has a rate of exactly 0 (the first output among them).
std::vector<double> warmup_taps(const std::vector<double>& full, std::size_t count) {
  std::vector<double> taps(full.end() - static_cast<std::ptrdiff_t>(count), full.end());
  double rest = 0.0;
  for (std::size_t j = 1; j < count; ++j) rest += taps[j];
  taps[0] = -rest;
  return taps;
}

double apply(const std::vector<double>& taps, std::span<const double> x, std::size_t first) {
  double sum = 0.0;
  for (std::size_t j = 0; j < taps.size(); ++j) sum += taps[j] * x[first + j];
  return sum;
}

}  // namespace

namespace {

constexpr std::array<EnumName<Causality>, 5> kCausalityNames = {{{Causality::centred, "centred"},
                                                                 {Causality::causal, "causal"},
                                                                 {Causality::centred, "centered"},
                                                                 {Causality::centred, "offline"},
                                                                 {Causality::causal, "online"}}};

}  // namespace

std::string_view to_string(Causality causality) {
  return name_in(kCausalityNames, causality);
}

Causality parse_causality(std::string_view text, std::string_view option) {
  return parse_in(kCausalityNames, text, option, "a differentiator");
}

std::string causality_names() {
  return names_in(kCausalityNames);
}

DifferentiatorOptions recommended_rates(Causality causality) {
  DifferentiatorOptions o;
  o.causality = causality;
  if (causality == Causality::causal) {
    o.window_s = 61.0;
    o.poly_order = 1;
  }
  return o;
}

std::size_t window_samples(const DifferentiatorOptions& options, double dt_s) {
  const double whole = std::max(std::round(options.window_s / dt_s), 0.0);
  const auto w = static_cast<std::size_t>(whole);
  return w % 2 == 1 ? w : w + 1;
}

std::size_t warmup_samples(const DifferentiatorOptions& options, double dt_s) {
  return options.causality == Causality::causal ? window_samples(options, dt_s) - 1 : 0;
}

void validate(const DifferentiatorOptions& options, double dt_s, std::size_t n_samples) {
  if (!(dt_s > 0) || !std::isfinite(dt_s)) {
    throw OptionError("dt_s", "the sample interval must be positive and finite");
  }
  if (!(options.window_s > 0) || !std::isfinite(options.window_s)) {
    throw OptionError("window_s", "the differentiator window must be positive and finite, got " +
                                      std::to_string(options.window_s));
  }
  if (options.poly_order < 1 || options.poly_order > 4) {
    throw OptionError("poly_order", std::to_string(options.poly_order) + " is outside 1..4");
  }
  const std::size_t w = window_samples(options, dt_s);
  if (w < 3 || w < static_cast<std::size_t>(options.poly_order) + 2) {
    throw OptionError("window_s", "a window of " + std::to_string(options.window_s) + " s is " +
                                      std::to_string(w) + " samples; a degree-" +
                                      std::to_string(options.poly_order) + " fit needs at least " +
                                      std::to_string(std::max(3, options.poly_order + 2)));
  }
  if (n_samples > 0 && options.causality == Causality::centred && n_samples < w) {
    throw OptionError("window_s", "the centred differentiator's window of " + std::to_string(w) +
                                      " samples is longer than the signal (" +
                                      std::to_string(n_samples) + " samples)");
  }
}

DifferentiatorProperties differentiator_properties(const DifferentiatorOptions& options,
                                                   double dt_s) {
  validate(options, dt_s);
  const std::size_t w = window_samples(options, dt_s);
  const auto m = static_cast<std::ptrdiff_t>(w / 2);
  const std::ptrdiff_t first =
      options.causality == Causality::centred ? -m : -static_cast<std::ptrdiff_t>(w - 1);
  const auto taps = derivative_taps(first, w, options.poly_order);
  double curvature = 0.0;
  double power = 0.0;
  for (std::size_t j = 0; j < w; ++j) {
    const double k = static_cast<double>(first + static_cast<std::ptrdiff_t>(j));
    curvature += taps[j] * k * k;
    power += taps[j] * taps[j];
  }
  DifferentiatorProperties props;
  props.window = w;
  props.delay_s = -0.5 * curvature * dt_s;  // taps are per sample: h_k (1/s) = taps / dt
  props.noise_gain_per_s = std::sqrt(power) / dt_s;
  return props;
}

std::vector<double> differentiate(std::span<const double> x, double dt_s,
                                  const DifferentiatorOptions& options) {
  validate(options, dt_s, x.size());
  const std::size_t n = x.size();
  const std::size_t w = window_samples(options, dt_s);
  const int p = options.poly_order;
  std::vector<double> out(n, 0.0);
  if (options.causality == Causality::centred) {
    const std::size_t m = w / 2;
    const auto centre = derivative_taps(-static_cast<std::ptrdiff_t>(m), w, p);
    for (std::size_t i = m; i + m < n; ++i) out[i] = apply(centre, x, i - m);
    for (std::size_t i = 0; i < m; ++i) {  // the fit to the first and last W samples
      out[i] = apply(derivative_taps(-static_cast<std::ptrdiff_t>(i), w, p), x, 0);
      const std::size_t r = n - 1 - i;
      out[r] = apply(derivative_taps(-static_cast<std::ptrdiff_t>(w - 1 - i), w, p), x, n - w);
    }
  } else {
    const auto full = derivative_taps(-static_cast<std::ptrdiff_t>(w - 1), w, p);
    for (std::size_t i = 0; i < n; ++i) {
      if (i + 1 >= w) {
        out[i] = apply(full, x, i + 1 - w);
      } else {
        out[i] = apply(warmup_taps(full, i + 1), x, 0);
      }
    }
  }
  for (double& v : out) v /= dt_s;
  return out;
}

CausalDifferentiator::CausalDifferentiator(const DifferentiatorOptions& options, double dt_s)
    : dt_s_(dt_s) {
  DifferentiatorOptions causal = options;
  causal.causality = Causality::causal;
  validate(causal, dt_s);
  w_ = window_samples(causal, dt_s);
  taps_.reserve(w_);
  const auto full = derivative_taps(-static_cast<std::ptrdiff_t>(w_ - 1), w_, causal.poly_order);
  for (std::size_t k = 1; k < w_; ++k) taps_.push_back(warmup_taps(full, k));
  taps_.push_back(full);
  buffer_.assign(2 * w_, 0.0);
}

double CausalDifferentiator::push(double x) noexcept {
  if (size_ == buffer_.size()) {  // keep the newest W − 1 samples at the front
    std::copy(buffer_.end() - static_cast<std::ptrdiff_t>(w_ - 1), buffer_.end(), buffer_.begin());
    size_ = w_ - 1;
  }
  buffer_[size_++] = x;
  ++count_;
  const std::size_t used = std::min(count_, w_);
  const std::span<const double> window(buffer_.data() + size_ - used, used);
  return apply(taps_[used - 1], window, 0) / dt_s_;
}

}  // namespace fogdrift::signal
