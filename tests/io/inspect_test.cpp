#include "fogdrift/io/inspect.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fogdrift {
namespace {

TEST(Inspect, RateGapsAndRanges) {
  Recording r;
  for (double t : {1.0, 2.0, 3.0, 4.0, 7.0, 8.0, 9.0}) {
    r.time_s.push_back(t);
    r.gyro_dph.push_back(t);  // 1..9, so mean and STD are known
    r.temp_fog_degc.push_back(-t);
    r.temp_acc1_degc.push_back(0);
    r.temp_acc2_degc.push_back(0);
  }
  const RecordingSummary s = summarize(r);
  EXPECT_EQ(s.samples, 7u);
  EXPECT_DOUBLE_EQ(s.duration_s, 8.0);
  EXPECT_DOUBLE_EQ(s.sample_rate_hz, 1.0);
  EXPECT_EQ(s.gaps, 1u);
  EXPECT_DOUBLE_EQ(s.longest_gap_s, 3.0);
  EXPECT_DOUBLE_EQ(s.columns[0].mean, 34.0 / 7.0);
  EXPECT_DOUBLE_EQ(s.columns[1].min, -9.0);
}

// Found by a new user (issue 32): a log of 50 Hz bursts every 305 s was reported as "24 gaps".
TEST(Inspect, BurstsAreSaidToBeBursts) {
  auto log = [](const std::vector<double>& burst_starts) {
    Recording r;
    for (double start : burst_starts)
      for (int k = 0; k < 10; ++k) {
        r.time_s.push_back(start + 0.02 * k);
        r.gyro_dph.push_back(0);
        r.temp_fog_degc.push_back(20);
      }
    return summarize(r);
  };
  const RecordingSummary bursty = log({0, 305, 610, 915.5, 1220});
  EXPECT_EQ(bursty.gaps, 4u);
  EXPECT_EQ(bursty.bursts, 5u);
  EXPECT_DOUBLE_EQ(bursty.burst_period_s, 305.0);
  EXPECT_NEAR(bursty.sample_rate_hz, 50.0, 1e-9);
  // A lost burst leaves a burst log.
  EXPECT_EQ(log({0, 305, 915, 1220}).bursts, 4u);
  // Gaps at irregular times are gaps, not bursts.
  const RecordingSummary gappy = log({0, 305, 400, 1220});
  EXPECT_EQ(gappy.gaps, 3u);
  EXPECT_EQ(gappy.bursts, 0u);
  EXPECT_EQ(gappy.burst_period_s, 0.0);
}

TEST(Inspect, ColumnRangeStdIsTheSampleStd) {
  const ColumnRange r = column_range("x", {2, 4, 4, 4, 5, 5, 7, 9});
  EXPECT_DOUBLE_EQ(r.mean, 5.0);
  EXPECT_DOUBLE_EQ(r.std, std::sqrt(32.0 / 7.0));
}

// A chamber sheet as a log to join (issue 58): it was refused for lacking a gyro; now its span,
// step, columns and ranges are summarised, its text columns named and not ranged.
TEST(Inspect, ALogToJoinIsSummarisedWithWhatItLacks) {
  Recording sheet;
  sheet.partial = true;
  sheet.chamber_degc.emplace();
  for (double t : {-600.0, -300.0, 0.0, 300.0}) {
    sheet.time_s.push_back(t);
    sheet.chamber_degc->push_back(20.0 + t / 300.0);
  }
  sheet.extra.push_back({"temp_case_degc", {"19.5", "20.5", "21.5", "22.5"}});
  sheet.extra.push_back({"operator", {"jd", "jd", "kl", "kl"}});
  const RecordingSummary s = summarize(sheet);
  EXPECT_TRUE(s.partial);
  EXPECT_EQ(s.missing, (std::vector<std::string>{"gyro_dph", "temp_fog_degc"}));
  EXPECT_DOUBLE_EQ(s.start_s, -600.0);
  EXPECT_DOUBLE_EQ(s.sample_interval_s, 300.0);
  ASSERT_EQ(s.columns.size(), 2u);
  EXPECT_EQ(s.columns[0].name, "chamber_degc");
  EXPECT_DOUBLE_EQ(s.columns[0].min, 18.0);
  EXPECT_EQ(s.columns[1].name, "temp_case_degc");
  EXPECT_DOUBLE_EQ(s.columns[1].max, 22.5);
  EXPECT_EQ(s.extra_columns, (std::vector<std::string>{"temp_case_degc", "operator"}));
}

}  // namespace
}  // namespace fogdrift
