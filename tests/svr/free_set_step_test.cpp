// The free-set Newton step (src/svr/free_set_step.cpp) against references computed here
// independently: the closed-form minimum of the equality-constrained quadratic (a bordered linear
// system, solved by full-pivoting LU) when no bound is met, and the exact minimum over the box
// (every assignment of the variables to a bound or the inside, enumerated) when bounds are met.
#include "svr/free_set_step.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <random>

namespace fogdrift::svr::detail {
namespace {

// A positive definite kernel block: an RBF kernel of random points, as the solver sees it.
Eigen::MatrixXd rbf_block(int m, double sigma, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd x(m, 3);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < 3; ++j) x(i, j) = normal(rng);
  Eigen::MatrixXd k(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      k(i, j) = std::exp(-(x.row(i) - x.row(j)).squaredNorm() / (2 * sigma * sigma));
  return k;
}

double objective(const Eigen::MatrixXd& k, const Eigen::VectorXd& r, const Eigen::VectorXd& d) {
  return r.dot(d) + 0.5 * d.dot(k * d);
}

// The minimum of rᵀΔ + ½ΔᵀKΔ subject to ΣΔ = 0 and Δ_i = fixed_i where `fixed` says so.
Eigen::VectorXd constrained_minimum(const Eigen::MatrixXd& k, const Eigen::VectorXd& r,
                                    const std::vector<int>& where, const Eigen::VectorXd& lo,
                                    const Eigen::VectorXd& hi) {
  const int m = static_cast<int>(k.rows());
  Eigen::VectorXd d = Eigen::VectorXd::Zero(m);
  std::vector<int> free;
  for (int i = 0; i < m; ++i) {
    if (where[i] < 0) d[i] = lo[i];
    if (where[i] > 0) d[i] = hi[i];
    if (where[i] == 0) free.push_back(i);
  }
  const int n = static_cast<int>(free.size());
  if (n == 0) return d;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 1, n + 1);
  Eigen::VectorXd b(n + 1);
  const Eigen::VectorXd g = r + k * d;  // the gradient with the fixed part in place
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) a(i, j) = k(free[i], free[j]);
    a(i, n) = a(n, i) = 1;
    b[i] = -g[free[i]];
  }
  b[n] = -d.sum();
  const Eigen::VectorXd s = a.fullPivLu().solve(b);
  for (int i = 0; i < n; ++i) d[free[i]] = s[i];
  return d;
}

TEST(FreeSetStep, WithoutBoundsItIsTheEqualityConstrainedMinimum) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    // Narrow kernels give well-conditioned blocks, wide ones the nearly singular blocks of the
    // paper's search, where the ridge (1e-7 of the diagonal) moves the step along directions
    // that barely change the objective.
    const bool narrow = trial % 2 == 0;
    const int m = 2 + trial;
    const Eigen::MatrixXd k = rbf_block(m, narrow ? 0.3 : 1.0, rng);
    Eigen::VectorXd r(m);
    for (int i = 0; i < m; ++i) r[i] = unit(rng);
    const Eigen::VectorXd lo = Eigen::VectorXd::Constant(m, -1e9), hi = -lo;
    const FreeSetStep step = free_set_step(k, r, lo, hi, m);
    const Eigen::VectorXd exact =
        constrained_minimum(k, r, std::vector<int>(static_cast<std::size_t>(m), 0), lo, hi);
    EXPECT_TRUE(step.moved);
    EXPECT_TRUE(step.reached_minimum);
    EXPECT_EQ(step.removals, 0u);
    EXPECT_LT(std::abs(step.delta.sum()), 1e-12 * (1 + step.delta.cwiseAbs().sum()));
    const double f_step = objective(k, r, step.delta), f_exact = objective(k, r, exact);
    EXPECT_GE(f_step, f_exact - 1e-12 * std::abs(f_exact));
    if (narrow) {
      EXPECT_LT((step.delta - exact).norm(), 1e-6 * exact.norm());
      EXPECT_LE(f_step - f_exact, 1e-12 * std::abs(f_exact));
    } else {
      EXPECT_LE(f_step - f_exact, 1e-4 * std::abs(f_exact));
    }
  }
}

