// The field's measures (field.hpp): the share of the removable error removed on the RMSEs, and
// the drift's own error removed finding by finding, each against a closed form, and pooled over
// a simulated campaign's start-ups.
#include "fogdrift/eval/field.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::eval {
namespace {

TEST(Field, TheShareRemovedIsTheRemovableErrorsSquareThatGoes) {
  // raw 0.05°, floor 0.03°: 0.0016 removable; 0.04° compensated leaves 0.0007 of it.
  EXPECT_DOUBLE_EQ(share_removed(0.05, 0.04, 0.03), (0.0025 - 0.0016) / (0.0025 - 0.0009));
  EXPECT_DOUBLE_EQ(share_removed(0.05, 0.03, 0.03), 1.0);
  EXPECT_DOUBLE_EQ(share_removed(0.05, 0.05, 0.03), 0.0);
  EXPECT_LT(share_removed(0.05, 0.06, 0.03), 0.0);
  EXPECT_TRUE(std::isnan(share_removed(0.03, 0.02, 0.03)));  // nothing removable
  EXPECT_TRUE(std::isnan(share_removed(0.05, std::nan(""), 0.03)));
}

// Findings with a noise part n, a drift part d and what a model leaves of it e: raw = n + d,
// compensated = n + e, floor = n.
struct Findings {
  std::vector<double> raw, comp, floor;
};
Findings findings(const std::vector<double>& noise, const std::vector<double>& drift,
                  const std::vector<double>& left) {
  Findings f;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    f.raw.push_back(noise[i] + drift[i]);
    f.comp.push_back(noise[i] + left[i]);
    f.floor.push_back(noise[i]);
  }
  return f;
}

TEST(Field, TheDriftsOwnErrorRemovedPairsEachFindingWithItsFloor) {
  const Findings f = findings({0.02, -0.01, 0.005}, {0.01, 0.02, -0.02}, {0.005, -0.01, 0.0});
  // 1 − (0.005² + 0.01²) / (0.01² + 0.02² + 0.02²)
  EXPECT_NEAR(drift_error_removed(f.raw, f.comp, f.floor), 1 - 1.25e-4 / 9e-4, 1e-12);
  EXPECT_DOUBLE_EQ(drift_error_removed(f.raw, f.floor, f.floor), 1.0);     // the true drift
  EXPECT_DOUBLE_EQ(drift_error_removed(f.raw, f.raw, f.floor), 0.0);       // no compensation
  EXPECT_TRUE(std::isnan(drift_error_removed(f.floor, f.comp, f.floor)));  // no drift
  const std::vector<double> two(f.raw.begin(), f.raw.begin() + 2);
  EXPECT_THROW(drift_error_removed(two, f.comp, f.floor), std::invalid_argument);
}

TEST(Field, AFindingEitherSideOfTheAzimuthsWrapIsCloseToItsFloor) {
  // Errors either side of ±180° (a finding half a turn off): +179.99° and −179.99° are 0.02°
  // apart, not 359.98°.
  const std::vector<double> floor{179.99}, raw{-179.99}, comp{179.995};
  EXPECT_NEAR(drift_error_removed(raw, comp, floor), 1 - 0.005 * 0.005 / (0.02 * 0.02), 1e-9);
}

TEST(Field, TheFindingByFindingShareDoesNotMoveWithTheNoise) {
  // One drift and one model over 90 findings, under twenty noise draws ten times the drift's
  // size: the share on the RMSEs scatters with the noise, the paired one stays where the
  // model's error puts it, 1 − 0.5² = 0.75.
  const std::size_t n = 90;
  std::vector<double> drift(n), left(n);
  for (std::size_t i = 0; i < n; ++i) {
    drift[i] = 0.002 * std::cos(0.3 * static_cast<double>(i));
    left[i] = 0.5 * drift[i];
  }
  double lowest = 1, highest = -1;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Rng rng(seed);
    std::vector<double> noise(n);
    for (double& x : noise) x = 0.02 * rng.normal();
    const Findings f = findings(noise, drift, left);
    EXPECT_NEAR(drift_error_removed(f.raw, f.comp, f.floor), 0.75, 1e-9);
    const double s = share_removed(rms(f.raw), rms(f.comp), rms(f.floor));
    if (std::isfinite(s)) lowest = std::min(lowest, s), highest = std::max(highest, s);
  }
  EXPECT_GT(highest - lowest, 0.5);  // the RMSEs' share spreads over more than 50 points
}

TEST(Field, ACampaignsSummaryPairsEveryFindingOfEveryStartUp) {
  // Simulated start-ups carry their true drift: subtracting it leaves the floor (1), subtracting
  // nothing leaves the raw findings (0), and subtracting half of it leaves about a quarter of
  // the drift's error, north-finding being linear in the small biases it sees.
  sim::NorthfindOptions no;
  no.temps_degc = {-16, 17, 43};
  no.findings = 3;
  const sim::SimulatedCampaign c = sim::simulate_northfind(sim::Instrument{}, no);
  auto scaled = [](double k) -> DriftOf {
    return [k](const Recording& rec) {
      std::vector<double> d = rec.numeric_column("drift_true_dph");
      for (double& x : d) x *= k;
      return d;
    };
  };
  const FieldSummary whole = field_summary(c.campaign, c.recordings, scaled(1));
  ASSERT_EQ(whole.recordings.size(), 3u);
  for (const FieldRecording& r : whole.recordings) {
    EXPECT_EQ(r.raw_error_deg.size(), 3u);
    EXPECT_EQ(r.comp_error_deg, r.floor_error_deg);
    EXPECT_DOUBLE_EQ(r.raw_rmse_deg, rms(r.raw_error_deg));
  }
  EXPECT_EQ(whole.drift_error_removed(), 1.0);
  EXPECT_EQ(field_summary(c.campaign, c.recordings, scaled(0)).drift_error_removed(), 0.0);
  EXPECT_NEAR(field_summary(c.campaign, c.recordings, scaled(0.5)).drift_error_removed(), 0.75,
              0.02);
  // Without a drift nothing is compensated, and nothing is paired.
  EXPECT_TRUE(std::isnan(field_summary(c.campaign, c.recordings, {}).drift_error_removed()));
}

}  // namespace
}  // namespace fogdrift::eval
