// How `fogdrift campaign` cuts a long log, described once (cut_option_table.hpp): defaults that
// are CutOptions', setters that set their own field only, and cut()'s errors answered by the
// option that sets the field.
#include "fogdrift/io/cut_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace fogdrift {
namespace {

TEST(CutOptionTable, DefaultsAreTheLibrarysAndEachOptionSetsItsOwnField) {
  const std::vector<std::string> before = defaults_of(cut_option_table());
  EXPECT_EQ(before, (std::vector<std::string>{"0", "0", "false", "0.05", "600"}));
  const std::vector<std::pair<std::string, std::string>> given = {
      {"cut_gap_s", "600"},
      {"cut_window_s", "1800"},
      {"cut_plateaus", "true"},
      {"plateau_rate_degc_per_min", "0.1"},
      {"plateau_min_s", "300"}};
  for (std::size_t i = 0; i < given.size(); ++i) {
    CutOptions o;
    apply_option(cut_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(cut_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
}

TEST(CutOptionTable, RefusalsAndTheLibrarysErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(cut_option_table());
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"cut_gap_s", "-1"},
                                                        {"cut_window_s", "-5"},
                                                        {"plateau_rate_degc_per_min", "0"},
                                                        {"plateau_min_s", "0"}}) {
    CutOptions o;
    EXPECT_THROW(apply_option(cut_option_table(), o, keyword, text), OptionError) << keyword;
  }
  // cut() names its fields (gap_s, …), which the options answer in each front end's words.
  for (const auto& [field, keyword] : std::vector<std::pair<std::string, std::string>>{
           {"gap_s", "cut_gap_s"}, {"window_s", "cut_window_s"}, {"plateaus", "cut_plateaus"}}) {
    EXPECT_EQ(option_word(specs, field, false), keyword);
  }
  EXPECT_EQ(option_word(specs, "gap_s", true), "--cut-gap-s");
}

}  // namespace
}  // namespace fogdrift
