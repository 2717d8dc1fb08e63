// The channels a model compensates: their kinds, units, output columns and readings
// (target.hpp).
#include "fogdrift/io/target.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

TEST(Target, EachKindHasItsUnitAndColumns) {
  struct Case {
    const char* column;
    TargetKind kind;
    const char* axis;
    const char* symbol;
    const char* drift;
    const char* compensated;
  };
  for (const Case& c : {
           Case{"gyro_dph", TargetKind::gyro, "gyro", "°/h", "drift_dph", "gyro_comp_dph"},
           Case{"gyro_y_dph", TargetKind::gyro, "y", "°/h", "drift_y_dph", "gyro_y_comp_dph"},
           Case{"accel_x_g", TargetKind::accelerometer, "accel_x", "g", "drift_accel_x_g",
                "accel_x_comp_g"},
           Case{"accel_z_g", TargetKind::accelerometer, "accel_z", "g", "drift_accel_z_g",
                "accel_z_comp_g"},
           Case{"sf_fog_ppm", TargetKind::scale_factor, "sf_fog", "ppm", "drift_sf_fog_ppm",
                "sf_fog_comp_ppm"},
       }) {
    SCOPED_TRACE(c.column);
    const auto t = parse_target(c.column);
    ASSERT_TRUE(t.has_value());
    EXPECT_EQ(t->kind, c.kind);
    EXPECT_EQ(t->axis, c.axis);
    EXPECT_EQ(t->symbol(), c.symbol);
    EXPECT_EQ(t->drift_column(), c.drift);
    EXPECT_EQ(t->compensated_column(), c.compensated);
    EXPECT_EQ(axis_name(c.column), c.axis);
  }
}

TEST(Target, GyroAxesByName) {
  for (const char* good : {"gyro_dph", "gyro_y_dph", "gyro_2_dph", "gyro_left_x_dph"})
    EXPECT_TRUE(is_target_column(good)) << good;
  for (const char* bad : {"gyro__dph", "gyro_Y_dph", "gyro_y", "temp_fog_degc", ""})
    EXPECT_FALSE(is_target_column(bad)) << bad;
}

TEST(Target, OtherColumnsAreNotTargets) {
  for (const char* name : {"temp_fog_degc", "time_s", "table_deg", "gyro_Y_dph", "accel__g",
                           "sf_ppm", "gyroY", "sf_x_pct", "chamber_degc"}) {
    SCOPED_TRACE(name);
    EXPECT_FALSE(is_target_column(name));
  }
  try {
    target_of("gyroY", "--targets");
    FAIL() << "no error";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--targets");
    EXPECT_NE(std::string(e.what()).find("'gyroY' is not a target: a gyro (gyro_dph, "
                                         "gyro_NAME_dph), an accelerometer"),
              std::string::npos)
        << e.what();
  }
}

TEST(Target, ReadingsComeFromTheNamedColumn) {
  Recording r;
  r.source = "r.csv";
  r.time_s = {0, 1};
  r.gyro_dph = {1, 2};
  r.temp_fog_degc = {20, 21};
  r.accel_x_g = std::vector<double>{0.001, 0.002};
  r.extra.push_back({"sf_fog_ppm", {"12.5", "13"}});
  r.extra.push_back({"gyro_y_dph", {"3", "4.5"}});
  EXPECT_EQ(with_target(r, "gyro_y_dph").gyro_dph, (std::vector<double>{3, 4.5}));
  EXPECT_EQ(target_values(r, "accel_x_g"), (std::vector<double>{0.001, 0.002}));
  EXPECT_EQ(target_values(r, "sf_fog_ppm"), (std::vector<double>{12.5, 13}));
  EXPECT_EQ(with_target(r, "sf_fog_ppm").gyro_dph, (std::vector<double>{12.5, 13}));
  EXPECT_EQ(with_target(r, "gyro_dph").gyro_dph, r.gyro_dph);
  r.extra.back().cells[1] = "n/a";
  EXPECT_THROW(with_target(r, "gyro_y_dph"), InputError);  // a cell that is not a number
  try {
    target_values(r, "accel_y_g");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("r.csv"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("has no column 'accel_y_g', the accelerometer the model "
                                         "compensates (import it with --map accel_y_g=COLUMN)"),
              std::string::npos)
        << e.what();
  }
}

// One rule for a reference wherever it is given (a manifest, --reference, references=).
TEST(Target, AReferenceIsAFiniteNumberForATarget) {
  EXPECT_NO_THROW(check_reference("accel_z_g", 1.0, "--reference"));
  EXPECT_NO_THROW(check_reference("sf_fog_ppm", -kReferenceLimit, "--reference"));
  for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity(), 2e7}) {
    try {
      check_reference("accel_x_g", bad, "references");
      FAIL() << bad;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "references");
      EXPECT_NE(std::string(e.what()).find("is not a number of magnitude at most 10000000, g"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(check_reference("temp_fog_degc", 0.0, "references"), OptionError);
}

}  // namespace
}  // namespace fogdrift
