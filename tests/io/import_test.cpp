#include "fogdrift/io/import.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "fogdrift/base/error.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

TEST(ParseUnit, ConversionsAgainstHandComputedValues) {
  const double rad_s = 1e-5;  // 1e-5 rad/s = 1e-5·180/π·3600 °/h = 2.0626480624709636 °/h
  const auto r = parse_unit("gyro_dph", "rad/s");
  EXPECT_NEAR(rad_s * r.scale + r.offset, 2.0626480624709636, 1e-15);
  EXPECT_DOUBLE_EQ(parse_unit("gyro_dph", "deg/s").scale, 3600.0);
  EXPECT_DOUBLE_EQ(parse_unit("time_s", "ms").scale, 1e-3);
  const auto k = parse_unit("temp_fog_degc", "K");
  EXPECT_NEAR(300.0 * k.scale + k.offset, 26.85, 1e-12);
  const auto f = parse_unit("temp_acc1_degc", "degF");
  EXPECT_NEAR(-40.0 * f.scale + f.offset, -40.0, 1e-12);
  EXPECT_NEAR(212.0 * f.scale + f.offset, 100.0, 1e-12);
  const auto counts = parse_unit("temp_acc2_degc", "counts:0.0625:-50");
  EXPECT_DOUBLE_EQ(1000.0 * counts.scale + counts.offset, 12.5);
  EXPECT_NEAR(9.80665 * parse_unit("accel_x_g", "m/s2").scale, 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(std::numbers::pi * parse_unit("table_deg", "rad").scale, 180.0);
}

TEST(ParseUnit, UnknownUnitsNameTheOptionAndTheAcceptedUnits) {
  try {
    parse_unit("gyro_dph", "rpm");
    FAIL();
  } catch (const OptionError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--unit gyro_dph=rpm"), std::string::npos) << m;
    EXPECT_NE(m.find("rad/s"), std::string::npos) << m;
  }
  EXPECT_THROW(parse_unit("temp_fog_degc", "counts:0.1"), OptionError);
  EXPECT_THROW(parse_unit("temp_fog_degc", "counts:0:5"), OptionError);
  EXPECT_THROW(parse_unit("pressure", "Pa"), OptionError);
}

TEST(Import, ForeignLoggerWithMappingUnitsAndSemicolons) {
  test::TempDir dir;
  test::write_file(dir / "logger.csv",
                   "Zeit [ms];Rate X [rad/s];T0;T1;T2;Status\n"
                   "5000;0,0001;1000;1010;990;OK\n"
                   "6000;0,0002;1001;1011;991;OK\n");
  ImportOptions o;
  o.delimiter = ';';
  o.decimal_comma = true;
  o.time_from_zero = true;
  o.columns = {{"time_s", "Zeit [ms]"},
               {"gyro_dph", "Rate X [rad/s]"},
               {"temp_fog_degc", "T0"},
               {"temp_acc1_degc", "T1"},
               {"temp_acc2_degc", "T2"}};
  o.conversions = {{"time_s", parse_unit("time_s", "ms")},
                   {"gyro_dph", parse_unit("gyro_dph", "rad/s")},
                   {"temp_fog_degc", parse_unit("temp_fog_degc", "counts:0.0625:-40")},
                   {"temp_acc1_degc", parse_unit("temp_acc1_degc", "counts:0.0625:-40")},
                   {"temp_acc2_degc", parse_unit("temp_acc2_degc", "counts:0.0625:-40")}};
  const Recording r = import_recording(dir / "logger.csv", o);
  EXPECT_EQ(r.time_s, (std::vector<double>{0.0, 1.0}));
  EXPECT_NEAR(r.gyro_dph[0], 20.626480624709636, 1e-12);
  EXPECT_DOUBLE_EQ(r.temp_fog_degc[0], 22.5);
  EXPECT_DOUBLE_EQ(r.temp_acc1_degc[1], 23.1875);
  ASSERT_EQ(r.extra.size(), 1u);
  EXPECT_EQ(r.extra[0].name, "Status");
}

TEST(Import, MappingToAnAbsentColumnListsTheColumns) {
  test::TempDir dir;
  test::write_file(dir / "l.csv", "t,w,a,b,c\n1,2,3,4,5\n2,2,3,4,5\n");
  ImportOptions o;
  o.columns = {{"gyro_dph", "Rate"}};
  try {
    import_recording(dir / "l.csv", o);
    FAIL();
  } catch (const OptionError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("--map gyro_dph=Rate"), std::string::npos) << m;
    EXPECT_NE(m.find("'t', 'w', 'a', 'b', 'c'"), std::string::npos) << m;
  }
}

