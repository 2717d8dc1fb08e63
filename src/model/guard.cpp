#include "fogdrift/model/guard.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

double squared_distance(const double* a, const double* b, std::size_t d) noexcept {
  double s = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double e = a[k] - b[k];
    s += e * e;
  }
  return s;
}

// The 90th percentile of `nearest`; 0 when empty.
double percentile_90(std::vector<double>& nearest) {
  if (nearest.empty()) return 0.0;
  const auto at = nearest.begin() + static_cast<std::ptrdiff_t>(0.9 * double(nearest.size() - 1));
  std::nth_element(nearest.begin(), at, nearest.end());
  return *at;
}

struct Spacings {
  double labels = 0;      ///< to the nearest row of another label
  double conditions = 0;  ///< to the nearest row of the same label and another condition
};

// The 90th percentiles over (at most kSpacingRows evenly spread) rows of the distance to the
// nearest row of another label, and of the same label and another condition (0 without
// conditions, or where no row has such a neighbour). One pass: each distance is computed once.
Spacings spacings(std::span<const double> z, std::size_t dims, std::span<const std::size_t> labels,
                  std::span<const std::size_t> conditions) {
  constexpr std::size_t kSpacingRows = 4000;
  const std::size_t n = labels.size();
  const std::size_t step = (n + kSpacingRows - 1) / kSpacingRows;
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < n; i += step) rows.push_back(i);
  std::vector<double> nearest_label, nearest_condition;
  for (std::size_t i : rows) {
    double label = std::numeric_limits<double>::infinity(), condition = label;
    for (std::size_t j : rows) {
      const bool other_label = labels[j] != labels[i];
      const bool other_condition =
          !other_label && !conditions.empty() && conditions[j] != conditions[i];
      if (!other_label && !other_condition) continue;
      const double d2 = squared_distance(z.data() + i * dims, z.data() + j * dims, dims);
      if (other_label)
        label = std::min(label, d2);
      else
        condition = std::min(condition, d2);
    }
    if (std::isfinite(label)) nearest_label.push_back(std::sqrt(label));
    if (std::isfinite(condition)) nearest_condition.push_back(std::sqrt(condition));
  }
  return {percentile_90(nearest_label), percentile_90(nearest_condition)};
}

}  // namespace

void validate(const GuardSettings& s) {
  if (s.prototypes < 1 || s.prototypes > 4096)
    throw OptionError("guard.prototypes", fmt::format("{} is outside [1, 4096]", s.prototypes));
  if (!(s.full_at > 0.0) || !std::isfinite(s.full_at))
    throw OptionError("guard.full_at", fmt::format("{} must be finite and > 0", s.full_at));
  if (!(s.zero_at > s.full_at) || !std::isfinite(s.zero_at))
    throw OptionError("guard.zero_at", fmt::format("{} must be greater than guard.full_at ({})",
                                                   s.zero_at, s.full_at));
  if (!(s.recover_s >= 0) || !std::isfinite(s.recover_s))
    throw OptionError(
        "guard.recover_s",
        fmt::format("{} s must be finite and ≥ 0 (0: latched until power-on)", s.recover_s));
}

