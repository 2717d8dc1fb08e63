#include "fogdrift/io/cut.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

Recording seconds(const std::vector<double>& t) {
  Recording r;
  r.source = "long.csv";
  r.time_s = t;
  for (double ti : t) {
    r.gyro_dph.push_back(ti);
    r.temp_fog_degc.push_back(20);
    r.temp_acc1_degc.push_back(20);
    r.temp_acc2_degc.push_back(20);
  }
  r.extra.push_back({"tag", std::vector<std::string>(t.size(), "x")});
  return r;
}

TEST(Cut, AtGapsThenIntoWindows) {
  std::vector<double> t;
  for (int i = 0; i < 100; ++i) t.push_back(i);        // 0..99
  for (int i = 0; i < 260; ++i) t.push_back(500 + i);  // 500..759, after a 401 s gap
  const Recording rec = seconds(t);
  CutSummary s;
  const auto at_gaps = cut(rec, {60, 0}, &s);
  ASSERT_EQ(at_gaps.size(), 2u);
  EXPECT_EQ(s.gaps, 1u);
  EXPECT_EQ(at_gaps[0].size(), 100u);
  EXPECT_DOUBLE_EQ(at_gaps[1].time_s.front(), 500.0);  // keeps its time since power-on
  EXPECT_EQ(at_gaps[1].extra[0].cells.size(), 260u);

  // Windows of 100 s: 0..99 | 500..599, 600..699 | 700..759 (spans 59 s, over half: kept).
  const auto windows = cut(rec, {60, 100}, &s);
  ASSERT_EQ(windows.size(), 4u);
  EXPECT_EQ(windows[1].size(), 100u);
  EXPECT_DOUBLE_EQ(windows[3].time_s.front(), 700.0);
  EXPECT_EQ(windows[3].size(), 60u);
  // Windows of 120 s: 0..99 | 500..619, 620..739 | 740..759 (spans 19 s): dropped.
  const auto w120 = cut(rec, {60, 120}, &s);
  EXPECT_EQ(s.dropped, 1u);
  // Said, not lost without a word (issue 58): 20 samples, 740 to 759 s.
  EXPECT_EQ(s.dropped_samples, 20u);
  ASSERT_EQ(s.dropped_spans_s.size(), 1u);
  EXPECT_EQ(s.dropped_spans_s[0], (std::pair<double, double>{740.0, 759.0}));
  ASSERT_EQ(w120.size(), 3u);
  EXPECT_DOUBLE_EQ(w120.back().time_s.back(), 739.0);
}

TEST(Cut, AtTheEndsOfTemperaturePlateaus) {
  // A chamber staircase at 1 Hz: 20 °C for 1000 s, a ramp of 1.2 °C/min for 500 s, 30 °C for
  // 1000 s, another ramp, 40 °C for 1000 s; the unit 5 °C warmer than the air.
  auto chamber = [](double t) {
    return t < 1000   ? 20.0
           : t < 1500 ? 20.0 + (t - 1000) / 50.0
           : t < 2500 ? 30.0
           : t < 3000 ? 30.0 + (t - 2500) / 50.0
                      : 40.0;
  };
  Recording rec;
  rec.source = "stairs.csv";
  rec.chamber_degc.emplace();
  for (int i = 0; i < 4000; ++i) {
    const double t = i;
    rec.time_s.push_back(t);
    rec.gyro_dph.push_back(0);
    rec.temp_fog_degc.push_back(chamber(t) + 5.0);
    rec.chamber_degc->push_back(chamber(t));
  }
  CutOptions o;
  o.plateaus = true;
  CutSummary s;
  const auto pieces = cut(rec, o, &s);
  ASSERT_EQ(pieces.size(), 3u);
  EXPECT_EQ(s.plateaus, 2u);
  // By hand: near a ramp starting at R, the ±60 s slope at sample i is (i + 60 − R)/100 °C/min,
  // below 0.05 up to i = R − 56; the next piece starts one sample later.
  EXPECT_DOUBLE_EQ(pieces[1].time_s.front(), 1000 - 55);
  EXPECT_DOUBLE_EQ(pieces[2].time_s.front(), 2500 - 55);
  // Each piece: a step and the plateau it settles to.
  EXPECT_DOUBLE_EQ(pieces[1].chamber_degc->back(), 30.0);
  EXPECT_DOUBLE_EQ(pieces[2].chamber_degc->back(), 40.0);
  // Without a chamber column, the FOG thermometer is read.
  rec.chamber_degc.reset();
  EXPECT_EQ(cut(rec, o).size(), 3u);
  o.plateau_min_s = 1200;  // no plateau is that long: no cut
  EXPECT_EQ(cut(rec, o).size(), 1u);
}

TEST(Cut, RejectsImpossibleOptionsAndEmptyResults) {
  const Recording rec = seconds({0, 1, 2});
  try {
    cut(rec, {-1, 0});
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "gap_s");
  }
  CutOptions o;
  o.min_samples = 10;
  EXPECT_THROW(cut(rec, o), InputError);
}

}  // namespace
}  // namespace fogdrift