TEST(Import, BadCellNamesForeignLineAndColumn) {
  test::TempDir dir;
  test::write_file(dir / "l.csv", "t,w,a,b,c\n1,2,3,4,5\n2,x,3,4,5\n");
  ImportOptions o;
  o.columns = {{"time_s", "t"},
               {"gyro_dph", "w"},
               {"temp_fog_degc", "a"},
               {"temp_acc1_degc", "b"},
               {"temp_acc2_degc", "c"}};
  try {
    import_recording(dir / "l.csv", o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("l.csv:3:2: column 'w' (for gyro_dph)"), std::string::npos)
        << e.what();
  }
  o.decimal_comma = true;  // impossible with ',' as the delimiter
  EXPECT_THROW(import_recording(dir / "l.csv", o), OptionError);
}

TEST(Import, PreambleCommentsDatesAndSlowChannels) {
  test::TempDir dir;
  // A logger that writes its settings first, comments between rows, date-time stamps, and a
  // thermometer read every other sample.
  test::write_file(dir / "log.csv",
                   "Logger v2.1\n"
                   "serial,4711\n"
                   "stamp,rate,temp\n"
                   "2024-03-01 12:00:00.000,0.5,20.0\n"
                   "# operator opened the chamber\n"
                   "2024-03-01 12:00:00.500,0.6,\n"
                   "2024-03-01 12:00:01.000,0.7,20.5\n");
  ImportOptions o;
  o.skip_lines = 2;
  o.comment = '#';
  o.hold_empty = true;
  o.columns = {{"time_s", "stamp"}, {"gyro_dph", "rate"}, {"temp_fog_degc", "temp"}};
  o.conversions = {{"time_s", parse_unit("time_s", "iso8601")}};
  ImportReport report;
  const Recording r = import_recording(dir / "log.csv", o, &report);
  EXPECT_EQ(r.time_s, (std::vector<double>{0.0, 0.5, 1.0}));  // from the first stamp
  EXPECT_EQ(r.temp_fog_degc, (std::vector<double>{20.0, 20.0, 20.5}));
  EXPECT_EQ(report.held.at("temp_fog_degc"), 1u);
  EXPECT_TRUE(r.temp_acc1_degc.empty());  // the unit has one thermometer
  // Without --hold-empty the empty cell is an error on its line.
  o.hold_empty = false;
  try {
    import_recording(dir / "log.csv", o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_EQ(e.column(), 3u);
  }
}

TEST(ParseUnit, CountsAndRegistersForEveryColumn) {
  // A MEMS gyro register: 131 counts per °/s, so °/h = counts · 3600/131.
  const auto g = parse_unit("gyro_dph", "int16:27.480916030534353:0");
  EXPECT_EQ(g.signed_bits, 16);
  EXPECT_DOUBLE_EQ(131.0 * g.scale, 3600.0);
  EXPECT_DOUBLE_EQ(parse_unit("accel_x_g", "counts:0.001:0").scale, 0.001);
  EXPECT_THROW(parse_unit("time_s", "iso"), OptionError);
}

TEST(Import, TimeFromTheSampleRateWhenTheFileHasNone) {
  test::TempDir dir;
  test::write_file(dir / "rate.csv", "wx,t\n1,20\n2,20\n3,21\n");
  ImportOptions o;
  o.columns = {{"gyro_dph", "wx"}, {"temp_fog_degc", "t"}};
  EXPECT_THROW(import_recording(dir / "rate.csv", o), OptionError);  // no time column
  o.time_from_rate_hz = 4;
  EXPECT_EQ(import_recording(dir / "rate.csv", o).time_s, (std::vector<double>{0, 0.25, 0.5}));
  o.time_from_rate_hz = -1;
  try {
    import_recording(dir / "rate.csv", o);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--time-from-rate-hz");
  }
}

TEST(Import, BadRegistersStampsAndCyclesNameTheirCell) {
  test::TempDir dir;
  auto error_of = [&](const std::string& text, const ImportOptions& o) -> InputError {
    test::write_file(dir / "bad.csv", text);
    try {
      import_recordings(dir / "bad.csv", o);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "accepted: " << text;
    return InputError("", 0, 0, "");
  };
  ImportOptions o;
  o.columns = {{"gyro_dph", "g"}, {"temp_fog_degc", "t"}};
  o.time_from_rate_hz = 1;
  o.conversions = {{"temp_fog_degc", parse_unit("temp_fog_degc", "int16:0.01:0")}};
  const InputError reg = error_of("g,t\n0,100\n0,70000\n", o);  // above 2^16 − 1
  EXPECT_EQ(reg.line(), 3u);
  EXPECT_EQ(reg.column(), 2u);
  EXPECT_NE(
      reg.message().find("is not an int16 register value (a whole number in [-32768, 65535])"),
      std::string::npos)
      << reg.what();
  EXPECT_NE(error_of("g,t\n0,100\n0,1.5\n", o).message().find("int16 register"), std::string::npos);

  ImportOptions d;
  d.columns = {{"time_s", "when"}, {"gyro_dph", "g"}, {"temp_fog_degc", "t"}};
  d.conversions = {{"time_s", parse_unit("time_s", "iso8601")}};
  const InputError stamp = error_of("when,g,t\n2024-03-01 12:00:00,0,20\n12:00:01,0,20\n", d);
  EXPECT_EQ(stamp.line(), 3u);
  EXPECT_NE(stamp.message().find("'12:00:01' is not a date and time"), std::string::npos);

  ImportOptions c;
  c.columns = {{"gyro_dph", "g"}, {"temp_fog_degc", "t"}};
  c.split_at_reset = true;
  const InputError cycle = error_of("time_s,g,t\n1,0,20\n2,0,20\n0,0,20\n", c);
  EXPECT_EQ(cycle.line(), 4u);
  EXPECT_NE(cycle.message().find("a power cycle of a single sample"), std::string::npos);
  const InputError twice = error_of("time_s,g,t\n1,0,20\n1,0,20\n", c);
  EXPECT_NE(twice.message().find("the same stamp twice"), std::string::npos);

  // A file's own time column and a time from the rate are not both taken.
  o.columns["time_s"] = "g";
  test::write_file(dir / "both.csv", "g,t\n0,100\n0,100\n");
  EXPECT_THROW(import_recording(dir / "both.csv", o), OptionError);
}

// A chamber sheet as a test house keeps it: HH:MM every 5 minutes through midnight, thermometers
// in °F, a BOM, trailing empty columns and rows, and no gyro.
constexpr const char* kSheet =
    "\xEF\xBB\xBFTime,Case (F),Air (C),,\n"
    "23:50,68.0,20.0,,\n"
    "23:55,69.8,21.0,,\n"
    "00:00,71.6,22.0,,\n"
    "00:05,73.4,23.0,,\n"
    ",,,,\n";

// Found by a new user (issue 58): a sheet's last rows had a time and empty cells, and import
// --partial stopped at the first ("'' is not a finite number"); --hold-empty invented readings.
TEST(Import, RowsWithATimeAndNoValuesArePadding) {
  test::TempDir dir;
  test::write_file(dir / "sheet.csv",
                   "Time,Air (C),Case (F)\n"
                   "10:00,20.0,68.0\n"
                   "10:05,21.0,69.8\n"
                   "10:10,,\n"
                   "10:15, ,\n");
  ImportOptions o;
  o.columns = {{"time_s", "Time"}, {"temp_acc1_degc", "Case (F)"}, {"chamber_degc", "Air (C)"}};
  o.conversions = {{"time_s", parse_unit("time_s", "clock")},
                   {"temp_acc1_degc", parse_unit("temp_acc1_degc", "degF")}};
  o.allow_partial = true;
  o.time_zero = "10:00";
  ImportReport report;
  const Recording sheet = import_recording(dir / "sheet.csv", o, &report);
  EXPECT_EQ(sheet.time_s, (std::vector<double>{0.0, 300.0}));
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0], "dropped 2 row(s) with a time and no values (lines 4..5)");
}

