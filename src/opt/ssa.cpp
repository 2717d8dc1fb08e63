#include "fogdrift/opt/ssa.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "opt/population.hpp"

namespace fogdrift::opt {

void validate(const SsaOptions& options) {
  if (!(options.producer_fraction > 0 && options.producer_fraction < 1))
    throw OptionError("producer_fraction",
                      fmt::format("{} is outside (0, 1)", options.producer_fraction));
  if (!(options.scout_fraction > 0 && options.scout_fraction <= 1))
    throw OptionError("scout_fraction",
                      fmt::format("{} is outside (0, 1]", options.scout_fraction));
  if (!(options.safety_threshold >= 0.5 && options.safety_threshold <= 1))
    throw OptionError("safety_threshold",
                      fmt::format("{} is outside [0.5, 1]", options.safety_threshold));
}

namespace {

// Division guard of eq. (5), "the smallest constant" in Xue & Shen.
constexpr double kEpsilon = 1e-50;

struct Flock {
  std::size_t n, d;
  std::vector<double> x;  // remembered (best) position of each sparrow, row-major
  std::vector<double> f;  // its fitness
  std::span<double> row(std::size_t i) { return {x.data() + i * d, d}; }
};

}  // namespace

Summary ssa(const Problem& problem, const RunOptions& run, const SsaOptions& options) {
  validate(problem);
  validate(run, 5);
  validate(options);
  const std::size_t n = run.population, d = problem.dimension(), T = run.iterations;
  const auto share = [n](double fraction) {
    return std::clamp<std::size_t>(
        static_cast<std::size_t>(std::lround(fraction * static_cast<double>(n))), 1, n - 1);
  };
  const std::size_t producers = share(options.producer_fraction);
  const std::size_t scouts = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::lround(options.scout_fraction * static_cast<double>(n))));

  Rng rng(run.seed);
  detail::Run r(Algorithm::ssa, problem, run);
  for (const char* name : {"producer_forage", "producer_alarm", "scrounger_starving",
                           "scrounger_follow", "scout_toward_best", "scout_away_from_worst"})
    r.count(name, 0);

  Flock flock{n, d, detail::uniform_points(problem, n, rng), std::vector<double>(n)};
  r.evaluate(flock.x, flock.f);
  if (!r.end_iteration(0, flock.f)) return r.finish();

  std::vector<std::size_t> order(n), who;
  std::vector<double> moved, moved_f;  // the sparrows moved in one stage, evaluated together
  std::vector<double> next(n * d), next_f(n);
  std::vector<double> worst(d), best_producer(d);
  std::vector<std::size_t> pool(n);

  // Evaluates the rows of `next` of the sparrows in `who`, and keeps each new position that is
  // better than the remembered one (Algorithm 1, "if the new location is better than before").
  auto evaluate_stage = [&] {
    moved.resize(who.size() * d);
    moved_f.resize(who.size());
    for (std::size_t k = 0; k < who.size(); ++k)
      std::copy_n(next.begin() + static_cast<std::ptrdiff_t>(who[k] * d), d,
                  moved.begin() + static_cast<std::ptrdiff_t>(k * d));
    r.evaluate(moved, moved_f);
    for (std::size_t k = 0; k < who.size(); ++k) {
      const std::size_t i = who[k];
      next_f[i] = moved_f[k];
      if (moved_f[k] < flock.f[i]) {
        flock.f[i] = moved_f[k];
        std::copy_n(moved.begin() + static_cast<std::ptrdiff_t>(k * d), d, flock.row(i).begin());
      }
    }
  };

  for (std::size_t t = 1; t <= T; ++t) {
    // Rank by remembered fitness, best first (ties by index, so the order is reproducible).
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return flock.f[a] < flock.f[b]; });
    const auto worst_row = flock.row(order[n - 1]);
    std::copy(worst_row.begin(), worst_row.end(), worst.begin());
    const double r2 = rng.uniform();  // alarm value, one per iteration

    // Producers, eq. (3).
    who.assign(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(producers));
    for (std::size_t k = 0; k < producers; ++k) {
      const std::size_t i = order[k];
      const double rank = static_cast<double>(k + 1);
      const auto x = flock.row(i);
      std::span<double> y(next.data() + i * d, d);
      if (r2 < options.safety_threshold) {
        const double alpha = 1.0 - rng.uniform();  // α ∈ (0, 1]
        const double factor = std::exp(-rank / (alpha * static_cast<double>(T)));
        for (std::size_t j = 0; j < d; ++j) y[j] = x[j] * factor;
        r.count("producer_forage");
      } else {
        const double q = rng.normal();
        for (std::size_t j = 0; j < d; ++j) y[j] = x[j] + q;  // Q·L
        r.count("producer_alarm");
      }
      detail::clip(y, problem);
    }
    evaluate_stage();
    std::size_t best_k = 0;
    for (std::size_t k = 1; k < producers; ++k)
      if (next_f[order[k]] < next_f[order[best_k]]) best_k = k;
    std::copy_n(next.begin() + static_cast<std::ptrdiff_t>(order[best_k] * d), d,
                best_producer.begin());

    // Scroungers, eq. (4).
    who.assign(order.begin() + static_cast<std::ptrdiff_t>(producers), order.end());
    for (std::size_t k = producers; k < n; ++k) {
      const std::size_t i = order[k];
      const double rank = static_cast<double>(k + 1);
      const auto x = flock.row(i);
      std::span<double> y(next.data() + i * d, d);
      if (rank > static_cast<double>(n) / 2) {
        const double q = rng.normal();
        for (std::size_t j = 0; j < d; ++j) y[j] = q * std::exp((worst[j] - x[j]) / (rank * rank));
        r.count("scrounger_starving");
      } else {
        double step = 0;  // |x − x_P|·A⁺·L with A⁺ = Aᵀ/d
        for (std::size_t j = 0; j < d; ++j) {
          const double a = rng.uniform() < 0.5 ? -1.0 : 1.0;
          step += a * std::abs(x[j] - best_producer[j]);
        }
        step /= static_cast<double>(d);
        for (std::size_t j = 0; j < d; ++j) y[j] = best_producer[j] + step;
        r.count("scrounger_follow");
      }
      detail::clip(y, problem);
    }
    evaluate_stage();

    // Scouts, eq. (5): drawn without replacement from the whole flock, moved from their new
    // positions; x_w, f_w the worst of the new positions.
    std::size_t w = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (next_f[i] > next_f[w]) w = i;
    std::copy_n(next.begin() + static_cast<std::ptrdiff_t>(w * d), d, worst.begin());
    const double f_worst = next_f[w];
    std::iota(pool.begin(), pool.end(), 0);
    who.clear();
    for (std::size_t s = 0; s < scouts; ++s) {
      const std::size_t pick =
          s + static_cast<std::size_t>(rng.uniform() * static_cast<double>(n - s));
      std::swap(pool[s], pool[std::min(pick, n - 1)]);
      who.push_back(pool[s]);
    }
    const std::vector<double> best(r.best_point().begin(), r.best_point().end());
    const double f_best = r.best_fitness();
    for (const std::size_t i : who) {
      std::span<double> y(next.data() + i * d, d);
      const double fi = next_f[i];
      if (fi > f_best || !std::isfinite(fi)) {
        for (std::size_t j = 0; j < d; ++j)
          y[j] = best[j] + rng.normal() * std::abs(y[j] - best[j]);
        r.count("scout_toward_best");
      } else {  // f_i = f_g: this sparrow holds the best position found so far
        const double k = rng.uniform(-1.0, 1.0);
        const double denominator = (fi - f_worst) + kEpsilon;
        for (std::size_t j = 0; j < d; ++j) y[j] += k * std::abs(y[j] - worst[j]) / denominator;
        r.count("scout_away_from_worst");
      }
      detail::clip(y, problem);
    }
    evaluate_stage();

    if (!r.end_iteration(t, flock.f)) break;
  }
  return r.finish();
}

}  // namespace fogdrift::opt
