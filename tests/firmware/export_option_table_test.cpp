// `export-c`'s options (export_option_table.hpp): the header's own, then the fault policy's, and
// to_c_header's refusals answered by the option that sets the field.
#include "fogdrift/firmware/export_option_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift {
namespace {

TEST(ExportOptionTable, TheHeadersOptionsThenTheFaultPolicy) {
  const std::vector<OptionSpec> specs = specs_of(export_option_table());
  const std::vector<OptionSpec> faults = specs_of(fault_option_table());
  ASSERT_EQ(specs.size(), faults.size() + 4);
  std::vector<std::string> flags;
  for (std::size_t i = 0; i < 4; ++i) flags.push_back(specs[i].flag);
  EXPECT_EQ(flags, (std::vector<std::string>{"--prefix", "--stream-rate-hz", "--precision",
                                             "--force-float"}));
  for (std::size_t i = 0; i < faults.size(); ++i) EXPECT_EQ(specs[i + 4].flag, faults[i].flag);
  const std::vector<std::string> d = defaults_of(export_option_table());
  EXPECT_EQ(std::vector<std::string>(d.begin(), d.begin() + 4),
            (std::vector<std::string>{"fogdrift_model", "0", "double", "false"}));
}

TEST(ExportOptionTable, ValuesAreParsedAndBoundedByTheTable) {
  ExportOptions o;
  apply_option(export_option_table(), o, "precision", "float");
  apply_option(export_option_table(), o, "stream_rate_hz", "100");
  apply_option(export_option_table(), o, "prefix", "unit42");
  apply_option(export_option_table(), o, "stuck_s", "60");
  EXPECT_EQ(o.precision, CPrecision::single);
  EXPECT_EQ(o.stream_rate_hz, 100.0);
  EXPECT_EQ(o.prefix, "unit42");
  EXPECT_EQ(o.faults.stuck_s, 60.0);
  for (const auto& [keyword, text] : std::vector<std::pair<std::string, std::string>>{
           {"precision", "single"}, {"stream_rate_hz", "-1"}, {"stream_rate_hz", "20000"}}) {
    ExportOptions r;
    EXPECT_THROW(apply_option(export_option_table(), r, keyword, text), OptionError) << text;
  }
  // to_c_header names the rate "rate": the command line answers with --stream-rate-hz.
  EXPECT_EQ(option_word(specs_of(export_option_table()), "rate", true), "--stream-rate-hz");
}

}  // namespace
}  // namespace fogdrift