TEST(Import, AChamberSheetBecomesALogToJoin) {
  test::TempDir dir;
  test::write_file(dir / "sheet.csv", kSheet);
  ImportOptions o;
  o.columns = {{"time_s", "Time"}, {"temp_acc1_degc", "Case (F)"}, {"chamber_degc", "Air (C)"}};
  o.conversions = {{"time_s", parse_unit("time_s", "clock")},
                   {"temp_acc1_degc", parse_unit("temp_acc1_degc", "degF")}};
  try {
    import_recording(dir / "sheet.csv", o);
    FAIL() << "a sheet without a gyro is refused unless it is a log to join";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--map gyro_dph=COLUMN");
    EXPECT_NE(std::string(e.what()).find("--partial"), std::string::npos) << e.what();
  }
  o.allow_partial = true;
  o.time_zero = "23:57";  // the unit's power-on, on the same clock
  ImportReport report;
  const Recording sheet = import_recording(dir / "sheet.csv", o, &report);
  EXPECT_TRUE(sheet.partial);
  EXPECT_TRUE(sheet.gyro_dph.empty());
  EXPECT_EQ(report.missing, (std::vector<std::string>{"gyro_dph", "temp_fog_degc"}));
  ASSERT_EQ(report.notes.size(), 2u);
  EXPECT_EQ(report.notes[0], "dropped 2 empty column(s) with no name (column 4, 5)");
  // Through midnight, counted from 23:57: -7, -2, 3 and 8 minutes.
  EXPECT_EQ(sheet.time_s, (std::vector<double>{-420.0, -120.0, 180.0, 480.0}));
  EXPECT_NEAR(sheet.temp_acc1_degc[1], 21.0, 1e-12);  // 69.8 °F
  EXPECT_EQ(*sheet.chamber_degc, (std::vector<double>{20.0, 21.0, 22.0, 23.0}));
  // Written and read back as a log; a recording reader refuses it and names join.
  write_recording(dir / "sheet_fd.csv", sheet);
  EXPECT_EQ(read_log(dir / "sheet_fd.csv").time_s, sheet.time_s);
  try {
    read_recording(dir / "sheet_fd.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fogdrift join"), std::string::npos) << e.what();
  }
}

