// The chamber schedule of a protocol: settling against the simulator's own integration, the
// paper's cycle in closed form, warm start-ups chained to soaked ones, and passes that save the
// return of the range.
#include "fogdrift/sim/chamber.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/sim/nfs.hpp"

namespace fogdrift::sim {
namespace {

double farthest(const NfsSimulator& nfs, double air) {
  double d = 0;
  for (double t : nfs.temps_degc()) d = std::max(d, std::fabs(t - air));
  return d;
}

// Settling is measured with a 10 s step; the simulator integrates the same network at its own
// fine step. After the time found every node is within the margin, and a minute earlier not.
TEST(Chamber, SettlingAgreesWithTheSimulatorsOwnIntegration) {
  const Instrument instrument;
  const double s = settle_seconds(instrument, 0.0, 10.0, 0.1);
  // docs/field.md: about 3 hours for the default instrument's slowest unpowered lag.
  EXPECT_GT(s, 2 * 3600.0);
  EXPECT_LT(s, 4 * 3600.0);
  const auto air = [](double) { return 10.0; };
  NodeTemps start;
  start.fill(0.0);
  NfsSimulator early(instrument, start);
  early.advance(s - 60, air, false);
  EXPECT_GT(farthest(early, 10.0), 0.1);
  NfsSimulator late(instrument, start);
  late.advance(s + 10, air, false);  // one of the schedule's steps past it, at the fine step
  EXPECT_LT(farthest(late, 10.0), 0.1);
  // A smaller margin takes longer, and a step twice as large longer too.
  EXPECT_GT(settle_seconds(instrument, 0.0, 10.0, 0.01), s);
  EXPECT_GT(settle_seconds(instrument, 0.0, 20.0, 0.1), s);
}

// The paper's cycle is fixed times: one calibration sweep is the move from the start, the
// settle at its first set point, and soak + powered at each set point with a ramp between.
TEST(Chamber, TheCalibrationSweepIsThePapersCycle) {
  CalibrationOptions p;
  p.repetitions = 1;
  p.test_repetitions = 0;
  p.temps_degc = {0, 10, 20};
  ChamberOptions o;
  o.start_degc = 20;
  const ChamberSchedule s = chamber_schedule(Instrument{}, p, o);
  ASSERT_FALSE(s.steps.empty());
  EXPECT_EQ(s.steps[0].action, "ramp");
  EXPECT_EQ(s.steps[0].repetition, 0);
  EXPECT_DOUBLE_EQ(s.steps[0].seconds, 20 * 60.0);  // 20 °C at 1 °C/min
  EXPECT_EQ(s.steps[1].action, "settle");
  const double settle = s.steps[1].seconds;
  EXPECT_NEAR(s.move_hours, 20.0 / 60, 1e-12);
  EXPECT_NEAR(s.repetition_hours[0] * 3600, settle + 3 * (1200 + 1800) + 2 * 600, 1e-6);
  EXPECT_NEAR(s.hours, s.move_hours + s.repetition_hours[0], 1e-12);
  EXPECT_EQ(s.test_hours, 0.0);
  std::size_t recorded = 0;
  for (const ChamberStep& st : s.steps) recorded += st.action == "powered (recorded)" ? 1 : 0;
  EXPECT_EQ(recorded, 3u);
}

// A warm start-up is the soaked start-up's 30 powered minutes, then off and on again: chained,
// each costs only those two steps; unchained, a settle and the first run of its own.
TEST(Chamber, AWarmSweepRidesOnASoakedOne) {
  CalibrationOptions p;
  p.repetitions = 2;
  p.test_repetitions = 0;
  p.approaches = {Approach::soaked, Approach::warm};
  p.temps_degc = {0, 10, 20, 30};
  const ChamberSchedule chained = chamber_schedule(Instrument{}, p);
  EXPECT_EQ(chained.chained_warm_start_ups, 4u);
  EXPECT_NEAR(chained.repetition_hours[1] * 3600, 4 * (p.warm_off_s + p.powered_s), 1e-6);
  ChamberOptions apart;
  apart.chain_warm = false;
  const ChamberSchedule unchained = chamber_schedule(Instrument{}, p, apart);
  EXPECT_EQ(unchained.chained_warm_start_ups, 0u);
  EXPECT_GT(unchained.repetition_hours[1], chained.repetition_hours[1] + 4 * 1800 / 3600.0);
  EXPECT_GT(unchained.hours, chained.hours);
  // The warm start-up's first run is 30 minutes: a soaked start-up of another length is not it.
  p.powered_s = 1200;
  EXPECT_EQ(chamber_schedule(Instrument{}, p).chained_warm_start_ups, 0u);
}

// After an ascending calibration sweep the chamber is at the top: a soaked sweep, which any
// order serves, starts there instead of returning to the bottom; a second calibration sweep,
// whose history is the ascending cycle, returns.
TEST(Chamber, PassesStartAtTheNearerEnd) {
  CalibrationOptions p;
  p.repetitions = 3;
  p.test_repetitions = 1;
  p.approaches = {Approach::calibration, Approach::soaked, Approach::calibration};
  p.temps_degc = {-20, 0, 20, 40};
  const ChamberSchedule s = chamber_schedule(Instrument{}, p);
  std::vector<double> soaked_order, third_order;
  for (const ChamberStep& st : s.steps) {
    if (st.action != "powered (recorded)") continue;
    (st.repetition == 2 ? soaked_order : third_order).push_back(st.set_point_degc);
  }
  EXPECT_EQ(soaked_order, (std::vector<double>{40, 20, 0, -20}));
  // The test repetition's hours are the third sweep's own.
  EXPECT_NEAR(s.test_hours, s.repetition_hours[2], 1e-12);
  double sum = s.move_hours;
  for (double h : s.repetition_hours) sum += h;
  EXPECT_NEAR(sum, s.hours, 1e-9);
}

// A ramping start-up settles 10 °C below its set point and is powered while the air ramps up.
TEST(Chamber, ARampingStartUpBeginsTenDegreesBelow) {
  CalibrationOptions p;
  p.repetitions = 1;
  p.test_repetitions = 0;
  p.approaches = {Approach::ramping};
  p.temps_degc = {10, 20};
  const ChamberSchedule s = chamber_schedule(Instrument{}, p);
  std::vector<const ChamberStep*> recorded;
  for (const ChamberStep& st : s.steps)
    if (st.action == "powered (recorded)") recorded.push_back(&st);
  ASSERT_EQ(recorded.size(), 2u);
  EXPECT_EQ(recorded[0]->air_from_degc, 0.0);
  EXPECT_EQ(recorded[0]->air_to_degc, 10.0);
  EXPECT_EQ(recorded[1]->air_from_degc, 10.0);  // the first one's end: no move
  EXPECT_EQ(recorded[1]->air_to_degc, 20.0);
}

// A soaked start-up costs its settling; on fewer set points the soaked and warm sweeps cost
// fewer hours, and the calibration sweep keeps its own set points and hours.
TEST(Chamber, FewerStartUpSetPointsCostFewerHours) {
  CalibrationOptions p;
  p.repetitions = 3;
  p.test_repetitions = 0;
  p.approaches = {Approach::calibration, Approach::soaked, Approach::warm};
  const ChamberSchedule full = chamber_schedule(Instrument{}, p);
  p.start_up_temps_degc = {-40, -7, 27, 60};
  const ChamberSchedule sparse = chamber_schedule(Instrument{}, p);
  EXPECT_NEAR(sparse.repetition_hours[0], full.repetition_hours[0], 1e-9);
  EXPECT_LT(sparse.repetition_hours[1], full.repetition_hours[1] * 0.5);
  EXPECT_EQ(sparse.chained_warm_start_ups, 4u);
  std::vector<double> soaked;
  for (const ChamberStep& st : sparse.steps)
    if (st.repetition == 2 && st.action == "powered (recorded)")
      soaked.push_back(st.set_point_degc);
  EXPECT_EQ(soaked, (std::vector<double>{60, 27, -7, -40}));  // from the sweep's end, 60 °C
}

TEST(Chamber, ImpossibleSettingsNameTheirOption) {
  auto expect_option = [](ChamberOptions o, const std::string& option) {
    try {
      chamber_schedule(Instrument{}, CalibrationOptions{}, o);
      ADD_FAILURE() << "no error for " << option;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), option) << e.what();
    }
  };
  ChamberOptions o;
  o.chamber_ramp_degc_per_min = 0;
  expect_option(o, "chamber_ramp_degc_per_min");
  o = {};
  o.settled_within_degc = 0;
  expect_option(o, "settled_within_degc");
  o = {};
  o.start_degc = NAN;
  expect_option(o, "start_degc");
  // A unit that would take months to settle is refused, not scheduled for a week and called
  // settled.
  Instrument slow;
  slow.thermal.capacity_j_per_k[0] = 1e7;  // the housing: τ ≈ 1e7 J/K / 1.2 W/K, some 96 days
  try {
    chamber_schedule(slow, CalibrationOptions{});
    ADD_FAILURE() << "no error for an instrument that does not settle";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "settled_within_degc");
    EXPECT_NE(std::string(e.what()).find("in 7 days"), std::string::npos) << e.what();
  }
  CalibrationOptions p;
  p.repetitions = 0;
  try {
    chamber_schedule(Instrument{}, p);
    ADD_FAILURE() << "no error for repetitions";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "calibration.repetitions");
  }
}

}  // namespace
}  // namespace fogdrift::sim
