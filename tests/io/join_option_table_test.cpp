// `fogdrift join`'s options, described once (join_option_table.hpp): defaults that are
// JoinOptions', setters that set their own field only, the offset's searches and their width,
// auto limits, and the library's errors answered by the option that sets the field.
#include "fogdrift/io/join_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace fogdrift {
namespace {

TEST(JoinOptionTable, DefaultsAreTheLibrarysAndEachOptionSetsItsOwnField) {
  const std::vector<std::string> before = defaults_of(join_option_table());
  EXPECT_EQ(before, (std::vector<std::string>{"", "false", "linear", "none", "", "0", "false",
                                              "auto", "auto"}));
  const std::vector<std::pair<std::string, std::string>> given = {
      {"columns", "chamber_degc,tc_case_degc"},
      {"replace", "true"},
      {"method", "nearest"},
      {"offset_s", "-3.5"},
      {"offset_from", "temp_fog_degc=T_case,chamber_degc"},
      {"offset_range_s", "0"},  // 0 is its default: set with searches below
      {"force", "true"},
      {"max_step_s", "30"},
      {"max_age_s", "2"}};
  for (std::size_t i = 0; i < given.size(); ++i) {
    JoinOptions o;
    apply_option(join_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(join_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
}

TEST(JoinOptionTable, TheSearchesAndTheirWidthReachTheLibrary) {
  JoinOptions o;
  apply_option(join_option_table(), o, "offset_from", "temp_fog_degc=T_case,chamber_degc");
  apply_option(join_option_table(), o, "offset_range_s", "120");
  ASSERT_EQ(o.estimates.size(), 2u);
  EXPECT_EQ(o.estimates[0].recording_column, "temp_fog_degc");
  EXPECT_EQ(o.estimates[0].log_column, "T_case");
  EXPECT_EQ(o.estimates[1].recording_column, "chamber_degc");
  EXPECT_EQ(o.estimates[1].log_column, "chamber_degc");
  EXPECT_EQ(o.estimates[0].range_s, 120.0);
  EXPECT_EQ(o.estimates[1].range_s, 120.0);
  apply_option(join_option_table(), o, "max_step_s", "auto");
  EXPECT_FALSE(o.max_step_s);
}

/// The keyword of the option the refusal of `keyword` = `text` names.
std::string refused_by(const std::string& keyword, const std::string& text) {
  JoinOptions o;
  try {
    apply_option(join_option_table(), o, keyword, text);
  } catch (const OptionError& e) {
    return option_word(specs_of(join_option_table()), e.option(), false);
  }
  return "(accepted)";
}

TEST(JoinOptionTable, RefusalsAreAnsweredByTheirOption) {
  EXPECT_EQ(refused_by("offset_from", "=T_case"), "offset_from");
  EXPECT_EQ(refused_by("offset_from", "a=b,"), "offset_from");
  EXPECT_EQ(refused_by("offset_range_s", "60"), "offset_range_s");  // no search to widen
  EXPECT_EQ(refused_by("offset_range_s", "-1"), "offset_range_s");
  EXPECT_EQ(refused_by("max_step_s", "0"), "max_step_s");
  EXPECT_EQ(refused_by("method", "cubic"), "method");
  EXPECT_EQ(refused_by("columns", "a,,b"), "columns");
  // The library's own names: a column the files lack is the search's, which offset_from sets.
  EXPECT_EQ(option_word(specs_of(join_option_table()), "estimate", true), "--offset-from");
}

}  // namespace
}  // namespace fogdrift
