// `compensate`'s options (compensate_option_table.hpp) and the guard's one switch
// (guard_option.hpp): the same description in every table of a command that applies a model.
#include "fogdrift/model/compensate_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/stream/stream_option_table.hpp"

namespace fogdrift {
namespace {

/// What a user and the docs see of an option.
std::vector<std::string> face(const OptionSpec& s) {
  return {s.keyword, s.flag, std::string(to_string(s.type)), s.unit, s.range.text(), s.doc};
}

TEST(CompensateOptionTable, TheGuardIsOnByDefaultAndTurnedOffByName) {
  EXPECT_EQ(defaults_of(compensate_option_table()), (std::vector<std::string>{"true"}));
  CompensateOptions o;
  apply_option(compensate_option_table(), o, "guarded", "false");
  EXPECT_FALSE(o.guarded);
  EXPECT_THROW(apply_option(compensate_option_table(), o, "guarded", "half"), OptionError);
}

TEST(CompensateOptionTable, EveryCommandThatAppliesAModelHasTheOneGuardSwitch) {
  const std::vector<std::string> guard = face(compensate_option_table().front().spec);
  EXPECT_EQ(guard[1], "--no-guard");
  EXPECT_EQ(face(stream_option_table().front().spec), guard);
  EXPECT_EQ(face(eval::evaluation_option_table().front().spec), guard);
  EXPECT_EQ(face(eval::finding_option_table().front().spec), guard);
}

}  // namespace
}  // namespace fogdrift
