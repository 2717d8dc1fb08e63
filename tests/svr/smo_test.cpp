// What both solver layouts share (src/svr/smo.hpp): the two-variable step against the minimum
// of its one-dimensional quadratic, computed apart; ρ; the warm-start scaling; the iteration
// limit. The loop itself is checked through both layouts in pair_solver_test and svr_test.
#include "svr/smo.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>

#include "fogdrift/base/random.hpp"

namespace fogdrift::svr::detail {
namespace {

TEST(TwoVariableStep, ReachesTheClippedMinimumAlongTheConstraintLine) {
  // Keeping y_i·α_i + y_j·α_j fixed leaves one direction: (δ, δ) when the signs differ,
  // (−δ, δ) when they agree. Along it the dual is ½·quad·δ² + b·δ with b = G_i + G_j or
  // G_j − G_i, whose minimum over the δ that keep both variables in [0, C] is −b/quad clipped
  // to that interval.
  Rng rng(11);
  int clipped = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    // Half the pairs with equal bounds, half with sample weights that differ.
    const double c_i = rng.uniform(0.1, 10);
    const double c_j = rng.uniform(0, 1) < 0.5 ? c_i : rng.uniform(0.1, 10);
    auto any_alpha = [&](double c) {
      const double u = rng.uniform(0, 1);
      return u < 0.2 ? 0.0 : (u < 0.4 ? c : rng.uniform(0, c));  // bounds are common
    };
    const double a_i = any_alpha(c_i), a_j = any_alpha(c_j);
    const int y_i = rng.uniform(0, 1) < 0.5 ? 1 : -1, y_j = rng.uniform(0, 1) < 0.5 ? 1 : -1;
    const double g_i = rng.uniform(-3, 3), g_j = rng.uniform(-3, 3);
    const double quad = rng.uniform(0.01, 4);
    const bool apart = y_i != y_j;
    const double b = apart ? g_i + g_j : g_j - g_i;
    // δ keeps α_j + δ in [0, C_j], and α_i + δ (apart) or α_i − δ (together) in [0, C_i].
    const double lo = apart ? std::max(-a_i, -a_j) : std::max(a_i - c_i, -a_j);
    const double hi = apart ? std::min(c_i - a_i, c_j - a_j) : std::min(a_i, c_j - a_j);
    const double delta = std::clamp(-b / quad, lo, hi);
    if (delta != -b / quad) ++clipped;
    double new_i = a_i, new_j = a_j;
    two_variable_step(new_i, new_j, y_i, y_j, g_i, g_j, quad, c_i, c_j);
    const double tol = 1e-12 * (1 + c_i + c_j);
    ASSERT_NEAR(new_j, a_j + delta, tol) << "trial " << trial;
    ASSERT_NEAR(new_i, apart ? a_i + delta : a_i - delta, tol) << "trial " << trial;
    // In the box, to rounding: LIBSVM sets α_i = C_j + diff, which may pass C_i by an ulp when
    // the bounds differ (its status test α ≥ C then reads it as at the bound).
    ASSERT_GE(new_i, 0);
    ASSERT_LE(new_i, c_i + tol);
    ASSERT_GE(new_j, 0);
    ASSERT_LE(new_j, c_j + tol);
  }
  EXPECT_GT(clipped, 5000);  // the clipping branches were exercised
}

TEST(TwoVariableStep, ANonPositiveCurvatureBecomesTau) {
  double a_i = 0.5, a_j = 0.5;
  two_variable_step(a_i, a_j, 1, -1, -1e-13, 0, 0.0, 1.0, 1.0);  // δ = 1e-13 / τ = 0.1
  EXPECT_NEAR(a_i, 0.6, 1e-15);
  EXPECT_NEAR(a_j, 0.6, 1e-15);
}

TEST(RhoBounds, MeanOfTheFreeOrMidpointOfTheBounds) {
  RhoBounds free;
  free.add(1.0, true, Bound::free);
  free.add(2.0, false, Bound::free);
  free.add(100.0, true, Bound::upper);  // bounds do not count when some variable is free
  EXPECT_EQ(free.rho(), 1.5);
  // None free: y·G of an upper-bound variable with y = −1, or a lower-bound one with y = +1, is
  // an upper bound on ρ; the other two cases are lower bounds.
  RhoBounds bound;
  bound.add(3.0, false, Bound::upper);   // ub 3
  bound.add(5.0, true, Bound::lower);    // ub stays 3
  bound.add(-1.0, true, Bound::upper);   // lb −1
  bound.add(-4.0, false, Bound::lower);  // lb stays −1
  EXPECT_EQ(bound.rho(), 1.0);
}

TEST(WarmAlpha, ScalesInsideTheBoxAndKeepsTheBounds) {
  EXPECT_EQ(warm_alpha(0.0, 2.0, 8.0), 0.0);
  EXPECT_EQ(warm_alpha(2.0, 2.0, 8.0), 8.0);  // at C_prev: at the new C
  EXPECT_EQ(warm_alpha(0.5, 2.0, 8.0), 2.0);  // scaled by C/C_prev
  EXPECT_EQ(warm_alpha(1.5, 2.0, 0.5), 0.375);
  EXPECT_EQ(warm_alpha(-1e-300, 2.0, 8.0), 0.0);
}

TEST(IterationLimit, LibsvmsDefaultOrTheOneAskedFor) {
  EXPECT_EQ(iteration_limit(0, 10), 10000000);      // max(10⁷, 100·2l)
  EXPECT_EQ(iteration_limit(0, 100000), 20000000);  // 100·2l
  EXPECT_EQ(iteration_limit(0, std::size_t{1} << 30), INT_MAX);
  EXPECT_EQ(iteration_limit(25, 100000), 25);
}

}  // namespace
}  // namespace fogdrift::svr::detail
