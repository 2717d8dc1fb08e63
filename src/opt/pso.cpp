#include "fogdrift/opt/pso.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/error.hpp"
#include "opt/population.hpp"

namespace fogdrift::opt {

void validate(const PsoOptions& options) {
  auto non_negative = [](double v, const char* name) {
    if (!(v >= 0 && std::isfinite(v)))
      throw OptionError(name, fmt::format("{} must be finite and ≥ 0", v));
  };
  non_negative(options.inertia_start, "inertia_start");
  non_negative(options.inertia_end, "inertia_end");
  non_negative(options.cognitive, "cognitive");
  non_negative(options.social, "social");
  if (!(options.max_velocity_fraction > 0 && options.max_velocity_fraction <= 1))
    throw OptionError("max_velocity_fraction",
                      fmt::format("{} is outside (0, 1]", options.max_velocity_fraction));
}

Summary pso(const Problem& problem, const RunOptions& run, const PsoOptions& options) {
  validate(problem);
  validate(run, 2);
  validate(options);
  const std::size_t n = run.population, d = problem.dimension(), T = run.iterations;
  std::vector<double> v_max(d);
  for (std::size_t j = 0; j < d; ++j)
    v_max[j] = options.max_velocity_fraction * (problem.upper[j] - problem.lower[j]);

  Rng rng(run.seed);
  detail::Run r(Algorithm::pso, problem, run);
  std::vector<double> x = detail::uniform_points(problem, n, rng);
  std::vector<double> v(n * d);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < d; ++j) v[i * d + j] = rng.uniform(-v_max[j], v_max[j]);
  std::vector<double> f(n);
  r.evaluate(x, f);
  std::vector<double> personal = x, personal_f = f;
  if (!r.end_iteration(0, personal_f)) return r.finish();

  for (std::size_t t = 1; t <= T; ++t) {
    const double progress = T > 1 ? static_cast<double>(t - 1) / static_cast<double>(T - 1) : 0.0;
    const double w =
        options.inertia_start + (options.inertia_end - options.inertia_start) * progress;
    const std::vector<double> g(r.best_point().begin(), r.best_point().end());
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < d; ++j) {
        const std::size_t k = i * d + j;
        const double r1 = rng.uniform(), r2 = rng.uniform();
        double vk = w * v[k] + options.cognitive * r1 * (personal[k] - x[k]) +
                    options.social * r2 * (g[j] - x[k]);  // S&E eq. (1)
        vk = std::min(std::max(vk, -v_max[j]), v_max[j]);
        double xk = x[k] + vk;  // S&E eq. (2)
        if (xk < problem.lower[j] || xk > problem.upper[j]) {
          xk = std::min(std::max(xk, problem.lower[j]), problem.upper[j]);
          vk = 0;
        }
        x[k] = xk;
        v[k] = vk;
      }
    }
    r.evaluate(x, f);
    for (std::size_t i = 0; i < n; ++i)
      if (f[i] < personal_f[i]) {
        personal_f[i] = f[i];
        std::copy_n(x.begin() + static_cast<std::ptrdiff_t>(i * d), d,
                    personal.begin() + static_cast<std::ptrdiff_t>(i * d));
      }
    if (!r.end_iteration(t, personal_f)) break;
  }
  return r.finish();
}

}  // namespace fogdrift::opt