TEST(Import, TimeZeroIsValidatedAndAWholeRecordingMayNotStartBeforeIt) {
  test::TempDir dir;
  test::write_file(dir / "unit.csv",
                   "stamp,rate,t\n2020-03-07 15:41:00,1,20\n2020-03-07 15:41:01,1,20\n");
  ImportOptions o;
  o.columns = {{"time_s", "stamp"}, {"gyro_dph", "rate"}, {"temp_fog_degc", "t"}};
  o.conversions = {{"time_s", parse_unit("time_s", "iso8601")}};
  o.time_zero = "2020-03-07 15:40:50";
  EXPECT_EQ(import_recording(dir / "unit.csv", o).time_s, (std::vector<double>{10.0, 11.0}));
  o.time_zero = "15:40:50";  // a time of day for date-and-time stamps
  EXPECT_THROW(import_recording(dir / "unit.csv", o), OptionError);
  o.time_zero = "2020-03-07 15:41:00.5";  // after the first stamp: negative time
  try {
    import_recording(dir / "unit.csv", o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_NE(std::string(e.what()).find("--time-zero"), std::string::npos) << e.what();
  }
  o.conversions.clear();
  o.time_zero = "15:40";
  EXPECT_THROW(import_recording(dir / "unit.csv", o), OptionError);  // stamps read as numbers
}

TEST(Import, FurtherGyroAxesAndThermometersAreMappedWithTheirUnits) {
  test::TempDir dir;
  test::write_file(dir / "imu.csv",
                   "ms,gx,gy,gz,t\n0,0.001,0.002,-0.5,20\n20,0.001,0.004,-0.25,20\n");
  ImportOptions o;
  o.columns = {{"time_s", "ms"},
               {"gyro_dph", "gx"},
               {"gyro_y_dph", "gy"},
               {"gyro_z_dph", "gz"},
               {"temp_fog_degc", "t"}};
  o.conversions = {{"time_s", parse_unit("time_s", "ms")},
                   {"gyro_dph", parse_unit("gyro_dph", "deg/s")},
                   {"gyro_y_dph", parse_unit("gyro_y_dph", "deg/s")},
                   {"gyro_z_dph", parse_unit("gyro_z_dph", "rad/s")}};
  const Recording r = import_recording(dir / "imu.csv", o);
  EXPECT_EQ(r.numeric_column("gyro_y_dph"), (std::vector<double>{7.2, 14.4}));
  const double rad = 180.0 / std::numbers::pi * 3600.0;
  EXPECT_NEAR(r.numeric_column("gyro_z_dph")[1], -0.25 * rad, 1e-9);
  ASSERT_EQ(r.extra.size(), 2u);  // the mapped columns are not kept twice
  for (const char* bad : {"gyro_y", "Gyro_Y_dph", "gyro__dph", "temp_degc", "gyro_y_degc"})
    EXPECT_THROW(parse_unit(bad, "deg/s"), OptionError) << bad;
  EXPECT_NO_THROW(parse_unit("temp_tc3_degc", "degF"));
  EXPECT_THROW(parse_unit("temp_tc3_degc", "deg/s"), OptionError);        // not a temperature unit
  o.conversions["temp_board_degc"] = parse_unit("temp_board_degc", "K");  // unit, no --map
  EXPECT_THROW(import_recording(dir / "imu.csv", o), OptionError);
}

}  // namespace
}  // namespace fogdrift
