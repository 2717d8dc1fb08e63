// `inspect`'s options (inspect_option_table.hpp).
#include "fogdrift/io/inspect_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fogdrift {
namespace {

TEST(InspectOptionTable, TheLogSwitchIsOffByDefault) {
  EXPECT_EQ(defaults_of(inspect_option_table()), (std::vector<std::string>{"false"}));
  EXPECT_EQ(inspect_option_table().front().spec.flag, "--log");
  InspectOptions o;
  apply_option(inspect_option_table(), o, "log", "true");
  EXPECT_TRUE(o.log);
}

}  // namespace
}  // namespace fogdrift
