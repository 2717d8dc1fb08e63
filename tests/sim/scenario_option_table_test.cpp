// The simulator's protocol options, described once (scenario_option_table.hpp): defaults that
// are the library's, setters that set their own field only, and every field validate() names
// answered by the option that sets it.
#include "fogdrift/sim/scenario_option_table.hpp"

#include <gtest/gtest.h>

#include <set>

#include "option_values.hpp"

namespace fogdrift::sim {
namespace {

template <class O>
std::vector<std::string> texts_of(const OptionTable<O>& table, const O& o) {
  std::vector<std::string> texts;
  for (const auto& option : table) texts.push_back(option.text_of(o));
  return texts;
}

/// A value of the option other than `current`, as a user would write it, within its bounds.
template <class O>
std::string another_value(const Option<O>& option, const std::string& current) {
  switch (option.spec.type) {
    case OptionType::whole:
      return test::allowed_other(option.spec, current, {"2", "3"});
    case OptionType::number:
      return test::allowed_other(option.spec, current, {"45", "50", "5", "6"});
    case OptionType::numbers:
      return current == "-5,35" ? "20" : "-5,35";
    case OptionType::names:
      return current == "soaked,warm" ? "ramping" : "soaked,warm";
    case OptionType::choice:
      return current == "warm" ? "ramping" : "warm";
    default:
      break;
  }
  ADD_FAILURE() << option.spec.keyword << " has a type this table does not use";
  return current;
}

template <class O>
void each_option_sets_its_own_field_only(const OptionTable<O>& table, const O& defaults) {
  const std::vector<std::string> before = texts_of(table, defaults);
  std::set<std::string> keywords, flags;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& option = table[i];
    EXPECT_TRUE(keywords.insert(option.spec.keyword).second) << option.spec.keyword;
    EXPECT_TRUE(flags.insert(option.spec.flag).second) << option.spec.flag;
    EXPECT_FALSE(option.spec.doc.empty()) << option.spec.keyword;
    O o = defaults;
    option.set(o, option.text_of(defaults));  // the default reads back unchanged
    EXPECT_EQ(texts_of(table, o), before) << option.spec.keyword;
    const std::string value = another_value(option, before[i]);
    option.set(o, value);
    const std::vector<std::string> after = texts_of(table, o);
    for (std::size_t j = 0; j < after.size(); ++j) {
      if (j == i)
        EXPECT_EQ(after[j], value) << option.spec.keyword;
      else
        EXPECT_EQ(after[j], before[j])
            << option.spec.keyword << " changed " << table[j].spec.keyword;
    }
  }
}

TEST(ScenarioOptionTable, EachOptionSetsItsOwnFieldOnly) {
  each_option_sets_its_own_field_only(calibration_option_table(), CalibrationOptions{});
  each_option_sets_its_own_field_only(northfind_option_table(), NorthfindOptions{});
  each_option_sets_its_own_field_only(northfind_option_table(), stable_defaults());
  EXPECT_EQ(defaults_of(northfind_option_table(), stable_defaults())[0], "25");
}

/// The keyword whose option answers the error that setting `keyword` to `text` throws: at
/// parsing (its bounds) or in validate().
template <class O, class Validate>
std::string answered_by(const OptionTable<O>& table, const std::string& keyword,
                        const std::string& text, Validate validate) {
  try {
    O o;
    apply_option(table, o, keyword, text);
    validate(o);
  } catch (const OptionError& e) {
    return option_word(specs_of(table), e.option(), false);
  }
  return "(valid)";
}

TEST(ScenarioOptionTable, ValidationErrorsAreAnsweredByAnOption) {
  const auto& cal = calibration_option_table();
  const auto check_cal = [](const CalibrationOptions& o) { validate(o); };
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"temps_degc", "150"},
                                                        {"start_up_temps_degc", "0,150"},
                                                        {"repetitions", "0"},
                                                        {"test_repetitions", "9"},
                                                        {"soak_s", "-1"},
                                                        {"chamber_setpoint_sd_degc", "20"},
                                                        {"latitude_deg", "89"},
                                                        {"output_rate_hz", "0"},
                                                        {"warm_off_s", "-1"},
                                                        {"ramp_degc_per_min", "0"}}) {
    EXPECT_EQ(answered_by(cal, keyword, text, check_cal), keyword) << text;
  }
  const auto& nf = northfind_option_table();
  for (const std::string scenario : {"northfind", "stable"}) {
    const auto check_nf = [&](const NorthfindOptions& o) { validate(o, scenario); };
    for (const auto& [keyword, text] :
         std::vector<std::pair<std::string, std::string>>{{"temps_degc", "-80"},
                                                          {"findings", "0"},
                                                          {"position_s", "5"},
                                                          {"soak_s", "-1"},
                                                          {"latitude_deg", "-86"},
                                                          {"output_rate_hz", "2001"},
                                                          {"warm_off_s", "2e6"},
                                                          {"ramp_degc_per_min", "500"}}) {
      EXPECT_EQ(answered_by(nf, keyword, text, check_nf), keyword) << scenario << " " << text;
    }
  }
  // A name that is not an approach, and sweep, which is not a calibration approach.
  CalibrationOptions o;
  EXPECT_THROW(apply_option(cal, o, "approaches", "sunny"), OptionError);
  EXPECT_EQ(answered_by(cal, "approaches", "soaked,sweep", check_cal), "approaches");
}

}  // namespace
}  // namespace fogdrift::sim
