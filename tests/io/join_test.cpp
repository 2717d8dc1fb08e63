#include "fogdrift/io/join.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

/// The case temperature through a chamber step: 20 °C until power-on, self-heating towards 23 °C,
/// then a step at 1800 s towards 40 °C (curved, so that it can fix a time offset).
double case_temperature(double t) {
  const double at_step = 20.0 + 3.0 * (1.0 - std::exp(-1800.0 / 600.0));
  if (t < 0) return 20.0;
  if (t < 1800.0) return 20.0 + 3.0 * (1.0 - std::exp(-t / 600.0));
  return at_step + (40.0 - at_step) * (1.0 - std::exp(-(t - 1800.0) / 900.0));
}

/// A unit's recording every `step_s` from 0 to `end_s`: a gyro and its own thermometer.
Recording unit(double step_s, double end_s) {
  Recording r;
  r.source = "unit.csv";
  for (double t = 0; t <= end_s + 1e-9; t += step_s) {
    r.time_s.push_back(t);
    r.gyro_dph.push_back(0.01 * std::sin(t / 500.0));
    r.temp_fog_degc.push_back(case_temperature(t));
  }
  return r;
}

/// A chamber sheet: every `step_s` on its own clock, which reads `offset_s` less than the unit's
/// (t_unit = t_sheet + offset_s); a thermocouple on the case reading `bias` high, and the air.
Recording sheet(double step_s, double from_s, double to_s, double offset_s, double bias) {
  Recording s;
  s.partial = true;
  s.source = "sheet.csv";
  s.chamber_degc.emplace();
  std::vector<std::string> tc;
  for (double t = from_s; t <= to_s + 1e-9; t += step_s) {
    s.time_s.push_back(t);
    s.chamber_degc->push_back(10.0 + 0.001 * t);  // a line: interpolation is exact
    tc.push_back(csv::format_number(case_temperature(t + offset_s) + bias));
  }
  s.extra.push_back({"tc_case_degc", tc});
  s.extra.push_back({"operator", std::vector<std::string>(s.size(), "jd")});
  return s;
}

TEST(Join, LinearTakesTheLogsValuesAtTheRecordingsTimeMinusTheOffset) {
  const Recording rec = unit(10.0, 3600.0);
  const Recording log = sheet(300.0, -600.0, 4200.0, 0.0, 0.0);
  JoinOptions o;
  o.columns = {"chamber_degc"};
  o.offset_s = 120.0;  // t_recording = t_log + 120
  const JoinResult r = join(rec, log, o);
  ASSERT_EQ(r.segments.size(), 1u);
  const Recording& out = r.segments[0];
  ASSERT_EQ(out.size(), rec.size());
  for (std::size_t i = 0; i < out.size(); ++i)  // the line, at t − 120, to rounding
    EXPECT_NEAR((*out.chamber_degc)[i], 10.0 + 0.001 * (out.time_s[i] - 120.0), 1e-12);
  EXPECT_EQ(out.gyro_dph, rec.gyro_dph);  // the recording's own columns are untouched
  EXPECT_FALSE(out.partial);
  EXPECT_EQ(r.summary.columns, (std::vector<std::string>{"chamber_degc"}));
  EXPECT_DOUBLE_EQ(r.summary.limit_s, 450.0);  // 1.5 × the sheet's 300 s
  EXPECT_DOUBLE_EQ(r.summary.log_from_s, -480.0);
  EXPECT_EQ(r.summary.log_rows_used, 12u);  // sheet times 0 .. 3300 s land inside 0 .. 3600 s
}

