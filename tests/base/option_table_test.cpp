// Option descriptions (option_table.hpp): the parsers every table uses, the words of each front
// end, help texts and the docs table.
#include "fogdrift/base/option_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace fogdrift {
namespace {

OptionSpec spec(std::string keyword, std::string flag, OptionType type = OptionType::number) {
  return {std::move(keyword), std::move(flag), type, "", "", "", {}};
}

/// The keyword an OptionError thrown by `f` names, "" when it throws none.
template <class F>
std::string keyword_of_error(F&& f) {
  try {
    f();
  } catch (const OptionError& e) {
    return e.option();
  }
  return "";
}

TEST(OptionTable, WholeNumbers) {
  const OptionSpec s = spec("folds", "--folds", OptionType::whole);
  EXPECT_EQ(parse_whole_option(s, "3"), 3u);
  EXPECT_EQ(parse_whole_option(s, "0"), 0u);
  EXPECT_EQ(parse_whole_option(s, "1e3"), 1000u);
  for (const char* bad : {"-1", "1.5", "x", "", "nan", "inf", "1e300"})
    EXPECT_EQ(keyword_of_error([&] { parse_whole_option(s, bad); }), "folds") << bad;
}

TEST(OptionTable, Numbers) {
  const OptionSpec s = spec("c_max", "--c-max");
  EXPECT_EQ(parse_number_option(s, "1e4"), 1e4);
  EXPECT_EQ(parse_number_option(s, "-0.25"), -0.25);
  for (const char* bad : {"big", "", "nan", "inf", "1,5"})
    EXPECT_EQ(keyword_of_error([&] { parse_number_option(s, bad); }), "c_max") << bad;
}

TEST(OptionTable, ListsOfNumbers) {
  const OptionSpec spec{"temps_degc", "--temps", OptionType::numbers, "°C", "", "", {}};
  EXPECT_EQ(parse_numbers_option(spec, "-40,-30.5,25"), (std::vector<double>{-40, -30.5, 25}));
  EXPECT_EQ(parse_numbers_option(spec, "7"), (std::vector<double>{7}));
  for (const char* bad : {"", "1,,2", "1,2,", "-40,warm", "nan", "1e999"}) {
    try {
      parse_numbers_option(spec, bad);
      ADD_FAILURE() << bad;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "temps_degc") << bad;
    }
  }
  const std::vector<double> values{-40, 0.1, 1e-7, 60};
  EXPECT_EQ(parse_numbers_option(spec, option_numbers_text(values)), values);
  EXPECT_EQ(option_numbers_text(values), "-40,0.1,1e-07,60");
}

TEST(OptionTable, AutoOrAValue) {
  const OptionSpec s = spec("block_s", "--block-s", OptionType::seconds_or_auto);
  EXPECT_FALSE(parse_seconds_or_auto_option(s, "auto").has_value());
  EXPECT_EQ(*parse_seconds_or_auto_option(s, "20"), 20.0);
  for (const char* bad : {"0", "-5", "soon", "Auto"})
    EXPECT_EQ(keyword_of_error([&] { parse_seconds_or_auto_option(s, bad); }), "block_s") << bad;
  const OptionSpec d = spec("rate_degree", "--rate-degree", OptionType::whole_or_auto);
  EXPECT_FALSE(parse_whole_or_auto_option(d, "auto").has_value());
  EXPECT_EQ(*parse_whole_or_auto_option(d, "2"), 2u);
  for (const char* bad : {"1.5", "two", "-1"})
    EXPECT_EQ(keyword_of_error([&] { parse_whole_or_auto_option(d, bad); }), "rate_degree");
}

TEST(OptionTable, Switches) {
  const OptionSpec s = spec("racing", "--no-racing", OptionType::on_off);
  for (const char* on : {"true", "1", "yes", "on"}) EXPECT_TRUE(parse_on_off_option(s, on));
  for (const char* off : {"false", "0", "no", "off"}) EXPECT_FALSE(parse_on_off_option(s, off));
  EXPECT_EQ(keyword_of_error([&] { parse_on_off_option(s, "maybe"); }), "racing");
}

