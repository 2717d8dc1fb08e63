// Numbers, templates and model text as C text (src/base/c_text.hpp): every double the header
// prints reads back as the same double, tables break as documented, a template's keys are all
// replaced once, and no text from a model file leaves its comment or literal.
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
// Found by an attack (issue 57): a model's method, version and feature names went into the
// header's comments and literals as they were, so a model file could put code in firmware.
TEST(CText, ModelTextCannotLeaveItsCommentOrLiteral) {
  using detail::c_comment_text;
  using detail::c_string_literal;
  EXPECT_EQ(c_comment_text("ssa-svr 0.9"), "ssa-svr 0.9");
  EXPECT_EQ(c_comment_text("a*/b"), "a\\x2a\\x2fb");
  EXPECT_EQ(c_comment_text("/*"), "\\x2f\\x2a");
  EXPECT_EQ(c_comment_text("x\\"), "x\\x5c");
  EXPECT_EQ(c_comment_text("?"
                           "?/"),
            "\\x3f\\x3f\\x2f");
  EXPECT_EQ(c_comment_text(std::string("a\nb\0c", 5)), "a\\x0ab\\x00c");
  EXPECT_EQ(c_comment_text("\xc2\xb0"), "\\xc2\\xb0");
  EXPECT_EQ(c_string_literal("T_fog_degc"), "\"T_fog_degc\"");
  EXPECT_EQ(c_string_literal("a\"b\\c?"), "\"a\\\"b\\\\c\\?\"");
  EXPECT_EQ(c_string_literal("\n\x7f\xff"), "\"\\012\\177\\377\"");
  EXPECT_TRUE(detail::is_plain_c_identifier("gyro"));
  EXPECT_TRUE(detail::is_plain_c_identifier("accel_x"));
  EXPECT_FALSE(detail::is_plain_c_identifier("1"));
  EXPECT_FALSE(detail::is_plain_c_identifier("int"));
  EXPECT_FALSE(detail::is_plain_c_identifier("_Bool"));
  EXPECT_FALSE(detail::is_plain_c_identifier("_x"));
  EXPECT_FALSE(detail::is_plain_c_identifier("a-b"));
  EXPECT_FALSE(detail::is_plain_c_identifier(""));
}

}  // namespace fogdrift::detail
