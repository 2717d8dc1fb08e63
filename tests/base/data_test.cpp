// Regression data (data.hpp): subsets keep rows, targets and weights together, and validate
// names the sample and the rule broken.
#include "fogdrift/base/data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

Data three() {
  Data d;
  d.rows = 3, d.cols = 2;
  d.x = {1, 2, 3, 4, 5, 6};
  d.y = {10, 20, 30};
  d.weight = {1, 2, 3};
  return d;
}

TEST(Data, SubsetKeepsEachRowWithItsTargetAndWeight) {
  const std::size_t pick[] = {2, 0};
  const Data s = three().subset(pick);
  EXPECT_EQ(s.rows, 2u);
  EXPECT_EQ(s.cols, 2u);
  EXPECT_EQ(s.x, (std::vector<double>{5, 6, 1, 2}));
  EXPECT_EQ(s.y, (std::vector<double>{30, 10}));
  EXPECT_EQ(s.weight, (std::vector<double>{3, 1}));
  EXPECT_EQ(s.row(1)[1], 2);
}

std::string refusal(const Data& d) {
  try {
    validate(d, "rows.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Data, ValidateNamesTheSampleAndTheRule) {
  EXPECT_EQ(refusal(three()), "");
  EXPECT_NE(refusal(Data{}).find("no samples"), std::string::npos);
  Data nan = three();
  nan.x[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal(nan).find("sample 2: feature 2 is nan"), std::string::npos) << refusal(nan);
  Data zero = three();
  zero.weight[0] = 0;
  EXPECT_NE(refusal(zero).find("sample 1: weight is 0"), std::string::npos) << refusal(zero);
  Data short_y = three();
  short_y.y.pop_back();
  EXPECT_NE(refusal(short_y).find("need 6 values and 3 targets"), std::string::npos);
}

}  // namespace
}  // namespace fogdrift
