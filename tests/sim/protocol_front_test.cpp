// The studied protocols, priced and chosen: each is a protocol the simulator runs, the front is
// the running best of the worst 10th percentile, and the choice keeps to the budget.
#include "fogdrift/sim/protocol_front.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift::sim {
namespace {

const std::vector<Approach> kAll(kServiceConditions.begin(), kServiceConditions.end());

TEST(ProtocolFront, EveryStudiedProtocolIsOneTheSimulatorRuns) {
  ASSERT_FALSE(studied_protocols().empty());
  for (const StudiedProtocol& s : studied_protocols()) {
    EXPECT_NO_THROW(validate(s.protocol)) << s.name;
    // The last sweep is the test, begun as the paper's cycle; every other one is trained on.
    EXPECT_EQ(s.protocol.test_repetitions, 1) << s.name;
    EXPECT_EQ(approach_of(s.protocol, s.protocol.repetitions), Approach::calibration) << s.name;
    std::vector<const std::array<PopulationShare, 4>*> paths{&s.batch, &s.causal};
    for (const SeedRerun& r : s.reruns) {
      EXPECT_GT(r.search_seed_offset, 0) << s.name;  // other seeds than the first study's
      paths.push_back(&r.batch);
      paths.push_back(&r.causal);
    }
    for (const auto* path : paths)
      for (const PopulationShare& x : *path) {
        EXPECT_LE(x.worst_pct, x.p10_pct) << s.name;
        EXPECT_LE(x.p10_pct, x.median_pct) << s.name;
      }
  }
}

// A protocol is claimed at the worst of every set of search seeds it was studied with: a rerun
// can lower its figures, never raise them.
TEST(ProtocolFront, AClaimIsTheWorstOverEverySetOfSearchSeeds) {
  bool some_rerun = false;
  for (const PricedProtocol& p : price_protocols(Instrument{}, ChamberOptions{}, kAll)) {
    const StudiedProtocol& s = *p.studied;
    std::vector<const std::array<PopulationShare, 4>*> paths{&s.batch, &s.causal};
    EXPECT_GE(p.worse_than_raw, s.worse_than_raw) << s.name;
    for (const SeedRerun& r : s.reruns) {
      some_rerun = true;
      paths.push_back(&r.batch);
      paths.push_back(&r.causal);
      EXPECT_GE(p.worse_than_raw, r.worse_than_raw) << s.name;
    }
    double lowest_p10 = 1e300, lowest_median = 1e300, lowest = 1e300;
    for (const auto* path : paths)
      for (const PopulationShare& x : *path) {
        lowest_p10 = std::min(lowest_p10, x.p10_pct);
        lowest_median = std::min(lowest_median, x.median_pct);
        lowest = std::min(lowest, x.worst_pct);
      }
    EXPECT_EQ(p.worst_p10_pct, lowest_p10) << s.name;
    EXPECT_EQ(p.worst_median_pct, lowest_median) << s.name;
    EXPECT_EQ(p.worst_worst_pct, lowest) << s.name;
    // The goal: the median and 10th percentile, and none worse than raw with any seeds.
    EXPECT_EQ(p.meets_goal, lowest_median >= kGoalMedianPct && lowest_p10 >= kGoalP10Pct &&
                                lowest >= 0 && p.worse_than_raw == 0)
        << s.name;
  }
  EXPECT_TRUE(some_rerun);
}

TEST(ProtocolFront, PricedCheapestFirstWithTheFrontMarked) {
  const auto priced = price_protocols(Instrument{}, ChamberOptions{}, kAll);
  ASSERT_EQ(priced.size(), studied_protocols().size());
  double best = -1e300;
  for (std::size_t i = 0; i < priced.size(); ++i) {
    const PricedProtocol& p = priced[i];
    if (i > 0) {
      EXPECT_LE(priced[i - 1].service_hours, p.service_hours);
    }
    EXPECT_NEAR(p.service_hours, p.schedule.hours - p.schedule.test_hours, 1e-9);
    EXPECT_EQ(p.on_front, p.worst_p10_pct > best) << p.studied->name;
    best = std::max(best, p.worst_p10_pct);
    // The worst over all four conditions is no better than over any one of them.
    for (Approach a : kAll) {
      const auto one = price_protocols(Instrument{}, ChamberOptions{}, {a});
      for (const PricedProtocol& q : one)
        if (q.studied == p.studied) {
          EXPECT_GE(q.worst_p10_pct, p.worst_p10_pct);
        }
    }
  }
}

TEST(ProtocolFront, TheChoiceKeepsToTheBudgetAndTakesTheHighestTenthPercentile) {
  const auto priced = price_protocols(Instrument{}, ChamberOptions{}, kAll);
  EXPECT_FALSE(choose_protocol(priced, priced.front().service_hours - 0.1));
  for (double budget : {20.0, 40.0, 60.0, 100.0, 250.0}) {
    const auto chosen = choose_protocol(priced, budget);
    if (!chosen) {
      EXPECT_GT(priced.front().service_hours, budget);
      continue;
    }
    EXPECT_LE(chosen->service_hours, budget);
    EXPECT_TRUE(chosen->on_front) << budget;
    for (const PricedProtocol& p : priced)
      if (p.service_hours <= budget) {
        EXPECT_LE(p.worst_p10_pct, chosen->worst_p10_pct);
      }
  }
  // The cheapest meeting the goal is the first that does.
  const auto goal = cheapest_meeting_goal(priced);
  ASSERT_TRUE(goal);
  EXPECT_TRUE(goal->meets_goal);
  EXPECT_GE(goal->worst_median_pct, kGoalMedianPct);
  EXPECT_GE(goal->worst_p10_pct, kGoalP10Pct);
  EXPECT_GE(goal->worst_worst_pct, 0.0);
  EXPECT_EQ(goal->worse_than_raw, 0);
  for (const PricedProtocol& p : priced)
    if (p.service_hours < goal->service_hours) {
      EXPECT_FALSE(p.meets_goal) << p.studied->name;
    }
  // A tie goes to the cheaper.
  std::vector<PricedProtocol> tie(2, priced.front());
  tie[1].service_hours += 5;
  EXPECT_EQ(choose_protocol(tie, 1e9)->service_hours, tie[0].service_hours);
}

// The goal of docs/field.md, "Protocols worth their hours": within 60 chamber hours on the
// default instrument, a protocol whose population study has every median ≥ 85 % and every 10th
// percentile ≥ 60 %, batch and causal, on all 20 instruments, none worse than raw. The four
// start-up set points reach the median and 10th percentile with the first study's search seeds
// and miss the 10th percentile with others: 56 % at its worst wherever they lie (−40, −7, 27 and
// 60 °C: batch soaked, seeds k + 100; −40, −13, 13 and 40 °C: batch warm, seeds k + 100, three
// sets of seeds; −40, −5, 25 and 55 °C: batch warm, seeds k), so the tie goes to the cheapest
// placement, and each leaves unit 15's warm start-ups worse than raw: 60 hours buy the best
// protocol studied, which is not yet
// the goal (nor is the two-warm-sweep protocol of 77.8 h, whose batch warm 10th percentile falls
// to 48 %, nor the five sweeps of 105.1 h); the page says so, and this test fails, to be
// rewritten, once a protocol of 60 hours meets it whatever the seeds.
TEST(ProtocolFront, SixtyHoursBuyTheBestStudiedProtocolNotYetTheGoal) {
  const auto priced = price_protocols(Instrument{}, ChamberOptions{}, kAll);
  const auto chosen = choose_protocol(priced, 60);
  ASSERT_TRUE(chosen);
  EXPECT_EQ(chosen->studied->name, "four start-up set points");
  EXPECT_LE(chosen->service_hours, 60.0);
  EXPECT_EQ(chosen->studied->instruments, 20);
  EXPECT_GE(chosen->worst_median_pct, kGoalMedianPct);
  EXPECT_LT(chosen->worst_p10_pct, kGoalP10Pct);
  EXPECT_FALSE(chosen->meets_goal);
  // With its first search seeds alone it would have been claimed to meet the goal.
  for (const auto* path : {&chosen->studied->batch, &chosen->studied->causal})
    for (const PopulationShare& x : *path) {
      EXPECT_GE(x.median_pct, kGoalMedianPct);
      EXPECT_GE(x.p10_pct, kGoalP10Pct);
    }
  const auto goal = cheapest_meeting_goal(priced);
  ASSERT_TRUE(goal);
  EXPECT_GT(goal->service_hours, 60.0);
  EXPECT_EQ(goal->studied->name, "seven sweeps");  // five sweeps leave warm start-ups worse
  // It meets the goal with other search seeds too (k + 100, 2026-12-02).
  EXPECT_FALSE(goal->studied->reruns.empty());
}

// "None worse than raw" is part of the goal: the five-sweep protocol has its medians and 10th
// percentiles (79 % and more) but leaves unit 15's warm start-ups worse than raw with both sets
// of search seeds (−15 / −35 % and −36 / −39 %), so it meets the goal for a unit that never
// restarts warm and misses it for one that does.
TEST(ProtocolFront, AProtocolLeavingAnInstrumentWorseThanRawMissesTheGoal) {
  auto five = [](const std::vector<Approach>& service) {
    for (const PricedProtocol& p : price_protocols(Instrument{}, ChamberOptions{}, service))
      if (p.studied->name == "five sweeps") return p;
    ADD_FAILURE() << "no five-sweep protocol";
    return PricedProtocol{};
  };
  const PricedProtocol every = five(kAll);
  EXPECT_GE(every.worst_median_pct, kGoalMedianPct);
  EXPECT_GE(every.worst_p10_pct, kGoalP10Pct);
  EXPECT_LT(every.worst_worst_pct, 0.0);
  EXPECT_GT(every.worse_than_raw, 0);
  EXPECT_FALSE(every.meets_goal);
  const PricedProtocol never_warm = five({Approach::calibration, Approach::ramping});
  EXPECT_GE(never_warm.worst_worst_pct, 0.0);
  EXPECT_TRUE(never_warm.meets_goal);
}

TEST(ProtocolFront, ServiceConditionsAreStartUps) {
  for (const std::vector<Approach>& bad :
       {std::vector<Approach>{}, std::vector<Approach>{Approach::soaked, Approach::sweep}}) {
    try {
      price_protocols(Instrument{}, ChamberOptions{}, bad);
      ADD_FAILURE() << "accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "service");
    }
  }
}

}  // namespace
}  // namespace fogdrift::sim