TEST(OptionTable, NumberOrNone) {
  const OptionSpec s = spec("input_rate_dph", "--input-rate-dph", OptionType::number_or_none);
  EXPECT_FALSE(parse_number_or_none_option(s, "none").has_value());
  EXPECT_EQ(*parse_number_or_none_option(s, "-7.5"), -7.5);
  EXPECT_EQ(*parse_number_or_none_option(s, "0"), 0.0);
  for (const char* bad : {"", "None", "auto", "nan", "fast"})
    EXPECT_EQ(keyword_of_error([&] { parse_number_or_none_option(s, bad); }), "input_rate_dph")
        << bad;
}

// NAME=VALUE items, one a line: a name or value may hold commas and '=' (a foreign column's).
TEST(OptionTable, Assignments) {
  const OptionSpec s = spec("map", "--map", OptionType::assignments);
  using Items = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(parse_assignments_option(s, ""), Items{});
  const Items items{{"gyro_dph", "rate, x (deg/h)"}, {"temp_fog_degc", "T=fog"}};
  EXPECT_EQ(option_assignments_text(items), "gyro_dph=rate, x (deg/h)\ntemp_fog_degc=T=fog");
  EXPECT_EQ(parse_assignments_option(s, option_assignments_text(items)), items);
  EXPECT_EQ(parse_assignments_option(s, "a="), (Items{{"a", ""}}));  // an empty value is a value
  for (const char* bad : {"gyro_dph", "=x", "a=1\n\nb=2", "a=1\n"})
    EXPECT_EQ(keyword_of_error([&] { parse_assignments_option(s, bad); }), "map") << bad;
}

// A number's text reads back to the same double, in the fewest digits (what --help shows).
TEST(OptionTable, NumberTextRoundTrips) {
  EXPECT_EQ(option_number_text(0.05), "0.05");
  EXPECT_EQ(option_number_text(1000.0), "1000");
  EXPECT_EQ(option_number_text(1e-3), "0.001");
  const OptionSpec s = spec("x", "--x");
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300, 300), mantissa(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    const double v = mantissa(rng) * std::pow(10.0, exponent(rng));
    EXPECT_EQ(parse_number_option(s, option_number_text(v)), v) << option_number_text(v);
  }
}

TEST(OptionTable, EachFrontEndHasItsOwnWord) {
  std::vector<OptionSpec> specs = {spec("rate_window_s", "--rate-window-s"),
                                   spec("max_degree", "--max-degree")};
  specs[0].fields = {"window_s"};
  specs[1].fields = {"degree"};
  EXPECT_EQ(option_word(specs, "window_s", true), "--rate-window-s");
  EXPECT_EQ(option_word(specs, "window_s", false), "rate_window_s");
  EXPECT_EQ(option_word(specs, "max_degree", true), "--max-degree");
  EXPECT_EQ(option_word(specs, "degree", false), "max_degree");
  // A field no option sets keeps the library's name.
  EXPECT_EQ(option_word(specs, "targets", true), "targets");
}

TEST(OptionTable, HelpNamesOtherOptionsInEachFrontEndsWords) {
  std::vector<OptionSpec> specs = {spec("c_min", "--c-min"), spec("c_max", "--c-max")};
  specs[1].doc = "Largest C searched, above {c_min}";
  specs[1].range = "> {c_min}";
  specs[1].unit = "1";
  EXPECT_EQ(option_help(specs[1], specs, true), "Largest C searched, above --c-min (1; > --c-min)");
  EXPECT_EQ(option_help(specs[1], specs, false), "Largest C searched, above c_min (1; > c_min)");
  EXPECT_EQ(option_help(specs[0], specs, true), "");
}

TEST(OptionTable, MarkdownHasOneRowPerOptionAndEscapesPipes) {
  std::vector<OptionSpec> specs = {spec("block_s", "--block-s", OptionType::seconds_or_auto)};
  specs[0].unit = "s";
  specs[0].doc = "a | b, see {block_s}";
  const std::string md = options_markdown(specs, {"auto"});
  EXPECT_EQ(
      md,
      "| keyword | flag | type | unit | default | allowed | description |\n"
      "|---|---|---|---|---|---|---|\n"
      "| `block_s` | `--block-s` | seconds or auto | s | `auto` |  | a \\| b, see block_s |\n");
}

}  // namespace
}  // namespace fogdrift