NoveltyGuard NoveltyGuard::fit(std::span<const double> z, std::size_t dims,
                               std::span<const std::size_t> labels,
                               std::span<const std::size_t> conditions,
                               const GuardSettings& settings) {
  validate(settings);
  if (dims == 0 || z.size() < dims || z.size() % dims != 0)
    throw OptionError("guard", "needs at least one training row of the model's inputs");
  const std::size_t n = z.size() / dims;
  NoveltyGuard g;
  g.settings = settings;
  g.settings.prototypes = std::min(settings.prototypes, z.size() / dims);
  g.dims = dims;
  // Farthest-point sampling: nearest[i] is row i's squared distance to the prototypes so far.
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  std::size_t next = 0;
  const std::size_t k_max = std::min(settings.prototypes, n);
  for (std::size_t k = 0; k < k_max; ++k) {
    const double* p = z.data() + next * dims;
    g.prototypes.insert(g.prototypes.end(), p, p + dims);
    std::size_t farthest = 0;
    double farthest_d2 = -1;
    for (std::size_t i = 0; i < n; ++i) {
      nearest[i] = std::min(nearest[i], squared_distance(z.data() + i * dims, p, dims));
      if (nearest[i] > farthest_d2) farthest_d2 = nearest[i], farthest = i;
    }
    next = farthest;
    g.radius = std::sqrt(farthest_d2);
  }
  if (!labels.empty()) {
    if (labels.size() != n) throw OptionError("guard", "needs one label per training row");
    if (!conditions.empty() && conditions.size() != n)
      throw OptionError("guard", "needs one condition per training row");
    const Spacings spacing = spacings(z, dims, labels, conditions);
    g.radius = std::max(g.radius, spacing.labels);
    // Conditions widen the unit only where the labels span one: a model calibrated at one
    // temperature knows nothing of another, however its start-ups differed there.
    if (spacing.labels > 0) g.radius = std::max(g.radius, spacing.conditions);
  }
  // With as many prototypes as rows (or repeated rows) the cover radius is 0; a floor keeps ν
  // finite and says "only these points" (1e-3 standard deviations).
  g.radius = std::max(g.radius, 1e-3);
  return g;
}

double NoveltyGuard::novelty(std::span<const double> z, bool warming) const noexcept {
  double best = std::numeric_limits<double>::infinity();
  if (warming && warmup_inputs.size() == dims) {
    for (std::size_t k = 0; k < size(); ++k) {
      const double* p = prototypes.data() + k * dims;
      double s = 0.0;
      for (std::size_t j = 0; j < dims; ++j) {
        const double e = warmup_inputs[j] ? z[j] - p[j] : 0.0;
        s += e * e;
      }
      best = std::min(best, s);
    }
  } else {
    for (std::size_t k = 0; k < size(); ++k)
      best = std::min(best, squared_distance(z.data(), prototypes.data() + k * dims, dims));
  }
  return std::sqrt(best) / radius;
}

void NoveltyGuard::set_warmup_inputs(const std::vector<bool>& reads_rate) {
  warmup_inputs.assign(reads_rate.size(), 0);
  for (std::size_t j = 0; j < reads_rate.size(); ++j) warmup_inputs[j] = reads_rate[j] ? 0 : 1;
}

double NoveltyGuard::target_weight(double nu) const noexcept {
  if (std::isnan(nu)) return 0.0;  // inputs that are not numbers: no correction
  if (nu <= settings.full_at) return 1.0;
  if (nu >= settings.zero_at) return 0.0;
  return (settings.zero_at - nu) / (settings.zero_at - settings.full_at);
}

double GuardFilter::update(double time_s, double v, double recover_s) noexcept {
  const double dt = started_ ? std::max(0.0, time_s - last_time_s_) : 0.0;
  weight_ = std::min(v, weight_ + (recover_s > 0 ? dt / recover_s : 0.0));
  last_time_s_ = time_s;
  started_ = true;
  return weight_;
}

}  // namespace fogdrift

namespace fogdrift {

NoveltySummary summarize_novelty(std::span<const double> novelty, std::span<const double> weight) {
  NoveltySummary s;
  s.samples = novelty.size();
  for (std::size_t i = 0; i < novelty.size(); ++i) {
    if (std::isnan(novelty[i])) {
      s.max_novelty = novelty[i];
      continue;
    }
    if (novelty[i] > 1.0) ++s.outside;
    if (i < weight.size() && weight[i] < 1.0) ++s.reduced;
    if (!std::isnan(s.max_novelty)) s.max_novelty = std::max(s.max_novelty, novelty[i]);
  }
  return s;
}

std::string NoveltySummary::line() const {
  if (std::isnan(max_novelty)) return "novelty: the model has no guard (format version 1)";
  const double n = samples ? static_cast<double>(samples) : 1.0;
  return fmt::format(
      "novelty: {:.1f} % of {} samples outside the training region (max {:.2f}), correction "
      "reduced on {:.1f} %",
      100.0 * static_cast<double>(outside) / n, samples, max_novelty,
      100.0 * static_cast<double>(reduced) / n);
}

}  // namespace fogdrift
