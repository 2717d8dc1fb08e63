// `fogdrift import`'s options, described once (import_option_table.hpp): defaults that are the
// library's, setters that set their own field only, and import_plan's checks between options,
// each answered by an option.
#include "fogdrift/io/import_option_table.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fogdrift {
namespace {

TEST(ImportOptionTable, DefaultsAreTheLibrarysAndEachOptionSetsItsOwnField) {
  const std::vector<std::string> before = defaults_of(import_option_table());
  const std::vector<std::pair<std::string, std::string>> given = {
      {"map", "gyro_dph=Rate, X [rad/s]\ntime_s=t=ms"},
      {"units", "gyro_dph=rad/s"},
      {"delimiter", "tab"},
      {"decimal_comma", "true"},
      {"time_from_zero", "true"},
      {"drop_extra", "true"},
      {"skip_lines", "3"},
      {"time_from_rate_hz", "100"},
      {"time_zero", "15:41:07"},
      {"partial", "true"},
      {"comment", "#"},
      {"hold_empty", "true"},
      {"split_at_reset", "true"},
      {"hampel", "true"},
      {"hampel_half_window", "5"},
      {"hampel_sigma", "3"},
      {"outlier_columns", "gyro_dph"},
      {"rate_hz", "10"},
      {"step_s", "60"},
      {"method", "linear"},
      {"max_gap_s", "0"}};
  ASSERT_EQ(given.size(), before.size());
  for (std::size_t i = 0; i < given.size(); ++i) {
    ImportRunOptions o;
    apply_option(import_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(import_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
  ImportRunOptions o;
  apply_option(import_option_table(), o, "drop_extra", "true");
  EXPECT_FALSE(o.read.keep_extra);
  apply_option(import_option_table(), o, "delimiter", ";");
  EXPECT_EQ(o.read.delimiter, ';');
}

/// The keyword of the option that answers `options`' refusal by import_plan().
std::string refused_by(const std::vector<std::pair<std::string, std::string>>& given) {
  ImportRunOptions o;
  try {
    for (const auto& [keyword, text] : given) apply_option(import_option_table(), o, keyword, text);
    import_plan(o);
  } catch (const OptionError& e) {
    return option_word(specs_of(import_option_table()), e.option(), false);
  }
  return "(accepted)";
}

// The column map and units: one NAME=VALUE a flag, so a foreign name may hold commas and '=';
// each name once; the units read by parse_unit when the plan is made.
TEST(ImportOptionTable, TheMapAndUnitsAreAssignments) {
  ImportRunOptions o;
  apply_option(import_option_table(), o, "map", "gyro_dph=Rate, X [rad/s]\ntemp_fog_degc=T0");
  EXPECT_EQ(o.read.columns, (std::map<std::string, std::string>{{"gyro_dph", "Rate, X [rad/s]"},
                                                                {"temp_fog_degc", "T0"}}));
  apply_option(import_option_table(), o, "units", "gyro_dph=rad/s\ntemp_fog_degc=K");
  const ImportPlan plan = import_plan(o);
  ASSERT_EQ(plan.read.conversions.size(), 2u);
  EXPECT_EQ(plan.read.conversions.at("gyro_dph").scale, parse_unit("gyro_dph", "rad/s").scale);
  for (const auto& [keyword, text] : std::vector<std::pair<std::string, std::string>>{
           {"map", "gyro_dph=a\ngyro_dph=b"}, {"map", "gyro_dph="}, {"units", "gyro_dph"}}) {
    ImportRunOptions r;
    EXPECT_THROW(apply_option(import_option_table(), r, keyword, text), OptionError) << text;
  }
  ImportRunOptions bad;
  apply_option(import_option_table(), bad, "units", "gyro_dph=furlongs");
  try {
    import_plan(bad);
    ADD_FAILURE() << "an unknown unit was accepted";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--unit gyro_dph=furlongs");  // the item, as parse_unit names it
  }
}

TEST(ImportOptionTable, OptionsThatContradictOrDoNothingAreRefusedByName) {
  EXPECT_EQ(refused_by({{"rate_hz", "1"}, {"step_s", "1"}}), "step_s");
  EXPECT_EQ(refused_by({{"method", "mean"}}), "method");
  EXPECT_EQ(refused_by({{"max_gap_s", "30"}}), "max_gap_s");
  EXPECT_EQ(refused_by({{"hampel_sigma", "3"}}), "hampel_sigma");
  EXPECT_EQ(refused_by({{"hampel_half_window", "5"}}), "hampel_half_window");
  EXPECT_EQ(refused_by({{"outlier_columns", "gyro_dph"}}), "outlier_columns");
  EXPECT_EQ(refused_by({{"comment", "//"}}), "comment");
  EXPECT_EQ(refused_by({{"delimiter", ":"}}), "delimiter");
  EXPECT_EQ(refused_by({{"rate_hz", "-1"}}), "rate_hz");
  EXPECT_EQ(refused_by({{"hampel", "true"}, {"hampel_sigma", "3"}}), "(accepted)");
}

TEST(ImportOptionTable, ThePlanCarriesTheGridAndTheFilter) {
  ImportRunOptions o;
  apply_option(import_option_table(), o, "rate_hz", "4");
  apply_option(import_option_table(), o, "max_gap_s", "auto");
  apply_option(import_option_table(), o, "hampel", "true");
  apply_option(import_option_table(), o, "hampel_sigma", "3");
  const ImportPlan plan = import_plan(o);
  ASSERT_TRUE(plan.grid);
  EXPECT_EQ(plan.grid->step_s, 0.25);
  EXPECT_EQ(plan.grid->max_gap_s, -1.0);  // regrid's default: 10 steps
  ASSERT_TRUE(plan.read.outliers);
  EXPECT_EQ(plan.read.outliers->n_sigma, 3.0);
  EXPECT_FALSE(import_plan(ImportRunOptions{}).grid);
}

}  // namespace
}  // namespace fogdrift
