// The fault policy's options, described once (fault_option_table.hpp): defaults that are
// FaultPolicy's, setters that set their own field only, and every field validate() names
// answered by the option that sets it.
#include "fogdrift/stream/fault_option_table.hpp"

#include <gtest/gtest.h>

namespace fogdrift {
namespace {

std::vector<std::string> fault_texts(const FaultPolicy& p) {
  std::vector<std::string> out;
  for (const auto& option : fault_option_table()) out.push_back(option.text_of(p));
  return out;
}

TEST(FaultOptionTable, EachOptionSetsItsOwnFieldOnly) {
  const FaultPolicy defaults;
  const std::vector<std::string> before = fault_texts(defaults);
  EXPECT_EQ(before, defaults_of(fault_option_table()));
  for (std::size_t i = 0; i < fault_option_table().size(); ++i) {
    FaultPolicy p;
    fault_option_table()[i].set(p, "7.5");
    const std::vector<std::string> after = fault_texts(p);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? "7.5" : before[j]) << fault_option_table()[i].spec.keyword;
  }
}

TEST(FaultOptionTable, ValidationErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(fault_option_table());
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"temp_max_degc", "-70"},
                                                        {"gyro_limit_dph", "0"},
                                                        {"bridge_s", "-1"},
                                                        {"hold_s", "1"},
                                                        {"stuck_s", "-1"},
                                                        {"stuck_delta_degc", "0"},
                                                        {"temp_jump_degc", "-1"}}) {
    FaultPolicy p;
    // Refused at parsing, by its bounds, or by the check below.
    try {
      apply_option(fault_option_table(), p, keyword, text);
      validate(p);
      ADD_FAILURE() << keyword << " = " << text << " passed";
    } catch (const OptionError& e) {
      EXPECT_EQ(option_word(specs, e.option(), false), keyword);
      EXPECT_EQ(
          option_word(specs, e.option(), true), "--" + [&] {
            std::string flag = keyword;
            for (char& c : flag)
              if (c == '_') c = '-';
            return flag;
          }());
    }
  }
}

}  // namespace
}  // namespace fogdrift
