// `fogdrift campaign`'s options, described once (campaign_option_table.hpp): how a long log is
// cut (defaults that are CutOptions', setters that set their own field only, cut()'s errors
// answered by the option that sets the field), what the channels sensed, and the whole table.
#include "fogdrift/io/campaign_option_table.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fogdrift {
namespace {

TEST(CutOptionTable, DefaultsAreTheLibrarysAndEachOptionSetsItsOwnField) {
  const std::vector<std::string> before = defaults_of(cut_option_table());
  EXPECT_EQ(before, (std::vector<std::string>{"0", "0", "false", "0.05", "600"}));
  const std::vector<std::pair<std::string, std::string>> given = {
      {"cut_gap_s", "600"},
      {"cut_window_s", "1800"},
      {"cut_plateaus", "true"},
      {"plateau_rate_degc_per_min", "0.1"},
      {"plateau_min_s", "300"}};
  for (std::size_t i = 0; i < given.size(); ++i) {
    CutOptions o;
    apply_option(cut_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(cut_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
}

TEST(CutOptionTable, RefusalsAndTheLibrarysErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(cut_option_table());
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"cut_gap_s", "-1"},
                                                        {"cut_window_s", "-5"},
                                                        {"plateau_rate_degc_per_min", "0"},
                                                        {"plateau_min_s", "0"}}) {
    CutOptions o;
    EXPECT_THROW(apply_option(cut_option_table(), o, keyword, text), OptionError) << keyword;
  }
  // cut() names its fields (gap_s, …), which the options answer in each front end's words.
  for (const auto& [field, keyword] : std::vector<std::pair<std::string, std::string>>{
           {"gap_s", "cut_gap_s"}, {"window_s", "cut_window_s"}, {"plateaus", "cut_plateaus"}}) {
    EXPECT_EQ(option_word(specs, field, false), keyword);
  }
  EXPECT_EQ(option_word(specs, "gap_s", true), "--cut-gap-s");
}

TEST(SensedOptionTable, TheInputRateIsANumberOrNone) {
  SensedOptions o;
  EXPECT_EQ(defaults_of(sensed_option_table()), (std::vector<std::string>{"none", ""}));
  apply_option(sensed_option_table(), o, "input_rate_dph", "0");
  ASSERT_TRUE(o.input_rate_dph.has_value());
  EXPECT_EQ(*o.input_rate_dph, 0.0);
  apply_option(sensed_option_table(), o, "input_rate_dph", "none");
  EXPECT_FALSE(o.input_rate_dph.has_value());
  EXPECT_THROW(apply_option(sensed_option_table(), o, "input_rate_dph", "fast"), OptionError);
  EXPECT_THROW(apply_option(sensed_option_table(), o, "input_rate_dph", "1e9"), OptionError);
}

TEST(SensedOptionTable, ReferencesAreCheckedTargetColumnsEachGivenOnce) {
  SensedOptions o;
  apply_option(sensed_option_table(), o, "references", "accel_x_g=0\nsf_fog_ppm=-2.5");
  EXPECT_EQ(o.references, (std::map<std::string, double>{{"accel_x_g", 0}, {"sf_fog_ppm", -2.5}}));
  // Read back as written: the table's text of the value is the text that set it.
  EXPECT_EQ(defaults_of(sensed_option_table(), o)[1], "accel_x_g=0\nsf_fog_ppm=-2.5");
  const auto refused = [&](const std::string& text, const std::string& says) {
    SensedOptions r;
    try {
      apply_option(sensed_option_table(), r, "references", text);
      ADD_FAILURE() << text << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "references") << text;
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  };
  refused("accel_x_g", "is not NAME=VALUE");
  refused("=1", "is not NAME=VALUE");
  refused("accel_x_g=level", "is not a finite number");
  refused("accel_x_g=0\naccel_x_g=1", "accel_x_g is given twice");
  refused("temp_fog_degc=20", "temp_fog_degc");  // not a target column
  refused("accel_x_g=1e9", "magnitude");
}

TEST(CampaignOptionTable, HoldsEveryOptionOfTheCommandOnce) {
  const std::vector<OptionSpec> specs = specs_of(campaign_option_table());
  std::vector<std::string> flags;
  for (const OptionSpec& s : specs) flags.push_back(s.flag);
  EXPECT_EQ(flags, (std::vector<std::string>{"--test", "--repetitions", "--input-rate-dph",
                                             "--reference", "--latitude-deg", "--true-azimuth-deg",
                                             "--cut-gap-s", "--cut-window-s", "--cut-plateaus",
                                             "--plateau-rate-degc-per-min", "--plateau-min-s"}));
  CampaignOptions o;
  apply_option(campaign_option_table(), o, "test", "2,5");
  apply_option(campaign_option_table(), o, "repetitions", "1,1,2,2");
  apply_option(campaign_option_table(), o, "input_rate_dph", "-7.5");
  apply_option(campaign_option_table(), o, "latitude_deg", "47.4");
  apply_option(campaign_option_table(), o, "cut_gap_s", "600");
  EXPECT_EQ(o.test, "2,5");
  EXPECT_EQ(o.repetitions, (std::vector<double>{1, 1, 2, 2}));
  EXPECT_EQ(o.sensed.input_rate_dph, -7.5);
  EXPECT_EQ(o.latitude_deg, 47.4);
  EXPECT_EQ(o.cut.gap_s, 600);
  EXPECT_THROW(apply_option(campaign_option_table(), o, "latitude_deg", "91"), OptionError);
  EXPECT_THROW(apply_option(campaign_option_table(), o, "true_azimuth_deg", "-1"), OptionError);
  EXPECT_THROW(apply_option(campaign_option_table(), o, "repetitions", "0,1"), OptionError);
  // cut()'s fields are answered by campaign's flags too.
  EXPECT_EQ(option_word(specs, "gap_s", true), "--cut-gap-s");
}

}  // namespace
}  // namespace fogdrift
