#include "fogdrift/signal/hampel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

TEST(Hampel, KappaIsTheInverseOfTheNormalThirdQuartile) {
  // Φ(0.6744897501960817) = 0.75, so κ = 1 / 0.6744897501960817.
  EXPECT_NEAR(kGaussianMadScale, 1.0 / 0.6744897501960817, 1e-15);
}

TEST(Hampel, ReplacesSpikesByTheirWindowMedianAndNothingElse) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(2000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.01 * static_cast<double>(i) + noise(rng);
  const std::vector<std::size_t> spikes = {0, 400, 1201, 1999};
  for (std::size_t i : spikes) x[i] += 40.0;
  const HampelResult r = hampel(x, {25, 6.0});
  EXPECT_EQ(r.replaced, spikes);
  for (std::size_t i : spikes) {
    // The median of the (truncated) window, sorted by hand.
    const std::size_t lo = i >= 25 ? i - 25 : 0, hi = std::min<std::size_t>(x.size() - 1, i + 25);
    std::vector<double> w(x.begin() + static_cast<std::ptrdiff_t>(lo),
                          x.begin() + static_cast<std::ptrdiff_t>(hi + 1));
    std::sort(w.begin(), w.end());
    const double median =
        w.size() % 2 ? w[w.size() / 2] : 0.5 * (w[w.size() / 2 - 1] + w[w.size() / 2]);
    EXPECT_DOUBLE_EQ(r.signal[i], median) << i;
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::binary_search(spikes.begin(), spikes.end(), i)) {
      EXPECT_EQ(r.signal[i], x[i]);
    }
  }
}

TEST(Hampel, DefaultsLeavePlainGaussianNoiseAlone) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> x(40000);
  for (double& v : x) v = noise(rng);
  EXPECT_EQ(hampel(x).replaced.size(), 0u);
  // The textbook 3σ over 11 samples replaces a few per cent of good samples (docs/signal.md).
  const double share = static_cast<double>(hampel(x, {5, 3.0}).replaced.size()) / 40000.0;
  EXPECT_GT(share, 0.02);
  EXPECT_LT(share, 0.035);
}

TEST(Hampel, KeepsTheStepsOfAQuantisedThermometer) {
  // A slow warm-up read with 0.0625 °C resolution: flat runs and single-count steps.
  std::vector<double> x;
  for (int step = 0; step < 20; ++step)
    for (int k = 0; k < 30; ++k) x.push_back(20.0 + 0.0625 * step);
  x[315] = 85.0;  // a bus glitch
  const HampelResult r = hampel(x, {5, 3.0});
  ASSERT_EQ(r.replaced.size(), 1u);
  EXPECT_EQ(r.replaced[0], 315u);
  EXPECT_DOUBLE_EQ(r.signal[315], 20.0 + 0.0625 * 10);
}

TEST(Hampel, RejectsImpossibleOptions) {
  const std::vector<double> x = {1, 2, 3};
  EXPECT_THROW(hampel(x, {0, 3.0}), OptionError);
  try {
    hampel(x, {3, -1.0});
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "n_sigma");
  }
}

}  // namespace
}  // namespace fogdrift::signal
