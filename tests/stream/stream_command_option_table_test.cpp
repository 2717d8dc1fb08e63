// `fogdrift stream`'s options (stream_command_option_table.hpp): the rate and --strict, then the
// compensator's table as it is, setting StreamCommandOptions::stream.
#include "fogdrift/stream/stream_command_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fogdrift/stream/stream_option_table.hpp"

namespace fogdrift {
namespace {

std::string refusal(const std::string& keyword, const std::string& text) {
  StreamCommandOptions o;
  try {
    apply_option(stream_command_option_table(), o, keyword, text);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(StreamCommandOptionTable, TheRateAndStrictnessThenTheCompensatorsOptions) {
  const std::vector<OptionSpec> specs = specs_of(stream_command_option_table());
  const std::vector<OptionSpec> compensator = specs_of(stream_option_table());
  ASSERT_EQ(specs.size(), compensator.size() + 2);
  EXPECT_EQ(specs[0].keyword, "rate_hz");
  EXPECT_EQ(specs[0].type, OptionType::number_or_none);
  EXPECT_EQ(specs[1].keyword, "strict");
  for (std::size_t i = 0; i < compensator.size(); ++i) {
    EXPECT_EQ(specs[i + 2].keyword, compensator[i].keyword);
    EXPECT_EQ(specs[i + 2].fields, compensator[i].fields);
  }
  std::vector<std::string> expected{"none", "false"};
  for (const std::string& d : defaults_of(stream_option_table())) expected.push_back(d);
  EXPECT_EQ(defaults_of(stream_command_option_table()), expected);
}

TEST(StreamCommandOptionTable, SetsTheCommandsFieldsAndTheCompensators) {
  StreamCommandOptions o;
  apply_option(stream_command_option_table(), o, "rate_hz", "100");
  apply_option(stream_command_option_table(), o, "strict", "true");
  apply_option(stream_command_option_table(), o, "guarded", "false");
  apply_option(stream_command_option_table(), o, "bridge_s", "2.5");
  ASSERT_TRUE(o.rate_hz);
  EXPECT_EQ(*o.rate_hz, 100.0);
  EXPECT_TRUE(o.strict);
  EXPECT_FALSE(o.stream.guarded);
  EXPECT_EQ(o.stream.faults.bridge_s, 2.5);
  apply_option(stream_command_option_table(), o, "rate_hz", "none");
  EXPECT_FALSE(o.rate_hz);
}

TEST(StreamCommandOptionTable, ARateOutsideWhatAStreamRunsAtIsRefused) {
  // 0 would otherwise read as "the model's own rate"; the bound is the one export-c has.
  EXPECT_NE(refusal("rate_hz", "0").find("0 Hz must be > 0, ≤ 10000"), std::string::npos);
  EXPECT_NE(refusal("rate_hz", "20000").find("must be > 0, ≤ 10000"), std::string::npos);
  EXPECT_NE(refusal("rate_hz", "fast").find("rate_hz"), std::string::npos);
  EXPECT_EQ(refusal("rate_hz", "10000"), "accepted");
  // `rate`, the name decimation_factor's errors use, is this option.
  EXPECT_EQ(option_word(specs_of(stream_command_option_table()), "rate", true), "--rate-hz");
}

}  // namespace
}  // namespace fogdrift
