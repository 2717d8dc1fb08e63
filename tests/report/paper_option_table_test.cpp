// The paper experiment's options, described once (paper_option_table.hpp): defaults that are
// PaperOptions', setters that set their own field only, and every field validate() names
// answered by the option that sets it.
#include "fogdrift/report/paper_option_table.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace fogdrift::report {
namespace {

TEST(PaperOptionTable, EachOptionSetsItsOwnFieldOnly) {
  const PaperOptions defaults;
  const std::vector<std::string> before = defaults_of(paper_option_table(), defaults);
  EXPECT_EQ(before[0], "5");                               // seeds
  EXPECT_EQ(before[1], "bp,svr,pso-svr,gwo-svr,ssa-svr");  // methods: the paper's
  EXPECT_EQ(before[11], "calibration,soaked,warm,ramping");
  const std::vector<std::pair<std::string, std::string>> given = {{"seeds", "2"},
                                                                  {"methods", "bp,ssa-svr,gp"},
                                                                  {"first_seed", "7"},
                                                                  {"population", "12"},
                                                                  {"iterations", "3"},
                                                                  {"fitness", "train"},
                                                                  {"cv", "recording"},
                                                                  {"folds", "4"},
                                                                  {"epsilon", "0.1"},
                                                                  {"search_epsilon", "true"},
                                                                  {"approach", "warm"},
                                                                  {"cal_approaches", "calibration"},
                                                                  {"repetitions", "4"},
                                                                  {"start_ups", "none"},
                                                                  {"cal_temps_degc", "0,40"},
                                                                  {"nf_temps_degc", "10,30"},
                                                                  {"findings", "2"},
                                                                  {"studies", "false"}};
  ASSERT_EQ(given.size(), paper_option_table().size());
  for (std::size_t i = 0; i < given.size(); ++i) {
    EXPECT_EQ(paper_option_table()[i].spec.keyword, given[i].first);
    PaperOptions o;
    apply_option(paper_option_table(), o, given[i].first, given[i].second);
    const std::vector<std::string> after = defaults_of(paper_option_table(), o);
    for (std::size_t j = 0; j < after.size(); ++j)
      EXPECT_EQ(after[j], j == i ? given[i].second : before[j]) << given[i].first;
  }
  PaperOptions o;
  apply_option(paper_option_table(), o, "methods", "bp,ssa-svr,poly");
  EXPECT_EQ(o.methods, (std::vector<Method>{Method::bp, Method::ssa_svr, Method::poly}));
  apply_option(paper_option_table(), o, "start_ups", "soaked,sweep");
  EXPECT_EQ(o.start_ups, (std::vector<sim::Approach>{sim::Approach::soaked, sim::Approach::sweep}));
}

TEST(PaperOptionTable, ValidationErrorsAreAnsweredByAnOption) {
  const std::vector<OptionSpec> specs = specs_of(paper_option_table());
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"seeds", "0"},
                                                        {"methods", "bp,svr"},
                                                        {"methods", "bp,ssa-svr,bp"},
                                                        {"population", "3"},
                                                        {"iterations", "0"},
                                                        {"folds", "12"},
                                                        {"epsilon", "11"},
                                                        {"repetitions", "1"},
                                                        {"cal_approaches", "calibration,sweep"},
                                                        {"cal_temps_degc", "0,200"},
                                                        {"nf_temps_degc", "-90"},
                                                        {"findings", "0"}}) {
    PaperOptions o;
    // Refused at parsing, by its bounds, or by the check below.
    try {
      apply_option(paper_option_table(), o, keyword, text);
      validate(o);
      ADD_FAILURE() << keyword << " = " << text << " passed";
    } catch (const OptionError& e) {
      EXPECT_EQ(option_word(specs, e.option(), false), keyword) << e.what();
    }
  }
  // Parsing errors name the keyword too.
  for (const auto& [keyword, text] :
       std::vector<std::pair<std::string, std::string>>{{"methods", "bp,rf"},
                                                        {"fitness", "best"},
                                                        {"cv", "temperatures"},
                                                        {"approach", "lukewarm"},
                                                        {"start_ups", "soaked,lukewarm"},
                                                        {"nf_temps_degc", "10,warm"}}) {
    PaperOptions o;
    try {
      apply_option(paper_option_table(), o, keyword, text);
      ADD_FAILURE() << keyword << " = " << text << " parsed";
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), keyword) << e.what();
    }
  }
}

}  // namespace
}  // namespace fogdrift::report
