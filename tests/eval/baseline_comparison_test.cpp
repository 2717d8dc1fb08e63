// A model beside what needs no model (baseline_comparison.hpp): closed-form figures, the rules of
// harm and of "no better", and pooling.
#include "fogdrift/eval/baseline_comparison.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fogdrift::eval {
namespace {

TEST(BaselineComparison, FiguresHaveTheirClosedForms) {
  // y = 10 + (−1, 1, −1, 1): raw RMSE √(mean y²) = √101; recording mean RMSE 1; sample STD
  // √(4/3). A line of 10 leaves the same STD with RMSE 1; a model of y − 0.1 leaves RMSE 0.1.
  const std::vector<double> y = {9, 11, 9, 11};
  const std::vector<double> line(4, 10.0), model = {8.9, 10.9, 8.9, 10.9};
  const BaselineComparison c = compare_with_baselines(y, model, line, "T_fog_degc");
  EXPECT_EQ(c.rows, 4u);
  EXPECT_NEAR(c.raw_rmse, std::sqrt(101.0), 1e-13);
  EXPECT_NEAR(c.mean_rmse, 1.0, 1e-13);
  EXPECT_NEAR(c.raw_std, std::sqrt(4.0 / 3.0), 1e-13);
  EXPECT_NEAR(c.line_rmse, 1.0, 1e-13);
  EXPECT_NEAR(c.line_std, std::sqrt(4.0 / 3.0), 1e-13);
  EXPECT_NEAR(c.model_rmse, 0.1, 1e-13);
  EXPECT_NEAR(c.model_std, 0.0, 1e-13);
  EXPECT_TRUE(c.harms.empty());
  EXPECT_TRUE(c.no_better_than.empty());
}

TEST(BaselineComparison, EachRuleOfHarmIsNamedWithItsNumbers) {
  const std::vector<double> y = {1, -1, 1, -1};
  // A model that doubles the variation: worse than raw, adds variation, worse than the line.
  const std::vector<double> model = {-1, 1, -1, 1}, line(4, 0.0);
  const BaselineComparison c = compare_with_baselines(y, model, line, "T_fog_degc");
  ASSERT_EQ(c.harms.size(), 3u);
  EXPECT_NE(c.harms[0].find("worse than raw: RMSE 2 {unit} against 1"), std::string::npos)
      << c.harms[0];
  EXPECT_NE(c.harms[1].find("adds variation"), std::string::npos) << c.harms[1];
  EXPECT_NE(c.harms[2].find("worse than the line in T_fog_degc"), std::string::npos) << c.harms[2];
  EXPECT_TRUE(c.no_better_than.empty());  // harm is said, not "no better"
  // Without a line, that rule does not apply.
  EXPECT_EQ(compare_with_baselines(y, model, {}, "").harms.size(), 2u);
}

// A harm of a millionth is still a harm, and its figures are printed apart: "STD 0.04947 after
// against 0.04947 before" said nothing a user could check.
TEST(BaselineComparison, ATinyHarmIsPrintedWithTheDigitsThatShowIt) {
  const std::vector<double> y = {1, -1, 1, -1};
  const std::vector<double> model = {-1e-6, 1e-6, -1e-6, 1e-6};
  const BaselineComparison c = compare_with_baselines(y, model, {}, "");
  ASSERT_EQ(c.harms.size(), 2u);
  EXPECT_NE(c.harms[0].find("worse than raw: RMSE 1.000001 {unit} against 1"), std::string::npos)
      << c.harms[0];
  EXPECT_NE(c.harms[1].find("STD 1.154702 {unit} after against 1.154701 before"), std::string::npos)
      << c.harms[1];
}

TEST(BaselineComparison, AModelThatRemovesLessThanFivePercentIsNoBetter) {
  // A bias of 3 and a variation the model does not follow: the model removes the bias (as the
  // line does) and 2 % of the variation.
  const std::vector<double> y = {4, 2, 4, 2};
  const std::vector<double> model = {3.02, 2.98, 3.02, 2.98}, line(4, 3.0);
  const BaselineComparison c = compare_with_baselines(y, model, line, "T_fog_degc");
  EXPECT_TRUE(c.harms.empty());
  EXPECT_EQ(c.no_better_than,
            (std::vector<std::string>{"the recording mean", "the line in T_fog_degc"}));
  // At 10 % it is better than both.
  const std::vector<double> better = {3.1, 2.9, 3.1, 2.9};
  EXPECT_TRUE(compare_with_baselines(y, better, line, "T_fog_degc").no_better_than.empty());
}

TEST(BaselineComparison, PoolsRowsForRmseAndRecordingsForStd) {
  const BaselineComparison a =
      compare_with_baselines(std::vector<double>{1, -1}, std::vector<double>{0, 0}, {}, "");
  const BaselineComparison b = compare_with_baselines(std::vector<double>{3, 3, 3, 3},
                                                      std::vector<double>{3, 3, 3, 3}, {}, "");
  const std::vector<BaselineComparison> both = {a, b};
  const BaselineComparison p = pool(both, "");
  EXPECT_EQ(p.rows, 6u);
  EXPECT_NEAR(p.raw_rmse, std::sqrt((2 * 1.0 + 4 * 9.0) / 6), 1e-13);
  EXPECT_NEAR(p.model_rmse, std::sqrt(2.0 / 6), 1e-13);
  EXPECT_NEAR(p.raw_std, std::sqrt((2.0 + 0.0) / 2), 1e-13);  // a: sample STD √2
  EXPECT_FALSE(std::isfinite(p.line_rmse));
  // The model leaves a's variation: no better than the recording mean, pooled too.
  EXPECT_EQ(p.no_better_than, (std::vector<std::string>{"the recording mean"}));
}

}  // namespace
}  // namespace fogdrift::eval
