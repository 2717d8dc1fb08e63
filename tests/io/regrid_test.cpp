#include "fogdrift/io/regrid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

/// A recording whose every channel is a known function of time.
Recording from_times(const std::vector<double>& t, double (*f)(double)) {
  Recording r;
  r.source = "log.csv";
  r.time_s = t;
  for (double ti : t) {
    r.gyro_dph.push_back(f(ti));
    r.temp_fog_degc.push_back(20 + 0.01 * ti);
    r.temp_acc1_degc.push_back(21 + 0.02 * ti);
    r.temp_acc2_degc.push_back(22 - 0.01 * ti);
  }
  return r;
}

double ramp(double t) {
  return 3.0 + 0.5 * t;
}

TEST(Regrid, JitteryMillisecondStampsOnAFiftyHertzGrid) {
  // 50 Hz with stamps rounded to the millisecond: steps of 19, 20 and 21 ms.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.0015, 0.0015);
  std::vector<double> t;
  for (int i = 0; i < 3000; ++i)
    t.push_back(std::round((1.0 + 0.02 * i + jitter(rng)) * 1e3) / 1e3);
  const Recording rec = from_times(t, ramp);
  ASSERT_FALSE(is_uniformly_sampled(rec));
  const RegridResult r = regrid(rec, {0.02});
  EXPECT_EQ(r.summary.method, RegridMethod::linear);
  ASSERT_EQ(r.segments.size(), 1u);
  const Recording& out = r.segments[0];
  EXPECT_TRUE(is_uniformly_sampled(out));
  EXPECT_TRUE(r.summary.gaps.empty());
  EXPECT_GT(r.summary.input_max_jitter, 0.04);
  for (std::size_t i = 0; i < out.size(); ++i) {
    // Linear interpolation of linear channels is exact.
    EXPECT_NEAR(out.gyro_dph[i], ramp(out.time_s[i]), 1e-9);
    EXPECT_NEAR(out.temp_acc1_degc[i], 21 + 0.02 * out.time_s[i], 1e-9);
    EXPECT_NEAR(std::remainder(out.time_s[i], 0.02), 0.0, 1e-9);
  }
  EXPECT_GE(out.time_s.front(), t.front());
  EXPECT_LE(out.time_s.back(), t.back());
}

TEST(Regrid, BurstsBecomeTheirMeans) {
  // 250 samples at 50 Hz every 305 s, as a thermal-vacuum logger writes them.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 1.0);
  Recording rec;
  rec.source = "bursts.csv";
  std::vector<double> means;
  for (int b = 0; b < 10; ++b) {
    double sum = 0;
    for (int j = 0; j < 250; ++j) {
      const double ti = 2.0 + 305.0 * b + 0.02 * j;
      const double g = std::sin(0.001 * ti) + noise(rng);
      rec.time_s.push_back(ti);
      rec.gyro_dph.push_back(g);
      rec.temp_fog_degc.push_back(20.0 + b);
      rec.temp_acc1_degc.push_back(20.0 + b);
      rec.temp_acc2_degc.push_back(20.0 + b);
      sum += g;
    }
    means.push_back(sum / 250);
  }
  rec.extra.push_back({"status", std::vector<std::string>(rec.size(), "OK")});
  // A second gyro axis as numbers: carried onto the grid like gyro_dph, as a burst mean.
  std::vector<std::string> gyro_y;
  for (std::size_t i = 0; i < rec.size(); ++i)
    gyro_y.push_back(csv::format_number(2.0 * rec.gyro_dph[i] - 1.0));
  rec.extra.push_back({"gyro_y_dph", gyro_y});
  const RegridResult r = regrid(rec, {305.0});
  EXPECT_EQ(r.summary.method, RegridMethod::mean);
  ASSERT_EQ(r.segments.size(), 1u);
  const Recording& out = r.segments[0];
  ASSERT_EQ(out.size(), 10u);
  for (std::size_t b = 0; b < 10; ++b) {
    EXPECT_NEAR(out.gyro_dph[b], means[b], 1e-12);
    EXPECT_DOUBLE_EQ(out.temp_fog_degc[b], 20.0 + static_cast<double>(b));
    EXPECT_NEAR(out.time_s[b], 305.0 * static_cast<double>(b), 1e-9);
  }
  EXPECT_EQ(r.summary.dropped_columns, std::vector<std::string>{"status"});
  ASSERT_EQ(out.extra.size(), 1u);
  EXPECT_EQ(out.extra[0].name, "gyro_y_dph");
  for (std::size_t b = 0; b < 10; ++b)
    EXPECT_NEAR(*csv::parse_number(out.extra[0].cells[b]), 2.0 * means[b] - 1.0, 1e-12);
}

