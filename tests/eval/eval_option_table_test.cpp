// The evaluations' options, described once (eval_option_table.hpp): defaults that are the option
// structs', one guard switch in both tables, and the segmentation's checks answered by the option
// that sets each field.
#include "fogdrift/eval/eval_option_table.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace fogdrift::eval {
namespace {

TEST(EvalOptionTable, DefaultsAreTheLibrarysAndTheGuardIsOneSwitch) {
  EXPECT_EQ(defaults_of(evaluation_option_table()), (std::vector<std::string>{"true", "false"}));
  EXPECT_EQ(defaults_of(finding_option_table()),
            (std::vector<std::string>{"true", "0.05", "2", "10"}));
  const OptionSpec& a = evaluation_option_table().front().spec;
  const OptionSpec& b = finding_option_table().front().spec;
  EXPECT_EQ(a.keyword, "guarded");
  EXPECT_EQ(a.flag, "--no-guard");
  EXPECT_EQ(a.doc, b.doc);
  EvaluationOptions e;
  apply_option(evaluation_option_table(), e, "guarded", "false");
  apply_option(evaluation_option_table(), e, "allan", "true");
  EXPECT_FALSE(e.guarded);
  EXPECT_TRUE(e.allan);
  FindingOptions f;
  apply_option(finding_option_table(), f, "tolerance_deg", "0.5");
  apply_option(finding_option_table(), f, "settle_s", "4");
  apply_option(finding_option_table(), f, "min_dwell_s", "30");
  EXPECT_EQ(f.segmentation.tolerance_deg, 0.5);
  EXPECT_EQ(f.segmentation.settle_s, 4.0);
  EXPECT_EQ(f.segmentation.min_dwell_s, 30.0);
  EXPECT_TRUE(f.guarded);
}

TEST(EvalOptionTable, SegmentationErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(finding_option_table());
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"tolerance_deg", "0"},
                                                        {"tolerance_deg", "45"},
                                                        {"settle_s", "-1"},
                                                        {"min_dwell_s", "0"}}) {
    FindingOptions o;
    // Refused at parsing, by its bounds, or by the check below.
    try {
      apply_option(finding_option_table(), o, keyword, text);
      validate(o.segmentation);
      ADD_FAILURE() << keyword << " = " << text << " passed";
    } catch (const OptionError& e) {
      EXPECT_EQ(option_word(specs, e.option(), false), keyword);
      EXPECT_EQ(option_word(specs, e.option(), true), keyword == "tolerance_deg" ? "--tolerance-deg"
                                                      : keyword == "settle_s"    ? "--settle-s"
                                                                                 : "--min-dwell-s");
    }
  }
}

}  // namespace
}  // namespace fogdrift::eval