TEST(FreeSetStep, WithBoundsItDescendsStaysFeasibleAndEndsOnTheBoxExactly) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-1, 1), room(0.01, 0.5);
  int reached = 0;
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE(trial);
    const int m = 2 + trial % 6;
    const Eigen::MatrixXd k = rbf_block(m, 1.5, rng);
    Eigen::VectorXd r(m), lo(m), hi(m);
    for (int i = 0; i < m; ++i) {
      r[i] = unit(rng);
      lo[i] = -room(rng);
      hi[i] = room(rng);
    }
    const FreeSetStep step = free_set_step(k, r, lo, hi, m);
    const Eigen::VectorXd& d = step.delta;
    EXPECT_LT(std::abs(d.sum()), 1e-12);
    for (int i = 0; i < m; ++i) {
      EXPECT_GE(d[i], lo[i]);
      EXPECT_LE(d[i], hi[i]);
      if (step.ends[i] == FreeSetEnd::lower) {
        EXPECT_EQ(d[i], lo[i]);
      }
      if (step.ends[i] == FreeSetEnd::upper) {
        EXPECT_EQ(d[i], hi[i]);
      }
    }
    EXPECT_LE(objective(k, r, d), 0.0);
    // Never below the exact minimum over the box, found by trying every assignment of the
    // variables to the lower bound, the upper bound or the inside.
    double best = std::numeric_limits<double>::infinity();
    std::vector<int> where(static_cast<std::size_t>(m));
    int count = 1;
    for (int i = 0; i < m; ++i) count *= 3;
    for (int code = 0; code < count; ++code) {
      for (int i = 0, c = code; i < m; ++i, c /= 3) where[i] = c % 3 - 1;
      const Eigen::VectorXd x = constrained_minimum(k, r, where, lo, hi);
      bool feasible = std::abs(x.sum()) < 1e-9;
      for (int i = 0; i < m; ++i) feasible &= x[i] >= lo[i] - 1e-12 && x[i] <= hi[i] + 1e-12;
      if (feasible) best = std::min(best, objective(k, r, x));
    }
    EXPECT_GE(objective(k, r, d), best - 1e-9 * (1 + std::abs(best)));
    // A step that ended inside is the minimum over the variables it left free.
    if (step.reached_minimum) {
      ++reached;
      std::vector<int> kept(static_cast<std::size_t>(m));
      for (int i = 0; i < m; ++i) kept[i] = static_cast<int>(step.ends[i]);
      const Eigen::VectorXd x = constrained_minimum(k, r, kept, lo, hi);
      EXPECT_LT((d - x).norm(), 1e-5 * (1 + x.norm()));
    }
  }
  EXPECT_GT(reached, 20);  // the comparison above is not vacuous
}

TEST(FreeSetStep, AtAnOptimumOrWithOneVariableItDoesNothing) {
  std::mt19937 rng(3);
  const Eigen::MatrixXd k = rbf_block(6, 1.0, rng);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(6, -1), hi = -lo;
  // A gradient equal on every variable is optimal under Σ Δ = 0: at most a rounding's step.
  const FreeSetStep optimal = free_set_step(k, Eigen::VectorXd::Constant(6, 0.3), lo, hi, 6);
  EXPECT_LT(optimal.delta.norm(), 1e-12);
  EXPECT_EQ(optimal.removals, 0u);
  const FreeSetStep one =
      free_set_step(k.topLeftCorner(1, 1), Eigen::VectorXd::Ones(1), lo.head(1), hi.head(1), 1);
  EXPECT_FALSE(one.moved);
  EXPECT_EQ(one.delta[0], 0.0);
}

TEST(FreeSetStep, TheRemovalBudgetIsKept) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unit(-1, 1);
  const int m = 12;
  const Eigen::MatrixXd k = rbf_block(m, 2.0, rng);
  Eigen::VectorXd r(m);
  for (int i = 0; i < m; ++i) r[i] = 5 * unit(rng);
  const Eigen::VectorXd lo = Eigen::VectorXd::Constant(m, -1e-3), hi = -lo;
  const FreeSetStep all = free_set_step(k, r, lo, hi, m);
  ASSERT_GT(all.removals, 2u);
  const FreeSetStep two = free_set_step(k, r, lo, hi, 2);
  EXPECT_EQ(two.removals, 2u);
  EXPECT_GE(objective(k, r, two.delta), objective(k, r, all.delta) - 1e-15);
}

}  // namespace
}  // namespace fogdrift::svr::detail
