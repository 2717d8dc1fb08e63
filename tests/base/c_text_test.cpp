// Numbers and templates as C text (src/base/c_text.hpp): every double the header prints reads
// back as the same double, tables break as documented, and a template's keys are all replaced once.
#include "base/c_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "fogdrift/base/random.hpp"

namespace fogdrift::detail {
namespace {

TEST(CText, EveryNumberReadsBackAsTheSameDouble) {
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                0.1,
                                1.0 / 3.0,
                                -2.5e-300,
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max()};
  Rng rng(7);
  for (int i = 0; i < 2000; ++i)
    values.push_back(rng.normal(0, 1) * std::pow(10.0, rng.uniform(-30, 30)));
  for (double v : values) {
    const std::string text = c_number(v);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    EXPECT_EQ(std::signbit(std::strtod(text.c_str(), nullptr)), std::signbit(v)) << text;
  }
}

TEST(CText, ArraysBreakEveryPerLineValues) {
  const std::vector<double> v = {1, 2, 3, 4, 5};
  EXPECT_EQ(c_array(v, 2), "\n    1, 2, \n    3, 4, \n    5");
  EXPECT_EQ(c_array(std::vector<double>{}), "");
}

TEST(CText, TemplatesReplaceEveryKeyOnce) {
  // Every occurrence is replaced; a value that contains its own key is not replaced again.
  EXPECT_EQ(fill_template("@P@_a(@P@_b) @U@", {{"@P@", "unit"}, {"@U@", "UNIT"}}),
            "unit_a(unit_b) UNIT");
  EXPECT_EQ(fill_template("@A@ @A@", {{"@A@", "x@A@"}}), "x@A@ x@A@");
  EXPECT_EQ(fill_template("no keys", {{"@A@", "x"}}), "no keys");
}

}  // namespace
}  // namespace fogdrift::detail
