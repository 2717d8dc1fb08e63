// The bounds of an option's values: their text, and the check every parser makes with them.
#include "fogdrift/base/option_range.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/option_table.hpp"

namespace fogdrift {
namespace {

TEST(OptionRange, ReadsAsTheDocsWriteIt) {
  EXPECT_EQ(at_least(0).text(), "≥ 0");
  EXPECT_EQ(above(0).text(), "> 0");
  EXPECT_EQ(between(1, 1000).text(), "1 … 1000");
  EXPECT_EQ(between(0, 1e6).text(), "0 … 1e6");
  EXPECT_EQ(between(-70, 100).text(), "-70 … 100");
  EXPECT_EQ(between(0.001, 10).text(), "0.001 … 10");
  EXPECT_EQ(above(0).at_most(100).text(), "> 0, ≤ 100");
  EXPECT_EQ(above(0).below(45).text(), "> 0, < 45");
  EXPECT_EQ(at_least(0).below(1).text(), "≥ 0, < 1");
  EXPECT_EQ(at_least(2).with("ssa-svr ≥ 5").text(), "≥ 2; ssa-svr ≥ 5");
  const OptionRange relation = "> {c_min}";
  EXPECT_FALSE(relation.has_bounds());
  EXPECT_EQ(relation.text(), "> {c_min}");
  EXPECT_EQ(OptionRange().text(), "");
}

TEST(OptionRange, AMessageSaysAClosedRangeInWords) {
  EXPECT_EQ(between(-70, 100).bounds_phrase(), "between -70 and 100");
  EXPECT_EQ(between(0, 1e6).bounds_phrase(), "between 0 and 1e6");
  EXPECT_EQ(above(0).at_most(100).bounds_phrase(), "> 0, ≤ 100");
  EXPECT_EQ(at_least(0).bounds_phrase(), "≥ 0");
  EXPECT_EQ(at_least(2).with("ssa-svr ≥ 5").bounds_phrase(), "≥ 2");
}

TEST(OptionRange, ContainsItsClosedEndsAndNotItsOpenOnes) {
  EXPECT_TRUE(between(1, 4).contains(1));
  EXPECT_TRUE(between(1, 4).contains(4));
  EXPECT_FALSE(between(1, 4).contains(4.000001));
  EXPECT_FALSE(above(0).contains(0));
  EXPECT_TRUE(above(0).contains(1e-300));
  EXPECT_FALSE(at_least(0).below(1).contains(1));
  EXPECT_TRUE(at_least(0).below(1).contains(0));
  EXPECT_FALSE(at_least(0).contains(std::nan("")));
  EXPECT_TRUE(OptionRange("anything").contains(-1e300));
}

/// The message of the OptionError `f` throws, which must name `keyword`.
template <class F>
std::string refusal(const std::string& keyword, F f) {
  try {
    f();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), keyword);
    return e.message();
  }
  ADD_FAILURE() << keyword << " was not refused";
  return "";
}

TEST(OptionRange, EveryParserRefusesAValueOutsideTheBounds) {
  OptionSpec bridge{"bridge_s", "--bridge-s", OptionType::number, "s", at_least(0), "", {}};
  EXPECT_EQ(refusal("bridge_s", [&] { parse_number_option(bridge, "-1"); }), "-1 s must be ≥ 0");
  EXPECT_EQ(parse_number_option(bridge, "0"), 0.0);

  OptionSpec degree{"max_degree", "--max-degree", OptionType::whole, "", between(1, 6), "", {}};
  EXPECT_EQ(refusal("max_degree", [&] { parse_whole_option(degree, "7"); }),
            "7 must be between 1 and 6");
  EXPECT_EQ(refusal("max_degree", [&] { parse_whole_option(degree, "0"); }),
            "0 must be between 1 and 6");
  EXPECT_EQ(parse_whole_option(degree, "6"), 6u);

  OptionSpec temps{"temps_degc", "--temps", OptionType::numbers, "°C", between(-70, 100), "", {}};
  EXPECT_EQ(refusal("temps_degc", [&] { parse_numbers_option(temps, "0,150"); }),
            "150 °C must be between -70 and 100");

  OptionSpec window{"rate_window_s",
                    "--rate-window-s",
                    OptionType::seconds_or_auto,
                    "s",
                    above(0).at_most(600),
                    "",
                    {}};
  EXPECT_EQ(refusal("rate_window_s", [&] { parse_seconds_or_auto_option(window, "601"); }),
            "601 s must be > 0, ≤ 600");
  EXPECT_FALSE(parse_seconds_or_auto_option(window, "auto"));

  OptionSpec level{"level", "--level", OptionType::whole_or_auto, "", at_least(1), "", {}};
  EXPECT_EQ(refusal("level", [&] { parse_whole_or_auto_option(level, "0"); }), "0 must be ≥ 1");

  // A note alone checks nothing here: the library's validate() checks a rule between options.
  OptionSpec c_max{"c_max", "--c-max", OptionType::number, "", "> {c_min}", "", {}};
  EXPECT_EQ(parse_number_option(c_max, "-5"), -5.0);
}

TEST(OptionRange, HelpShowsTheBoundsAndTheNote) {
  const OptionSpec s{"folds",
                     "--folds",
                     OptionType::whole,
                     "",
                     at_least(2).with("at most the temperatures there are"),
                     "k of the folds",
                     {}};
  EXPECT_EQ(option_help(s, {s}, true), "k of the folds (≥ 2; at most the temperatures there are)");
}

}  // namespace
}  // namespace fogdrift
