// svm-train's options (libsvm_option_table.hpp): the one list the parser reads flags from, with
// svm-train's defaults.
#include "fogdrift/svr/libsvm_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fogdrift/svr/libsvm_options.hpp"

namespace fogdrift::svr {
namespace {

void expect_same(const LibsvmTrainOptions& a, const LibsvmTrainOptions& b, const std::string& why) {
  EXPECT_EQ(a.params.kernel, b.params.kernel) << why;
  EXPECT_EQ(a.params.c, b.params.c) << why;
  EXPECT_EQ(a.params.epsilon, b.params.epsilon) << why;
  EXPECT_EQ(a.params.tolerance, b.params.tolerance) << why;
  EXPECT_EQ(a.params.cache_mb, b.params.cache_mb) << why;
  EXPECT_EQ(a.params.shrinking, b.params.shrinking) << why;
  EXPECT_EQ(a.params.libsvm_path, b.params.libsvm_path) << why;
  EXPECT_EQ(a.gamma, b.gamma) << why;
  EXPECT_EQ(a.degree, b.degree) << why;
  EXPECT_EQ(a.coef0, b.coef0) << why;
  EXPECT_EQ(a.folds, b.folds) << why;
  EXPECT_EQ(a.quiet, b.quiet) << why;
}

TEST(LibsvmOptionTable, EveryFlagGivenItsDefaultChangesNothing) {
  const auto& table = libsvm_train_option_table();
  const std::vector<std::string> defaults = defaults_of(table);
  const LibsvmTrainOptions none = parse_libsvm_train_options("", 4);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const OptionSpec& s = table[i].spec;
    // -v's default, 0, is "no -v" (-v 0 is refused); a switch given is not its default.
    if (s.keyword == "folds" || s.type == OptionType::on_off) continue;
    const std::vector<std::string> tokens{s.flag, defaults[i]};
    expect_same(parse_libsvm_train_options(tokens, 4), none, s.flag + " " + defaults[i]);
  }
}

TEST(LibsvmOptionTable, SvmTrainsFlagsAndItsDefaults) {
  const std::vector<OptionSpec> specs = specs_of(libsvm_train_option_table());
  std::vector<std::string> flags;
  for (const OptionSpec& s : specs) flags.push_back(s.flag);
  EXPECT_EQ(flags,
            (std::vector<std::string>{"--solver", "-s", "-t", "-d", "-g", "--sigma", "-r", "-c",
                                      "-n", "-p", "-m", "-e", "-h", "-b", "-v", "-q"}));
  EXPECT_EQ(defaults_of(libsvm_train_option_table()),
            (std::vector<std::string>{"libsvm", "3", "2", "3", "none", "none", "0", "1", "0.5",
                                      "0.1", "100", "0.001", "1", "0", "0", "false"}));
}

TEST(LibsvmOptionTable, ATypedBoundIsCheckedAndNamedByTheFlag) {
  for (const auto& [text, message] : std::vector<std::pair<std::string, std::string>>{
           {"-c -1", "option -c: -1 must be > 0"},
           {"-p -0.5", "option -p: -0.5 must be ≥ 0"},
           {"-m 0", "option -m: 0 MB must be > 0"},
           {"-g 0", "option -g: 0 must be > 0"},
           {"-d 1.5", "option -d: '1.5' is not a whole number ≥ 0"},
           {"-q -c 2 -e 0", "option -e: 0 must be > 0"},
           // More than the field holds is refused, not wrapped round to 3 or 2.
           {"-s 4294967299", "option -s: '4294967299' is more than 4294967295"},
           {"-v 4294967298", "option -v: '4294967298' is more than 4294967295"}}) {
    try {
      parse_libsvm_train_options(text, 2);
      ADD_FAILURE() << text << " was accepted";
    } catch (const OptionError& e) {
      EXPECT_EQ(std::string(e.what()), message) << text;
    }
  }
}

}  // namespace
}  // namespace fogdrift::svr