TEST(Join, RowsOutsideTheLogAreDroppedAndItsLongGapsSplit) {
  const Recording rec = unit(10.0, 3600.0);
  Recording log = sheet(300.0, 600.0, 3000.0, 0.0, 0.0);  // covers 600 .. 3000 s
  // Lose the readings at 1500 and 1800 s: a 900 s step, over the 450 s limit.
  for (double lost : {1500.0, 1800.0}) {
    const auto at = static_cast<std::ptrdiff_t>(
        std::find(log.time_s.begin(), log.time_s.end(), lost) - log.time_s.begin());
    log.time_s.erase(log.time_s.begin() + at);
    log.chamber_degc->erase(log.chamber_degc->begin() + at);
    for (auto& e : log.extra) e.cells.erase(e.cells.begin() + at);
  }
  JoinOptions same_clock;
  same_clock.offset_s = 0.0;
  const JoinResult r = join(rec, log, same_clock);
  ASSERT_EQ(r.segments.size(), 2u);
  EXPECT_DOUBLE_EQ(r.segments[0].time_s.front(), 600.0);
  EXPECT_DOUBLE_EQ(r.segments[0].time_s.back(), 1200.0);
  EXPECT_DOUBLE_EQ(r.segments[1].time_s.front(), 2100.0);
  EXPECT_DOUBLE_EQ(r.segments[1].time_s.back(), 3000.0);
  EXPECT_EQ(r.summary.dropped_before, 60u);
  EXPECT_EQ(r.summary.dropped_after, 60u);
  EXPECT_EQ(r.summary.dropped_inside, 89u);  // 1210 .. 2090 s
  EXPECT_EQ(r.summary.rows_out, 61u + 91u);
  // The numeric extra comes along; the text one is reported, not joined.
  EXPECT_EQ(r.summary.columns, (std::vector<std::string>{"chamber_degc", "tc_case_degc"}));
  EXPECT_EQ(r.summary.skipped, (std::vector<std::string>{"operator"}));
  ASSERT_EQ(r.segments[0].extra.size(), 1u);
  EXPECT_EQ(r.segments[0].extra[0].name, "tc_case_degc");

  // A wider limit bridges the gap.
  JoinOptions wide = same_clock;
  wide.max_step_s = 900.0;
  EXPECT_EQ(join(rec, log, wide).segments.size(), 1u);
}

TEST(Join, NearestTakesTheClosestSampleWithinItsAge) {
  const Recording rec = unit(10.0, 600.0);
  const Recording log = sheet(300.0, 0.0, 600.0, 0.0, 0.0);
  JoinOptions o;
  o.method = JoinMethod::nearest;
  o.columns = {"chamber_degc"};
  o.offset_s = 0.0;
  o.max_age_s = 100.0;  // rows more than 100 s from a reading cannot be joined
  const JoinResult r = join(rec, log, o);
  ASSERT_EQ(r.segments.size(), 3u);  // around 0, 300 and 600 s
  EXPECT_DOUBLE_EQ(r.segments[1].time_s.front(), 200.0);
  EXPECT_DOUBLE_EQ(r.segments[1].time_s.back(), 400.0);
  for (double v : *r.segments[1].chamber_degc) EXPECT_DOUBLE_EQ(v, 10.3);
  EXPECT_EQ(r.summary.dropped_inside, 2u * 9u);
}

TEST(Join, EstimatesTheClockOffsetDespiteASensorBias) {
  // The sheet's clock runs 437 s behind the unit's and its thermocouple reads 0.4 °C high; the
  // sheet starts 20 minutes before power-on and is read every 60 s with 0.02 °C of noise.
  const double truth = 437.0;
  const Recording rec = unit(10.0, 7200.0);
  Recording log = sheet(60.0, -1200.0, 7000.0, truth, 0.4);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (auto& cell : log.extra[0].cells)
    cell = csv::format_number(*csv::parse_number(cell) + noise(rng));
  JoinOptions o;
  o.columns = {"tc_case_degc"};
  o.estimates = {OffsetSearch{"temp_fog_degc", "tc_case_degc", 0.0}};
  const JoinResult r = join(rec, log, o);
  ASSERT_EQ(r.summary.evidence.matches.size(), 1u);
  EXPECT_TRUE(r.summary.evidence.founded()) << r.summary.evidence.failures.front();
  const OffsetEstimate& e = r.summary.evidence.matches[0].estimate;
  EXPECT_NEAR(e.offset_s, truth, 5.0);
  EXPECT_LE(std::fabs(e.offset_s - truth), e.half_width_s);  // within its stated uncertainty
  EXPECT_NEAR(e.mean_difference, -0.4, 0.01);                // the thermocouple reads 0.4 high
  EXPECT_DOUBLE_EQ(r.summary.offset_s, e.offset_s);
  EXPECT_FALSE(e.at_edge);
  EXPECT_LT(e.residual_std, 0.03);  // the noise, the bias gone
  EXPECT_GT(e.residual_std_at_start, 1.0);
  EXPECT_LT(e.half_width_s, 120.0);
  EXPECT_LE(e.searched_from_s, -3000.0);
  EXPECT_GE(e.searched_to_s, 3000.0);

  // A range around a given centre finds it too; one that excludes it ends at its edge.
  o.offset_s = 400.0;
  o.estimates[0].range_s = 100.0;
  EXPECT_NEAR(join(rec, log, o).summary.offset_s, truth, 5.0);
  // A range that excludes it ends at its edge: evidence that fails, so nothing is joined unless
  // forced.
  o.offset_s = 0.0;
  const JoinEvidence edge = judge_alignment(rec, log, o);
  ASSERT_EQ(edge.matches.size(), 1u);
  EXPECT_TRUE(edge.matches[0].estimate.at_edge);
  EXPECT_NEAR(edge.offset_s, 100.0, 1e-9);
  ASSERT_FALSE(edge.founded());
  EXPECT_NE(edge.failures[0].find("at an end of the searched range"), std::string::npos);
  EXPECT_THROW(join(rec, log, o), InputError);
  o.force = true;
  const JoinResult forced = join(rec, log, o);
  EXPECT_TRUE(forced.summary.forced);
  EXPECT_NEAR(forced.summary.offset_s, 100.0, 1e-9);
}

