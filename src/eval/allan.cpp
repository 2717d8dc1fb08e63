#include "fogdrift/eval/allan.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <utility>

#include "fogdrift/base/error.hpp"

namespace fogdrift::eval {

AllanDeviation allan_deviation(std::span<const double> rate, double dt_s,
                               std::size_t points_per_decade) {
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw OptionError("dt_s", fmt::format("{} must be a finite interval > 0", dt_s));
  const std::size_t n = rate.size();
  if (n < 4) throw OptionError("rate", fmt::format("{} samples; Allan deviation needs 4", n));
  // Angle in rate·s, accumulated in long double so that long records keep their precision.
  std::vector<long double> theta(n + 1, 0.0L);
  for (std::size_t k = 0; k < n; ++k)
    theta[k + 1] = theta[k] + static_cast<long double>(rate[k]) * dt_s;

  std::vector<std::size_t> ms;
  if (points_per_decade == 0) {
    for (std::size_t m = 1; 2 * m <= n; m *= 2) ms.push_back(m);
  } else {
    const double step = std::pow(10.0, 1.0 / static_cast<double>(points_per_decade));
    for (double mf = 1; 2 * static_cast<std::size_t>(mf) <= n; mf *= step) {
      const auto m = static_cast<std::size_t>(std::llround(mf));
      if (ms.empty() || m != ms.back()) ms.push_back(m);
    }
    while (!ms.empty() && 2 * ms.back() > n) ms.pop_back();
  }
  AllanDeviation out;
  for (std::size_t m : ms) {
    const double tau = static_cast<double>(m) * dt_s;
    long double sum = 0;
    const std::size_t terms = n - 2 * m + 1;
    for (std::size_t k = 0; k < terms; ++k) {
      const long double d = theta[k + 2 * m] - 2 * theta[k + m] + theta[k];
      sum += d * d;
    }
    const double var =
        static_cast<double>(sum / (2.0L * tau * tau * static_cast<long double>(terms)));
    out.tau_s.push_back(tau);
    out.adev.push_back(std::sqrt(var));
    out.m.push_back(m);
  }
  return out;
}

namespace {

// Local log-log slope at each point (centred difference; one-sided at the ends).
std::vector<double> local_slopes(const AllanDeviation& c) {
  const std::size_t n = c.tau_s.size();
  std::vector<double> slope(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? i : i + 1;
    slope[i] =
        (std::log(c.adev[b]) - std::log(c.adev[a])) / (std::log(c.tau_s[b]) - std::log(c.tau_s[a]));
  }
  return slope;
}

// The coefficient a of σ = a·τ_h^slope from the points whose local slope is within 0.05 of
// `slope`, averaged in log space with weights m⁻¹ (about the number of independent clusters, so
// the better-determined short clusters count more); the point of closest slope when none is
// that close. Returns the coefficient and the τ of the heaviest point used.
std::pair<double, double> read_line(const AllanDeviation& c, const std::vector<double>& slopes,
                                    double slope) {
  double sum_w = 0, sum = 0, best_w = 0, tau_used = 0;
  std::size_t closest = 0;
  for (std::size_t i = 0; i < slopes.size(); ++i) {
    if (std::abs(slopes[i] - slope) < std::abs(slopes[closest] - slope)) closest = i;
    if (std::abs(slopes[i] - slope) > 0.05) continue;
    const double w = 1.0 / static_cast<double>(std::max<std::size_t>(1, c.m[i]));
    sum += w * (std::log(c.adev[i]) - slope * std::log(c.tau_s[i] / 3600.0));
    sum_w += w;
    if (w > best_w) best_w = w, tau_used = c.tau_s[i];
  }
  if (sum_w == 0)
    return {c.adev[closest] / std::pow(c.tau_s[closest] / 3600.0, slope), c.tau_s[closest]};
  return {std::exp(sum / sum_w), tau_used};
}

}  // namespace

NoiseTerms noise_terms(const AllanDeviation& c) {
  NoiseTerms t;
  if (c.tau_s.size() < 2) return t;
  const std::vector<double> slopes = local_slopes(c);
  // ARW: σ = N·τ_h^−½.
  std::tie(t.arw_deg_per_rt_h, t.arw_tau_s) = read_line(c, slopes, -0.5);
  // Bias instability: B = σ_min / √(2 ln 2 / π) at the flat part of the curve.
  std::size_t i_min = 0;
  for (std::size_t i = 1; i < c.adev.size(); ++i)
    if (c.adev[i] < c.adev[i_min]) i_min = i;
  t.bias_instability_dph = c.adev[i_min] / std::sqrt(2 * std::log(2.0) / std::numbers::pi);
  t.bias_instability_tau_s = c.tau_s[i_min];
  // RRW: σ = (K/√3)·τ_h^½.
  double a = 0;
  std::tie(a, t.rrw_tau_s) = read_line(c, slopes, 0.5);
  t.rrw_dph_per_rt_h = a * std::sqrt(3.0);
  return t;
}

}  // namespace fogdrift::eval