TEST(Regrid, PutsALogWithoutAGyroOnTheGrid) {
  // A chamber sheet read every 300 s from 60 s before power-on: no gyro, no FOG thermometer.
  Recording sheet;
  sheet.partial = true;
  sheet.source = "sheet.csv";
  sheet.chamber_degc.emplace();
  for (int i = 0; i < 5; ++i) {
    sheet.time_s.push_back(-60.0 + 300.0 * i);
    sheet.chamber_degc->push_back(20.0 + i);
  }
  const RegridResult r = regrid(sheet, {60.0});
  ASSERT_EQ(r.segments.size(), 1u);
  const Recording& out = r.segments[0];
  EXPECT_TRUE(out.partial);
  EXPECT_TRUE(out.gyro_dph.empty());
  EXPECT_DOUBLE_EQ(out.time_s.front(), -60.0);
  ASSERT_EQ(out.size(), 21u);
  EXPECT_NEAR((*out.chamber_degc)[1], 20.2, 1e-12);  // t = 0, a fifth of the way to 21 °C
}

TEST(Regrid, BridgesShortGapsAndSplitsAtLongOnes) {
  std::vector<double> t;
  for (int i = 0; i <= 300; ++i)
    if (i < 100 || i > 199) t.push_back(i);  // 1 Hz with seconds 100..199 missing
  const Recording rec = from_times(t, ramp);

  RegridOptions bridge{1.0};
  bridge.max_gap_s = 150;
  const RegridResult a = regrid(rec, bridge);
  ASSERT_EQ(a.segments.size(), 1u);
  ASSERT_EQ(a.summary.gaps.size(), 1u);
  EXPECT_TRUE(a.summary.gaps[0].bridged);
  EXPECT_EQ(a.summary.gaps[0].filled, 100u);
  EXPECT_DOUBLE_EQ(a.summary.gaps[0].length_s(), 101.0);
  EXPECT_EQ(a.segments[0].size(), 301u);
  EXPECT_NEAR(a.segments[0].gyro_dph[150], ramp(150), 1e-12);

  RegridOptions cut{1.0};
  cut.max_gap_s = 20;
  for (auto method : {RegridMethod::linear, RegridMethod::mean}) {
    cut.method = method;
    const RegridResult b = regrid(rec, cut);
    ASSERT_EQ(b.segments.size(), 2u) << to_string(method);
    EXPECT_FALSE(b.summary.gaps[0].bridged);
    EXPECT_EQ(b.segments[0].size(), 100u);
    EXPECT_DOUBLE_EQ(b.segments[1].time_s.front(), 200.0);  // keeps its time since power-on
    EXPECT_EQ(b.segments[1].size(), 101u);
  }
}

TEST(Regrid, TurntableAngleTakesTheNearestSampleNotAMean) {
  std::vector<double> t;
  for (int i = 0; i < 40; ++i) t.push_back(0.25 * i);
  Recording rec = from_times(t, ramp);
  rec.table_deg.emplace();
  for (double ti : t) rec.table_deg->push_back(ti < 5.0 ? 0.0 : 90.0);
  const RegridResult r = regrid(rec, {1.0});  // 4 Hz into 1 Hz bins: mean
  ASSERT_EQ(r.summary.method, RegridMethod::mean);
  for (std::size_t i = 0; i < r.segments[0].size(); ++i) {
    const double a = (*r.segments[0].table_deg)[i];
    EXPECT_TRUE(a == 0.0 || a == 90.0) << a;
  }
}

TEST(Regrid, RejectsImpossibleOptions) {
  const Recording rec = from_times({0, 1, 2, 3}, ramp);
  try {
    regrid(rec, {0.0});
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "step_s");
  }
  RegridOptions o{1.0};
  o.min_segment_samples = 10;
  EXPECT_THROW(regrid(rec, o), InputError);
  EXPECT_THROW(regrid_method_from_string("cubic"), OptionError);
}

}  // namespace
}  // namespace fogdrift
