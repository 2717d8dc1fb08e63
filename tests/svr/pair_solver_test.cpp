// The pair solver (src/svr/pair_solver.cpp) checked against the dual it solves, computed here
// independently: the returned gradient is Qα + p, the solution is feasible, the optimality
// conditions hold to the tolerance, ρ is LIBSVM's, and every option (shrinking, conjugate steps,
// rows in order) reaches the same optimum. Its agreement with LIBSVM itself is in svr_test.
#include "svr/pair_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "svr/datasets.hpp"

namespace fogdrift::svr {
namespace {

struct Problem {
  const char* name;
  Data data;
  Kernel kernel;
  double c, epsilon;
};

std::vector<Problem> problems() {
  return {
      {"startup-like, C = 1", testing::startup_like(400, 2), Kernel::rbf_sigma(1.0), 1.0, 0.1},
      {"startup-like, C = 100", testing::startup_like(400, 3), Kernel::rbf_sigma(0.5), 100.0, 0.05},
      {"smooth, linear kernel", testing::smooth(300, 4, 0.1, 4), Kernel::linear(), 10.0, 0.1},
      {"smooth, wide RBF, ε = 0", testing::smooth(250, 3, 0.05, 5), Kernel::rbf_sigma(3.0), 10.0,
       0.0}};
}

// The dual in LIBSVM's layout, from the kernel rows as the solver sees them (floats): index t < l
// is α⁺_t (y = +1, p = ε − z_t), t ≥ l is α⁻ (y = −1, p = ε + z_t).
struct Dual {
  std::size_t l;
  std::vector<std::vector<float>> k;  // l × l
  std::vector<double> z;
  double epsilon;
  int y(std::size_t t) const { return t < l ? 1 : -1; }
  double p(std::size_t t) const { return t < l ? epsilon - z[t] : epsilon + z[t - l]; }
  double q(std::size_t s, std::size_t t) const {
    return y(s) * y(t) * static_cast<double>(k[s % l][t % l]);
  }
};

Dual dual_of(const TrainingSet& set, const Kernel& kernel, double epsilon) {
  Dual d{set.size(), {}, set.data().y, epsilon};
  d.k.assign(d.l, std::vector<float>(d.l));
  for (std::size_t i = 0; i < d.l; ++i) set.kernel_row(kernel, i, d.k[i].data());
  return d;
}

struct Check {
  double max_gradient_error = 0, max_violation = 0, equality = 0, objective = 0, rho = 0;
  bool in_box = true;
};

Check check(const Dual& d, const DualSolution& s, double c) {
  Check out;
  const std::size_t n = 2 * d.l;
  std::vector<double> g(n);
  double quad = 0, linear = 0;
  for (std::size_t t = 0; t < n; ++t) {
    double qa = 0;
    for (std::size_t u = 0; u < n; ++u)
      if (s.alpha[u] != 0) qa += d.q(t, u) * s.alpha[u];
    g[t] = qa + d.p(t);
    quad += s.alpha[t] * qa;
    linear += d.p(t) * s.alpha[t];
    out.max_gradient_error =
        std::max(out.max_gradient_error, std::abs(g[t] - s.gradient[t]) / (1 + std::abs(g[t])));
    out.equality += d.y(t) * s.alpha[t];
    out.in_box = out.in_box && s.alpha[t] >= 0 && s.alpha[t] <= c;
  }
  out.objective = quad / 2 + linear;
  // LIBSVM's optimality test: max over I_up of −y·G against min over I_low.
  double m = -DBL_MAX, big_m = DBL_MAX, free_sum = 0;
  std::size_t free = 0;
  for (std::size_t t = 0; t < n; ++t) {
    const double v = -d.y(t) * g[t];
    const bool up = d.y(t) > 0 ? s.alpha[t] < c : s.alpha[t] > 0;
    const bool low = d.y(t) > 0 ? s.alpha[t] > 0 : s.alpha[t] < c;
    if (up) m = std::max(m, v);
    if (low) big_m = std::min(big_m, v);
    if (s.alpha[t] > 0 && s.alpha[t] < c) {
      free_sum += d.y(t) * g[t];
      ++free;
    }
  }
  out.max_violation = m - big_m;
  out.rho = free > 0 ? free_sum / static_cast<double>(free) : (m + big_m) / -2;
  return out;
}

DualSolution solve(const TrainingSet& set, const Problem& p, const SolverOptions& options,
                   SolverSummary* summary = nullptr, const DualSolution* warm = nullptr) {
  KernelCache q(set, p.kernel, 0);
  DualSolution out;
  const SolverSummary s = detail::solve_pairs(q, set.data().y, p.c, p.epsilon, options, out, warm);
  if (summary != nullptr) *summary = s;
  out.c = p.c;
  out.epsilon = p.epsilon;
  out.kernel = p.kernel;
  return out;
}

TEST(PairSolver, ReturnsAFeasibleOptimumWithItsTrueGradientAndRho) {
  for (const Problem& p : problems()) {
    SCOPED_TRACE(p.name);
    const TrainingSet set(p.data);
    const Dual d = dual_of(set, p.kernel, p.epsilon);
    SolverOptions options;
    SolverSummary summary;
    const DualSolution s = solve(set, p, options, &summary);
    ASSERT_EQ(summary.status, SolverStatus::optimal);
    const Check c = check(d, s, p.c);
    EXPECT_TRUE(c.in_box);
    EXPECT_LT(std::abs(c.equality), 1e-9 * p.c * static_cast<double>(d.l));
    EXPECT_LT(c.max_gradient_error, 1e-9);
    EXPECT_LT(c.max_violation, options.tolerance + 1e-9);
    EXPECT_NEAR(summary.objective, c.objective, 1e-9 * (1 + std::abs(c.objective)));
    EXPECT_NEAR(summary.rho, c.rho, 1e-9 * (1 + std::abs(c.rho)));
  }
}

TEST(PairSolver, EveryOptionReachesTheSameOptimum) {
  // Shrinking, conjugate steps, Newton steps and rows computed in order change the path, not the
  // problem: at a tight tolerance the objectives agree to about that tolerance.
  std::int64_t newton_steps = 0;
  for (const Problem& p : problems()) {
    SCOPED_TRACE(p.name);
    const TrainingSet set(p.data);
    const Dual d = dual_of(set, p.kernel, p.epsilon);
    SolverOptions base;
    base.tolerance = 1e-6;
    SolverSummary summary;
    const double reference = check(d, solve(set, p, base, &summary), p.c).objective;
    newton_steps += summary.newton_steps;
    for (int variant = 0; variant < 4; ++variant) {
      SolverOptions o = base;
      if (variant == 0) o.shrinking = false;
      if (variant == 1) o.conjugate = false;
      if (variant == 2) o.rows_in_order = false;
      if (variant == 3) o.newton = false;
      SCOPED_TRACE(variant);
      const Check c = check(d, solve(set, p, o), p.c);
      EXPECT_LT(c.max_violation, o.tolerance + 1e-9);
      EXPECT_NEAR(c.objective, reference, 1e-6 * (1 + std::abs(reference)));
    }
  }
  EXPECT_GT(newton_steps, 0);  // the Newton variant differs from the default somewhere
}

TEST(PairSolver, AWarmStartFromItsOwnOptimumIsAlreadyOptimal) {
  for (const Problem& p : problems()) {
    SCOPED_TRACE(p.name);
    const TrainingSet set(p.data);
    SolverOptions options;
    SolverSummary first, again;
    const DualSolution s = solve(set, p, options, &first);
    const DualSolution t = solve(set, p, options, &again, &s);
    EXPECT_TRUE(again.gradient_reused);
    EXPECT_LE(again.iterations, 2) << "from " << first.iterations;
    EXPECT_NEAR(again.objective, first.objective, 1e-9 * (1 + std::abs(first.objective)));
    EXPECT_EQ(t.alpha.size(), s.alpha.size());
  }
}

}  // namespace
}  // namespace fogdrift::svr
