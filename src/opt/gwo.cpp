#include "fogdrift/opt/gwo.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>

#include "fogdrift/base/error.hpp"
#include "opt/population.hpp"

namespace fogdrift::opt {

void validate(const GwoOptions& options) {
  if (!(options.a_start > 0 && std::isfinite(options.a_start)))
    throw OptionError("a_start", fmt::format("{} must be finite and > 0", options.a_start));
}

namespace {

// α, β, δ: the three best positions evaluated so far, best first. A better point demotes the
// leaders below it (Mirjalili's reference code overwrites without demoting; fogdrift keeps the
// three best, which is what the paper's text describes).
struct Leaders {
  std::array<std::vector<double>, 3> x;
  std::array<double, 3> f{std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::infinity()};

  void offer(std::span<const double> point, double fitness) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (fitness < f[k]) {
        for (std::size_t m = 2; m > k; --m) {
          f[m] = f[m - 1];
          x[m] = x[m - 1];
        }
        f[k] = fitness;
        x[k].assign(point.begin(), point.end());
        return;
      }
    }
  }
};

}  // namespace

Summary gwo(const Problem& problem, const RunOptions& run, const GwoOptions& options) {
  validate(problem);
  validate(run, 3);
  validate(options);
  const std::size_t n = run.population, d = problem.dimension(), T = run.iterations;

  Rng rng(run.seed);
  detail::Run r(Algorithm::gwo, problem, run);
  std::vector<double> x = detail::uniform_points(problem, n, rng);
  std::vector<double> f(n);
  Leaders leaders;
  for (auto& l : leaders.x) l = x;  // placeholders until offered
  for (auto& l : leaders.x) l.resize(d);
  auto offer_all = [&] {
    for (std::size_t i = 0; i < n; ++i)
      leaders.offer(std::span<const double>(x.data() + i * d, d), f[i]);
  };
  r.evaluate(x, f);
  offer_all();
  if (!r.end_iteration(0, f)) return r.finish();

  for (std::size_t t = 1; t <= T; ++t) {
    // a falls linearly from a_start (first iteration) towards 0.
    const double a = options.a_start * (1.0 - static_cast<double>(t - 1) / static_cast<double>(T));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < d; ++j) {
        double sum = 0;
        for (std::size_t k = 0; k < 3; ++k) {
          const double r1 = rng.uniform(), r2 = rng.uniform();
          const double big_a = 2 * a * r1 - a;                                   // eq. (3.3)
          const double big_c = 2 * r2;                                           // eq. (3.4)
          const double dist = std::abs(big_c * leaders.x[k][j] - x[i * d + j]);  // eq. (3.5)
          sum += leaders.x[k][j] - big_a * dist;                                 // eq. (3.6)
        }
        x[i * d + j] = sum / 3.0;  // eq. (3.7)
      }
      detail::clip(std::span<double>(x.data() + i * d, d), problem);
    }
    r.evaluate(x, f);
    offer_all();
    if (!r.end_iteration(t, f)) break;
  }
  return r.finish();
}

}  // namespace fogdrift::opt
