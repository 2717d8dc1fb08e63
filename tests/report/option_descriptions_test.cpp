// Every command's described options: a numeric range is typed, so what the docs say is allowed
// is what the parsers check, and the JSON gives it to a machine.
#include "fogdrift/report/option_descriptions.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace fogdrift::report {
namespace {

bool numeric(OptionType type) {
  return type == OptionType::whole || type == OptionType::number || type == OptionType::numbers ||
         type == OptionType::seconds_or_auto || type == OptionType::whole_or_auto ||
         type == OptionType::number_or_none;
}

TEST(OptionDescriptions, NumericBoundsAreTypedNotWritten) {
  // A note that begins as bounds do ("≥ 0", "1 … 4", "> 0, ≤ 100") would be documented and not
  // checked; a rule between options ("> {c_min}") is the library's to check.
  const std::regex written_bound(R"(^(≥|≤|>|<) ?-?[0-9]|^-?[0-9.]+(e[0-9]+)? …)");
  std::size_t bounded = 0;
  for (const std::string_view command : described_commands()) {
    const OptionDescriptions d = option_descriptions(command);
    for (const OptionSpec& s : d.specs) {
      if (!numeric(s.type)) continue;
      EXPECT_FALSE(std::regex_search(s.range.note, written_bound))
          << command << " " << s.keyword << ": '" << s.range.note << "'";
      bounded += s.range.has_bounds();
    }
  }
  EXPECT_GE(bounded, 50u);
}

TEST(OptionDescriptions, JsonGivesTheBounds) {
  const auto j = options_json(option_descriptions("stream"));
  bool seen = false;
  for (const auto& o : j) {
    if (o["keyword"] != "bridge_s") continue;
    seen = true;
    EXPECT_EQ(o["allowed"], "≥ 0");
    EXPECT_EQ(o["minimum"], 0.0);
    EXPECT_EQ(o["minimum_excluded"], false);
    EXPECT_TRUE(o["maximum"].is_null());
  }
  EXPECT_TRUE(seen);
}

}  // namespace
}  // namespace fogdrift::report
