#include "fogdrift/model/guard.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"

namespace fogdrift {
namespace {

// Farthest-point sampling on 0, 1, …, 10 (one dimension) with three prototypes picks 0, then 10,
// then 5 (the farthest from {0, 10}); the cover radius is then 2.
TEST(NoveltyGuard, FarthestPointsAndCoverRadiusInClosedForm) {
  std::vector<double> z;
  for (int i = 0; i <= 10; ++i) z.push_back(i);
  GuardSettings s;
  s.prototypes = 3;
  const NoveltyGuard g = NoveltyGuard::fit(z, 1, {}, {}, s);
  EXPECT_EQ(g.prototypes, (std::vector<double>{0, 10, 5}));
  EXPECT_DOUBLE_EQ(g.radius, 2.0);  // 2 → 0 is 2, 3 → 5 is 2, 7 → 5 is 2, 8 → 10 is 2
  const double outside[] = {16.0};
  EXPECT_DOUBLE_EQ(g.novelty(outside), 3.0);  // 6 from 10, over r = 2
}

// During the differentiator's warm-up ν leaves out the inputs that read a rate (guard.hpp,
// "Warm-up"): prototypes (0, 0) and (10, 0), r = 1 (one prototype each, no labels: the radius
// floor, set here by hand), input 1 a rate. (3, 4) is 5 from (0, 0) in full and 3 without the
// rate; (12, −100) is 2 from (10, 0) without it.
TEST(NoveltyGuard, WarmingUpLeavesTheRatesOut) {
  NoveltyGuard g;
  g.dims = 2;
  g.prototypes = {0, 0, 10, 0};
  g.radius = 1;
  g.set_warmup_inputs({false, true});
  ASSERT_EQ(g.warmup_inputs, (std::vector<unsigned char>{1, 0}));
  const double a[] = {3, 4}, b[] = {12, -100};
  EXPECT_DOUBLE_EQ(g.novelty(a), 5.0);
  EXPECT_DOUBLE_EQ(g.novelty(a, true), 3.0);
  EXPECT_DOUBLE_EQ(g.novelty(b, true), 2.0);
  EXPECT_GT(g.novelty(b), 99.0);
  // Without a mask (a model of no rate inputs, or none set), warming changes nothing.
  g.warmup_inputs.clear();
  EXPECT_DOUBLE_EQ(g.novelty(a, true), 5.0);
}

TEST(NoveltyGuard, EveryTrainingRowIsInside) {
  Rng rng(7);
  std::vector<double> z(3000 * 4);
  for (double& v : z) v = rng.normal();
  const NoveltyGuard g = NoveltyGuard::fit(z, 4, {}, {});
  EXPECT_EQ(g.size(), 256u);
  for (std::size_t i = 0; i < 3000; ++i)
    ASSERT_LE(g.novelty(std::span<const double>(z.data() + 4 * i, 4)), 1.0 + 1e-12) << i;
  const double far[] = {8, 8, 8, 8};
  EXPECT_GT(g.novelty(far), 3.0);
}

// The unit follows the labels' spacing: two parallel lines 4 apart, one per label, each sampled
// every 0.01: every row's nearest row of the other label is 4 away, so r = 4 (and not the cover
// radius of the prototypes), and a point midway between the lines has ν = 0.5.
TEST(NoveltyGuard, UnitIsTheSpacingBetweenLabels) {
  std::vector<double> z;
  std::vector<std::size_t> labels;
  for (std::size_t line = 0; line < 2; ++line)
    for (int i = 0; i <= 100; ++i) {
      z.push_back(0.01 * i);
      z.push_back(4.0 * static_cast<double>(line));
      labels.push_back(line);
    }
  const NoveltyGuard g = NoveltyGuard::fit(z, 2, labels, {});
  EXPECT_DOUBLE_EQ(g.radius, 4.0);
  const double midway[] = {0.5, 2.0};
  EXPECT_DOUBLE_EQ(g.novelty(midway), 0.5);
  EXPECT_THROW(NoveltyGuard::fit(z, 2, std::span<const std::size_t>(labels).first(3), {}),
               OptionError);
}

// The unit also follows the spacing of the start-up conditions calibrated at one temperature:
// two labels 4 apart, and at each label two conditions (repetitions) 6 apart, so r = 6 and a
// start-up between two calibrated conditions is familiar. Conditions that coincide (the paper's
// protocol: every repetition alike) leave r at the labels' spacing.
TEST(NoveltyGuard, UnitIsAlsoTheSpacingBetweenConditions) {
  auto lines = [](double condition_gap) {
    std::vector<double> z;
    std::vector<std::size_t> labels, conditions;
    for (std::size_t label = 0; label < 2; ++label)
      for (std::size_t condition = 0; condition < 2; ++condition)
        for (int i = 0; i <= 100; ++i) {
          z.push_back(0.01 * i);
          z.push_back(4.0 * static_cast<double>(label));
          z.push_back(condition_gap * static_cast<double>(condition));
          labels.push_back(label);
          conditions.push_back(condition);
        }
    return NoveltyGuard::fit(z, 3, labels, conditions, {});
  };
  EXPECT_DOUBLE_EQ(lines(6.0).radius, 6.0);
  EXPECT_DOUBLE_EQ(lines(0.0).radius, 4.0);
  // One label: the cover radius, whatever the conditions.
  std::vector<double> one;
  for (int i = 0; i <= 100; ++i) one.insert(one.end(), {0.01 * i, 0.0, 0.0, 0.01 * i, 0.0, 6.0});
  const std::vector<std::size_t> same(202, 0);
  std::vector<std::size_t> two(202);
  for (std::size_t i = 0; i < 202; ++i) two[i] = i % 2;
  EXPECT_LT(NoveltyGuard::fit(one, 3, same, two, {}).radius, 1.0);
  const std::vector<double> z(6, 0.0);
  const std::vector<std::size_t> labels = {0, 1}, conditions = {0};
  EXPECT_THROW(NoveltyGuard::fit(z, 3, labels, conditions, {}), OptionError);
}

TEST(NoveltyGuard, PolicyIsFullThenLinearThenNone) {
  NoveltyGuard g;
  g.settings.full_at = 1;
  g.settings.zero_at = 2;
  EXPECT_EQ(g.target_weight(0.5), 1.0);
  EXPECT_EQ(g.target_weight(1.0), 1.0);
  EXPECT_DOUBLE_EQ(g.target_weight(1.25), 0.75);
  EXPECT_EQ(g.target_weight(2.0), 0.0);
  EXPECT_EQ(g.target_weight(50.0), 0.0);
  EXPECT_EQ(g.target_weight(std::nan("")), 0.0);
}

// The weight falls at once and recovers by at most dt / recover_s per sample.
TEST(GuardFilter, FallsAtOnceRecoversAtItsRate) {
  GuardFilter f;
  EXPECT_EQ(f.update(0.0, 1.0, 100.0), 1.0);
  EXPECT_EQ(f.update(1.0, 0.0, 100.0), 0.0);
  EXPECT_DOUBLE_EQ(f.update(2.0, 1.0, 100.0), 0.01);
  EXPECT_DOUBLE_EQ(f.update(12.0, 1.0, 100.0), 0.11);
  EXPECT_DOUBLE_EQ(f.update(13.0, 0.05, 100.0), 0.05);
  EXPECT_DOUBLE_EQ(f.update(12.0, 1.0, 100.0), 0.05);  // time going back: no recovery
  f.reset();
  EXPECT_EQ(f.update(500.0, 0.3, 100.0), 0.3);
  // recover_s = 0: latched at its lowest until reset.
  f.reset();
  EXPECT_EQ(f.update(0.0, 0.4, 0.0), 0.4);
  EXPECT_EQ(f.update(1000.0, 1.0, 0.0), 0.4);
  EXPECT_EQ(f.update(2000.0, 0.1, 0.0), 0.1);
}

TEST(NoveltyGuard, NotANumberStopsTheCorrection) {
  std::vector<double> z = {0, 1, 2, 3};
  const NoveltyGuard g = NoveltyGuard::fit(z, 1, {}, {});
  const double nan[] = {std::nan("")};
  EXPECT_FALSE(std::isfinite(g.novelty(nan)));  // no prototype is nearer than infinity
  EXPECT_EQ(g.target_weight(g.novelty(nan)), 0.0);
}

TEST(NoveltyGuard, RejectsImpossibleSettings) {
  auto option_of = [](GuardSettings s) {
    try {
      validate(s);
    } catch (const OptionError& e) {
      return e.option();
    }
    return std::string("(none)");
  };
  GuardSettings s;
  s.prototypes = 0;
  EXPECT_EQ(option_of(s), "guard.prototypes");
  s = {};
  s.full_at = 0;
  EXPECT_EQ(option_of(s), "guard.full_at");
  s = {};
  s.zero_at = s.full_at;
  EXPECT_EQ(option_of(s), "guard.zero_at");
  s = {};
  s.recover_s = -1;
  EXPECT_EQ(option_of(s), "guard.recover_s");
}

}  // namespace
}  // namespace fogdrift