TEST(Join, APartialRecordingBecomesWholeWhenTheLogHoldsWhatItLacks) {
  Recording gyro_only = unit(10.0, 600.0);
  gyro_only.temp_fog_degc.clear();
  gyro_only.partial = true;
  Recording log = sheet(60.0, 0.0, 600.0, 0.0, 0.0);
  log.temp_fog_degc = *log.chamber_degc;
  JoinOptions o;
  o.columns = {"temp_fog_degc"};
  o.offset_s = 0.0;
  const JoinResult r = join(gyro_only, log, o);
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_FALSE(r.segments[0].partial);
  EXPECT_TRUE(r.segments[0].has_column("temp_fog_degc"));
}

TEST(Join, ImpossibleRequestsNameTheRuleBroken) {
  const Recording rec = unit(10.0, 600.0);
  const Recording log = sheet(60.0, 0.0, 600.0, 0.0, 0.0);
  JoinOptions same_clock;
  same_clock.offset_s = 0.0;
  auto option_of_for = [&](const Recording& r, const Recording& l) -> std::string {
    try {
      join(r, l, same_clock);
    } catch (const OptionError& e) {
      return e.option();
    }
    return "";
  };
  auto option_of = [&](const JoinOptions& o) -> std::string {
    try {
      join(rec, log, o);
    } catch (const OptionError& e) {
      return e.option();
    }
    return "";
  };
  EXPECT_EQ(option_of({}), "offset_s");  // 0 is no default for two clocks
  JoinOptions o = same_clock;
  o.columns = {"pressure"};
  EXPECT_EQ(option_of(o), "columns");
  o.columns = {"operator"};  // text
  EXPECT_EQ(option_of(o), "columns");
  o.columns = {"chamber_degc", "chamber_degc"};
  EXPECT_EQ(option_of(o), "columns");
  Recording has_air = rec;
  has_air.chamber_degc = std::vector<double>(rec.size(), 20.0);
  o.columns = {"chamber_degc"};
  EXPECT_THROW(join(has_air, log, o), OptionError);  // the recording has it already
  o.replace = true;
  EXPECT_NEAR((*join(has_air, log, o).segments[0].chamber_degc)[6], 10.06, 1e-12);
  // With no columns named, the ones the recording has are kept and said so.
  const JoinResult kept = join(has_air, log, same_clock);
  EXPECT_EQ(kept.summary.kept, (std::vector<std::string>{"chamber_degc"}));
  EXPECT_EQ(kept.summary.columns, (std::vector<std::string>{"tc_case_degc"}));
  EXPECT_EQ((*kept.segments[0].chamber_degc)[6], 20.0);
  Recording only_air = log;
  only_air.extra.clear();
  EXPECT_EQ(option_of_for(has_air, only_air), "columns");  // nothing left to bring in
  JoinOptions age = same_clock;
  age.max_age_s = 10;  // a nearest-method limit on the linear method
  EXPECT_EQ(option_of(age), "max_age_s");
  JoinOptions no_step = same_clock;
  no_step.max_step_s = 0.0;  // a limit must be a duration > 0; unset is auto
  EXPECT_EQ(option_of(no_step), "max_step_s");
  JoinOptions bad_method = same_clock;
  bad_method.method = JoinMethod::nearest;
  bad_method.max_step_s = 10;
  EXPECT_EQ(option_of(bad_method), "max_step_s");
  JoinOptions far;
  far.offset_s = 1e6;  // no overlap
  try {
    join(rec, log, far);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--time-zero"), std::string::npos) << e.what();
  }
  JoinOptions flat;
  flat.estimates = {OffsetSearch{"temp_fog_degc", "chamber_degc", 0.0}};
  Recording constant = rec;
  constant.temp_fog_degc.assign(rec.size(), 21.0);
  EXPECT_THROW(join(constant, log, flat), InputError);  // nothing to fix an offset with
  flat.estimates[0].recording_column = "nope";
  EXPECT_EQ(option_of(flat), "estimate");
  EXPECT_THROW(join_method_from_string("cubic"), OptionError);
}

