// How a model file is loaded (model_load_option_table.hpp): two switches, off by default, each
// setting its own field.
#include "fogdrift/model/model_load_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fogdrift {
namespace {

TEST(ModelLoadOptionTable, SwitchesOffByDefaultEachSettingItsOwnField) {
  const auto& t = model_load_option_table();
  EXPECT_EQ(defaults_of(t), (std::vector<std::string>{"false", "false"}));
  EXPECT_EQ(t[0].spec.flag, "--allow-edited");
  EXPECT_EQ(t[1].spec.flag, "--allow-old-format");
  ModelLoadOptions o;
  apply_option(t, o, "allow_edited", "true");
  EXPECT_TRUE(o.allow_edited);
  EXPECT_FALSE(o.allow_old_format);
  apply_option(t, o, "allow_old_format", "yes");
  EXPECT_TRUE(o.allow_old_format);
}

}  // namespace
}  // namespace fogdrift
