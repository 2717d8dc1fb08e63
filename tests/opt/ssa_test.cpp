// SSA's update rules, checked from the points it asks to evaluate (Xue & Shen 2020 eq. 3–5).
#include "fogdrift/opt/ssa.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fogdrift::opt {
namespace {

struct Batches {
  std::vector<std::vector<double>> points;
  std::vector<std::vector<double>> fitness;
};

Problem sphere_recorder(Batches& b, std::size_t d, double lo, double hi) {
  Problem p;
  p.lower.assign(d, lo);
  p.upper.assign(d, hi);
  p.evaluate = [&b, d](std::span<const double> x, std::span<double> f) {
    for (std::size_t i = 0; i < f.size(); ++i) {
      double s = 0;
      for (std::size_t j = 0; j < d; ++j) s += (x[i * d + j] - 0.3) * (x[i * d + j] - 0.3);
      f[i] = s;
    }
    b.points.emplace_back(x.begin(), x.end());
    b.fitness.emplace_back(f.begin(), f.end());
  };
  return p;
}

// With ST = 1 every iteration forages (R2 < 1): eq. (3) multiplies the rank-k producer's
// position by exp(−k/(α·T)) ∈ (0, exp(−k/T)], the same factor in every coordinate.
TEST(Ssa, ProducersContractTowardsTheOriginByEquation3) {
  Batches b;
  const std::size_t d = 3, n = 20, T = 10;
  const Problem p = sphere_recorder(b, d, -10, 10);
  RunOptions run;
  run.population = n;
  run.iterations = T;
  run.seed = 3;
  SsaOptions o;
  o.safety_threshold = 1.0;
  const Summary s = ssa(p, run, o);
  ASSERT_GE(b.points.size(), 2u);
  const auto& init = b.points[0];
  const auto& f0 = b.fitness[0];
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto c) { return f0[a] < f0[c]; });
  const auto& producers = b.points[1];
  ASSERT_EQ(producers.size(), 4 * d);  // PD = 0.2 of 20
  for (std::size_t k = 0; k < 4; ++k) {
    const double* x = init.data() + order[k] * d;
    const double* y = producers.data() + k * d;
    const double factor = y[0] / x[0];
    EXPECT_GT(factor, 0.0);
    EXPECT_LE(factor, std::exp(-static_cast<double>(k + 1) / T) * (1 + 1e-12)) << "rank " << k + 1;
    for (std::size_t j = 1; j < d; ++j) EXPECT_NEAR(y[j], factor * x[j], 1e-12 * std::abs(x[j]));
  }
  for (const auto& [name, count] : s.counters) {
    if (name == "producer_alarm") {
      EXPECT_EQ(count, 0);
    }
    if (name == "producer_forage") {
      EXPECT_EQ(count, static_cast<std::int64_t>(4 * T));
    }
  }
}

// Every rule of eq. (3)–(5) fires in an ordinary run, the f_i = f_g scout branch included.
TEST(Ssa, EveryBranchIsReached) {
  Batches b;
  const Problem p = sphere_recorder(b, 2, -5, 5);
  RunOptions run;
  run.iterations = 100;
  const Summary s = ssa(p, run);
  ASSERT_EQ(s.counters.size(), 6u);
  for (const auto& [name, count] : s.counters) EXPECT_GT(count, 0) << name;
  // 20 sparrows: 4 producers, 16 scroungers of which ranks 11–20 starve, 2 scouts.
  for (const auto& [name, count] : s.counters) {
    if (name == "scrounger_starving") {
      EXPECT_EQ(count, 10 * 100);
    }
    if (name == "scrounger_follow") {
      EXPECT_EQ(count, 6 * 100);
    }
    if (name == "scout_toward_best" || name == "scout_away_from_worst") {
      EXPECT_LE(count, 200);
    }
  }
  EXPECT_LT(s.best_fitness, 1e-6);
}

// Following scroungers move every coordinate by the same amount from x_P (A⁺ = Aᵀ/d, eq. 4).
TEST(Ssa, FollowingScroungersShiftEveryCoordinateEqually) {
  Batches b;
  const std::size_t d = 4, n = 20;
  const Problem p = sphere_recorder(b, d, -100, 100);
  RunOptions run;
  run.population = n;
  run.iterations = 1;
  ssa(p, run);
  const auto& producers = b.points[1];
  const auto& pf = b.fitness[1];
  const std::size_t best =
      static_cast<std::size_t>(std::min_element(pf.begin(), pf.end()) - pf.begin());
  const double* xp = producers.data() + best * d;
  const auto& scroungers = b.points[2];  // ranks 5..20 in order; ranks 5..10 follow
  for (std::size_t k = 0; k < 6; ++k) {
    const double* y = scroungers.data() + k * d;
    const double step = y[0] - xp[0];
    for (std::size_t j = 1; j < d; ++j) EXPECT_NEAR(y[j] - xp[j], step, 1e-9) << "rank " << k + 5;
  }
}

}  // namespace
}  // namespace fogdrift::opt
