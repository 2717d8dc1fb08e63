// `fogdrift train`'s options, described once (train_option_table.hpp): names that follow one
// rule, defaults that are the library's, setters that set their own field and nothing else, and
// the library's field names answered by the option that sets them.
#include "fogdrift/train/train_option_table.hpp"

#include <gtest/gtest.h>

#include <set>

#include "fogdrift/regress/gp.hpp"
#include "option_values.hpp"

namespace fogdrift {
namespace {

using O = CampaignTrainOptions;

std::vector<std::string> texts_of(const O& o) {
  std::vector<std::string> texts;
  for (const auto& option : train_option_table()) texts.push_back(option.text_of(o));
  return texts;
}

/// A value of the option other than `current`, as a user would write it, within its bounds.
std::string another_value(const Option<O>& option, const std::string& current) {
  switch (option.spec.type) {
    case OptionType::whole:
      return test::allowed_other(option.spec, current, {"7", "8", "2", "3", "100", "200"});
    case OptionType::number:
      return test::allowed_other(option.spec, current, {"0.25", "0.5", "0.005", "0.002"});
    case OptionType::seconds_or_auto:
      return current == "30" ? "40" : "30";
    case OptionType::whole_or_auto:
      return current == "2" ? "1" : "2";
    case OptionType::on_off:
      return current == "true" ? "false" : "true";
    case OptionType::names:
      return "fog,acc1";
    case OptionType::numbers:
      return current == "1,2" ? "3" : "1,2";
    case OptionType::text:
      return "T,dT";
    case OptionType::choice: {
      const std::string& r = option.spec.range.note;
      const std::string last = r.substr(r.rfind(", ") + 2);
      return last == current ? r.substr(0, r.find(',')) : last;
    }
    case OptionType::number_or_none:  // train has none of these
    case OptionType::assignments:
      break;
  }
  return current;
}

// Keywords are snake_case and flags are the keyword in kebab-case, --no- before a switch that is
// on by default: a user who knows one can write the other.
TEST(TrainOptionTable, FlagsAreTheKeywordsSpelledForTheCommandLine) {
  std::set<std::string> keywords, flags;
  const std::vector<std::string> defaults = defaults_of(train_option_table());
  for (std::size_t i = 0; i < train_option_table().size(); ++i) {
    const OptionSpec& s = train_option_table()[i].spec;
    EXPECT_TRUE(keywords.insert(s.keyword).second) << s.keyword;
    EXPECT_TRUE(flags.insert(s.flag).second) << s.flag;
    std::string flag = s.keyword;
    for (char& c : flag)
      if (c == '_') c = '-';
    const bool negated = s.type == OptionType::on_off && defaults[i] == "true";
    EXPECT_EQ(s.flag, (negated ? "--no-" : "--") + flag);
    EXPECT_FALSE(s.doc.empty()) << s.keyword;
    for (char c : s.keyword) EXPECT_TRUE(std::islower(c) || std::isdigit(c) || c == '_');
  }
}

// The defaults users see are the library's: writing each back changes nothing.
TEST(TrainOptionTable, DefaultsAreTheLibrarysAndReadBack) {
  const O defaults;
  O o;
  for (const auto& option : train_option_table()) option.set(o, option.text_of(defaults));
  EXPECT_EQ(texts_of(o), texts_of(defaults));
  EXPECT_EQ(o.train.tune.space, defaults.train.tune.space);
  EXPECT_EQ(o.train.method, defaults.train.method);
  EXPECT_EQ(o.auto_features, defaults.auto_features);
}

// Each setter sets its own option, reads back what it was given, and touches no other.
TEST(TrainOptionTable, EachOptionSetsItsOwnFieldOnly) {
  const O defaults;
  const std::vector<std::string> before = texts_of(defaults);
  for (std::size_t i = 0; i < train_option_table().size(); ++i) {
    const auto& option = train_option_table()[i];
    O o;
    const std::string value = another_value(option, before[i]);
    option.set(o, value);
    const std::vector<std::string> after = texts_of(o);
    for (std::size_t j = 0; j < after.size(); ++j) {
      if (j == i)
        EXPECT_NE(after[j], before[j]) << option.spec.keyword << " = " << value;
      else
        EXPECT_EQ(after[j], before[j])
            << option.spec.keyword << " changed " << train_option_table()[j].spec.keyword;
    }
  }
}

TEST(TrainOptionTable, ValuesReachTheLibrarysFields) {
  const auto& t = train_option_table();
  O o;
  apply_option(t, o, "c_max", "500");
  apply_option(t, o, "racing", "false");
  apply_option(t, o, "auto_box", "true");
  apply_option(t, o, "rate_window_s", "81");
  apply_option(t, o, "thermometers", "fog,acc1");
  apply_option(t, o, "features", "T,dT(fog)");
  apply_option(t, o, "gp_kernel", "ard");
  EXPECT_EQ(o.train.tune.space.c_max, 500);
  EXPECT_FALSE(o.train.tune.racing);
  EXPECT_EQ(o.train.auto_box_rounds, TrainOptions::kAutoBoxRounds);
  EXPECT_EQ(o.rate_window_s, 81.0);
  EXPECT_EQ(o.thermometers, (std::vector<std::string>{"fog", "acc1"}));
  EXPECT_FALSE(o.auto_features);
  // The thermometers set first are what a term without its own list reads.
  EXPECT_EQ(o.dataset.features.to_string(),
            FeatureSpec::parse("T,dT(fog)", {"fog", "acc1"}).to_string());
  EXPECT_TRUE(o.train.trainers.get<GpOptions>().ard);
}

TEST(TrainOptionTable, ErrorsNameTheOption) {
  const auto& t = train_option_table();
  const auto error_of = [&](const std::string& keyword, const std::string& text) {
    O o;
    try {
      apply_option(t, o, keyword, text);
    } catch (const OptionError& e) {
      return e.option();
    }
    return std::string();
  };
  EXPECT_EQ(error_of("method", "svm"), "method");
  EXPECT_EQ(error_of("cv", "folds"), "cv");
  EXPECT_EQ(error_of("folds", "three"), "folds");
  EXPECT_EQ(error_of("rate_degree", "5"), "rate_degree");
  EXPECT_EQ(error_of("gp_kernel", "matern"), "gp_kernel");
  EXPECT_EQ(error_of("differentiator", "forward"), "differentiator");
  EXPECT_EQ(error_of("no_such_option", "1"), "no_such_option");
}

// The library's names for the fields it validates are answered by the option that sets them,
// in each front end's word.
TEST(TrainOptionTable, LibraryFieldsHaveTheirOptionsWords) {
  const std::vector<OptionSpec> specs = specs_of(train_option_table());
  EXPECT_EQ(option_word(specs, "window_s", true), "--rate-window-s");
  EXPECT_EQ(option_word(specs, "poly_order", false), "rate_degree");
  EXPECT_EQ(option_word(specs, "degree", true), "--max-degree");
  EXPECT_EQ(option_word(specs, "denoise", true), "--denoise");
  EXPECT_EQ(option_word(specs, "epsilon_min", true), "--epsilon-min");
  // What validate(TrainOptions) names is an option users have.
  for (const auto& [field, set] :
       std::vector<std::pair<std::string, std::string>>{{"c_min", "0"},
                                                        {"sigma_max", "-1"},
                                                        {"cache_mb", "-1"},
                                                        {"folds", "1"},
                                                        {"population", "1"},
                                                        {"iterations", "0"},
                                                        {"epsilon", "-1"}}) {
    O o;
    apply_option(train_option_table(), o, "cv", "recording");  // where folds are checked
    // Refused at parsing, by its bounds, or by the check below.
    try {
      apply_option(train_option_table(), o, field, set);
      validate(o.train);
      ADD_FAILURE() << field << " = " << set << " passed";
    } catch (const OptionError& e) {
      EXPECT_NE(option_word(specs, e.option(), true), e.option()) << e.what();
    }
  }
}

}  // namespace
}  // namespace fogdrift
