#include "fogdrift/base/random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fogdrift {
namespace {

TEST(Rng, SameSeedSameStream) {
  Rng a(7), b(7), c(8);
  bool differs = false;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.next_u64();
    ASSERT_EQ(x, b.next_u64());
    differs |= x != c.next_u64();
  }
  EXPECT_TRUE(differs);
}

TEST(Rng, MatchesAnIndependentXoshiro256StarStarWithSplitmixSeeding) {
  // Reference values from a separate Python transcription of xoshiro256** (Blackman & Vigna)
  // seeded by four splitmix64 outputs of the seed. A change here changes every simulated campaign.
  Rng rng(1);
  EXPECT_EQ(rng.next_u64(), 0xc5883e370b0926c3ULL);
  EXPECT_EQ(rng.next_u64(), 0x021b74b80f71f81cULL);
  EXPECT_EQ(rng.next_u64(), 0x268df06749e5c8ceULL);
  EXPECT_NE(derive_seed(1, 0), derive_seed(1, 1));
  EXPECT_NE(derive_seed(1, 0), derive_seed(2, 0));
}

TEST(Rng, NormalHasUnitMomentsAndGaussianTails) {
  Rng rng(123);
  const int n = 400000;
  double sum = 0, sum2 = 0, sum4 = 0;
  int beyond3 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.normal();
    sum += x;
    sum2 += x * x;
    sum4 += x * x * x * x;
    beyond3 += std::abs(x) > 3.0;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.0, 5.0 / std::sqrt(n));
  EXPECT_NEAR(var, 1.0, 0.01);
  EXPECT_NEAR(sum4 / n, 3.0, 0.05);                     // kurtosis of a Gaussian
  EXPECT_NEAR(beyond3 / double(n), 0.0026998, 0.0005);  // P(|x| > 3)
}

TEST(Rng, UniformIsUniform) {
  Rng rng(5);
  int bins[10] = {};
  const int n = 100000;
  for (int i = 0; i < n; ++i) ++bins[static_cast<int>(rng.uniform() * 10)];
  for (int b : bins) EXPECT_NEAR(b, n / 10, 5 * std::sqrt(n / 10.0));
}

}  // namespace
}  // namespace fogdrift
