// Time stamps: dates and times against Python's datetime, times of day by hand.
#include "fogdrift/io/timestamp.hpp"

#include <gtest/gtest.h>

namespace fogdrift {
namespace {

TEST(ParseDatetime, AgainstPythonsDatetime) {
  // Reference values from Python's datetime(..., tzinfo=timezone.utc).timestamp().
  EXPECT_EQ(parse_datetime("1970-01-01T00:00:00Z"), 0.0);
  EXPECT_EQ(parse_datetime("2000-01-01 00:00:00"), 946684800.0);
  EXPECT_EQ(parse_datetime("1969-12-31 23:59:59"), -1.0);
  // 12:34:56.5 at +02:00 is 10:34:56.5 UTC on a leap day.
  EXPECT_EQ(parse_datetime("2024-02-29T12:34:56.5+02:00"), 1709202896.5);
  EXPECT_EQ(parse_datetime(" 2024-02-29 10:34:56,500 "), 1709202896.5);
  EXPECT_EQ(parse_datetime("2024-02-29 10:34"), 1709202840.0);  // seconds left out: :00
  for (const char* bad :
       {"2024-02-29", "2024-13-01 00:00:00", "2024-02-29 10:3", "yesterday", "2024-02-29 10:34:5",
        "2024-02-29 10:34.5", "2024-02-29 10:34:56.", "2024-02-29 10:34:56+2"})
    EXPECT_FALSE(parse_datetime(bad).has_value()) << bad;
}

TEST(ParseClock, TimesOfDayAgainstHandComputedSeconds) {
  EXPECT_DOUBLE_EQ(*parse_clock("15:45"), 15 * 3600.0 + 45 * 60.0);
  EXPECT_DOUBLE_EQ(*parse_clock("7:05"), 7 * 3600.0 + 5 * 60.0);
  EXPECT_DOUBLE_EQ(*parse_clock(" 00:00:30 "), 30.0);
  EXPECT_DOUBLE_EQ(*parse_clock("23:59:59.25"), 86399.25);
  for (const char* bad : {"", "15", "15:4", "24:00", "12:60", "12:00:61", "12:00:00.", "1545",
                          "12:00 PM", "2020-03-07 15:45"})
    EXPECT_FALSE(parse_clock(bad).has_value()) << bad;
  // A date and time without seconds, as spreadsheets write it.
  EXPECT_DOUBLE_EQ(*parse_datetime("2020-03-07 15:45") - *parse_datetime("2020-03-07 15:44:30"),
                   30.0);
  EXPECT_DOUBLE_EQ(*parse_datetime("2020-03-07T15:45Z"), *parse_datetime("2020-03-07 15:45:00"));
}

}  // namespace
}  // namespace fogdrift
