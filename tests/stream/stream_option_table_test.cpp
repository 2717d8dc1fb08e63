// `stream`'s options (stream_option_table.hpp): the guard, then the fault policy's table as it is,
// setting StreamOptions::faults, its errors still answered by the fault options' flags.
#include "fogdrift/stream/stream_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift {
namespace {

TEST(StreamOptionTable, TheGuardThenTheFaultPolicy) {
  const std::vector<OptionSpec> specs = specs_of(stream_option_table());
  const std::vector<OptionSpec> faults = specs_of(fault_option_table());
  ASSERT_EQ(specs.size(), faults.size() + 1);
  EXPECT_EQ(specs[0].keyword, "guarded");
  for (std::size_t i = 0; i < faults.size(); ++i) {
    EXPECT_EQ(specs[i + 1].keyword, faults[i].keyword);
    EXPECT_EQ(specs[i + 1].fields, faults[i].fields);
  }
  std::vector<std::string> expected{"true"};
  for (const std::string& d : defaults_of(fault_option_table())) expected.push_back(d);
  EXPECT_EQ(defaults_of(stream_option_table()), expected);

  StreamOptions o;
  apply_option(stream_option_table(), o, "bridge_s", "2.5");
  apply_option(stream_option_table(), o, "guarded", "false");
  EXPECT_EQ(o.faults.bridge_s, 2.5);
  EXPECT_FALSE(o.guarded);
  EXPECT_THROW(apply_option(stream_option_table(), o, "bridge_s", "-1"), OptionError);
  // validate(FaultPolicy) names faults.FIELD, which the option answers.
  EXPECT_EQ(option_word(specs, "faults.hold_s", true), "--hold-s");
}

}  // namespace
}  // namespace fogdrift
