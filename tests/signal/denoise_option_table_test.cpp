// Wavelet denoising's options, described once (denoise_option_table.hpp): defaults that are
// DenoiseOptions', setters that set their own field only, "max" and "auto" the same level, every
// choice listing its names, and the errors of denoise() answered by the option that sets it.
#include "fogdrift/signal/denoise_option_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fogdrift::signal {
namespace {

TEST(DenoiseOptionTable, DefaultsAreTheLibrarysAndEachOptionSetsItsOwnField) {
  const DenoiseOptions defaults;
  const std::vector<std::string> before = defaults_of(denoise_option_table(), defaults);
  EXPECT_EQ(before, (std::vector<std::string>{"sym4", "auto", "bayes", "soft", "symmetric"}));
  const std::vector<std::pair<std::string, std::string>> given = {{"wavelet", "db4"},
                                                                  {"level", "3"},
                                                                  {"threshold", "sure"},
                                                                  {"mode", "hard"},
                                                                  {"extension", "periodization"}};
  for (std::size_t i = 0; i < given.size(); ++i) {
    DenoiseOptions o;
    apply_option(denoise_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(denoise_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
  DenoiseOptions o;
  apply_option(denoise_option_table(), o, "level", "3");
  EXPECT_EQ(o.level, 3);
  apply_option(denoise_option_table(), o, "level", "max");
  EXPECT_FALSE(o.level);
  apply_option(denoise_option_table(), o, "level", "4");
  apply_option(denoise_option_table(), o, "level", "auto");
  EXPECT_FALSE(o.level);
}

TEST(DenoiseOptionTable, ChoicesListTheirNamesAndRefuseOthersByKeyword) {
  for (const auto& [keyword, names] : std::vector<std::pair<std::string, std::string>>{
           {"threshold", "universal, level, sure, bayes"},
           {"mode", "soft, hard"},
           {"extension", "symmetric, periodization, zero, periodic"}}) {
    const auto* option = find_option(denoise_option_table(), keyword);
    ASSERT_NE(option, nullptr) << keyword;
    EXPECT_EQ(option->spec.type, OptionType::choice);
    EXPECT_EQ(option->spec.range.text(), names);
    DenoiseOptions o;
    try {
      option->set(o, "median");
      ADD_FAILURE() << keyword << " took 'median'";
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), keyword);
      EXPECT_NE(e.message().find(names), std::string::npos) << e.message();
    }
  }
  DenoiseOptions o;
  for (const char* bad : {"-1", "0", "three", "1.5", "99999999999"})
    EXPECT_THROW(apply_option(denoise_option_table(), o, "level", bad), OptionError) << bad;
  try {
    apply_option(denoise_option_table(), o, "level", "99999999999");
  } catch (const OptionError& e) {
    EXPECT_EQ(e.message(),
              "99999999999 is too high: it must be at most floor(log2(N / (F − 1))) "
              "for N samples and a filter of F taps");
  }
}

TEST(DenoiseOptionTable, DenoisingErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(denoise_option_table());
  std::vector<double> x(256);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.1 * static_cast<double>(i));
  for (const auto& [keyword, text] : std::vector<std::pair<std::string, std::string>>{
           {"wavelet", "db99"}, {"level", "0"}, {"level", "12"}}) {
    DenoiseOptions o;
    // Refused at parsing, by its bounds, or by the check below.
    try {
      apply_option(denoise_option_table(), o, keyword, text);
      denoise(x, o);
      ADD_FAILURE() << keyword << " = " << text << " passed";
    } catch (const OptionError& e) {
      EXPECT_EQ(option_word(specs, e.option(), false), keyword);
      EXPECT_EQ(option_word(specs, e.option(), true), "--" + keyword);
    }
  }
}

}  // namespace
}  // namespace fogdrift::signal