TEST(JoinEvidence, ColumnsThatDoNotMoveTogetherAreRefused) {
  // The sheet's thermocouple sees another quantity: a slow ramp with a wobble of its own, not the
  // case. Some offset minimises the variance of the difference, but the difference stays as
  // large as the column's own spread.
  const Recording rec = unit(10.0, 7200.0);
  Recording log = sheet(60.0, 0.0, 7200.0, 0.0, 0.0);
  for (std::size_t i = 0; i < log.size(); ++i)
    log.extra[0].cells[i] =
        csv::format_number(5.0 - 0.001 * log.time_s[i] + 2.0 * std::sin(log.time_s[i] / 300.0));
  JoinOptions o;
  o.estimates = {OffsetSearch{"temp_fog_degc", "tc_case_degc", 0.0}};
  const JoinEvidence ev = judge_alignment(rec, log, o);
  ASSERT_FALSE(ev.founded());
  bool residual = false;
  for (const auto& f : ev.failures) residual = residual || f.find("move together") != f.npos;
  EXPECT_TRUE(residual) << fmt::format("{}", fmt::join(ev.failures, " | "));
  try {
    join(rec, log, o);
    FAIL() << "an unfounded join was written";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not founded"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
}

TEST(JoinEvidence, AConstantGapLargerThanTheColumnsChangeIsRefused) {
  // The same shape 15 °C apart: the offset is sharp and the residual small, but two sensors
  // that far apart while varying by less are not one quantity seen twice.
  const Recording rec = unit(10.0, 1700.0);  // 20 .. 22.9 °C of self-heating
  const Recording log = sheet(60.0, -600.0, 2400.0, 0.0, -15.0);
  JoinOptions o;
  o.estimates = {OffsetSearch{"temp_fog_degc", "tc_case_degc", 0.0}};
  const JoinEvidence ev = judge_alignment(rec, log, o);
  ASSERT_FALSE(ev.founded());
  EXPECT_NE(ev.failures.back().find("apart on average"), std::string::npos) << ev.failures.back();
  EXPECT_NEAR(ev.matches[0].estimate.mean_difference, 15.0, 0.05);
}

TEST(JoinEvidence, SeveralColumnsMustAgree) {
  // Two thermocouples on the sheet's clock, 437 s behind; one pair agrees with the truth, the
  // other is built 900 s off: each is sharp on its own, together they disagree.
  const double truth = 437.0;
  const Recording rec = unit(10.0, 7200.0);
  Recording log = sheet(60.0, -1200.0, 7000.0, truth, 0.4);
  std::vector<std::string> late;
  for (double t : log.time_s) late.push_back(csv::format_number(case_temperature(t + truth + 900)));
  log.extra.push_back({"tc_late_degc", late});
  JoinOptions o;
  o.estimates = {OffsetSearch{"temp_fog_degc", "tc_case_degc", 0.0}};
  const JoinEvidence one = judge_alignment(rec, log, o);
  EXPECT_TRUE(one.founded());
  EXPECT_NEAR(one.offset_s, truth, one.uncertainty_s);
  o.estimates.push_back(OffsetSearch{"temp_fog_degc", "tc_late_degc", 0.0});
  const JoinEvidence two = judge_alignment(rec, log, o);
  ASSERT_FALSE(two.founded());
  EXPECT_NE(two.failures.back().find("disagree"), std::string::npos) << two.failures.back();
  // Two that agree: the applied offset lies between them.
  o.estimates[1] = OffsetSearch{"temp_fog_degc", "tc_case_degc", 0.0};
  const JoinEvidence same = judge_alignment(rec, log, o);
  EXPECT_TRUE(same.founded());
  EXPECT_NEAR(same.offset_s, one.offset_s, 1e-9);
}

}  // namespace
}  // namespace fogdrift
