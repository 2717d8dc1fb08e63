// The command line's flags of an option table (option_table.hpp): one flag per option, its help
// text, type name and default from the option's description, and the user's values handed back
// in the table's order for the library to apply.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli_util.hpp"
#include "fogdrift/base/option_table.hpp"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace fogdrift::app {

class OptionFlags {
 public:
  /// Adds a flag to `cmd` for each option: an on/off option off by default is a flag --NAME that
  /// turns it on; one on by default a flag --no-NAME that turns it off, whichever way
  /// OptionSpec::flag spells it: the default decides (demo's studies are off, paper's on). With a
  /// `group`, --help lists the flags under that heading. The other flag, which asks for the
  /// default, is accepted too and not listed.
  OptionFlags(CLI::App* cmd, std::vector<OptionSpec> specs, std::vector<std::string> defaults,
              const std::string& group = "");

  /// (keyword, text) of each option given on the command line, in the table's order.
  std::vector<std::pair<std::string, std::string>> given() const;

  /// The library's fields (each option's keyword and OptionSpec::fields) and their flags, for
  /// as_flag.
  const FlagTable& flag_table() const { return flag_table_; }

  /// `text` with the options it names as {keyword} (option_table.hpp) named by their flags.
  std::string words(const std::string& text) const;

  /// `e` named by the flag that sets its field, its message in words().
  OptionError named(const OptionError& e) const;

  /// Sets every option given in `options`; an OptionError is named().
  template <class O>
  void apply(const OptionTable<O>& table, O& options) const {
    try {
      for (const auto& [keyword, text] : given()) apply_option(table, options, keyword, text);
    } catch (const OptionError& e) {
      throw named(e);
    }
  }

 private:
  std::vector<OptionSpec> specs_;
  std::vector<std::string> defaults_;
  std::vector<std::unique_ptr<std::string>> texts_;  // stable addresses for CLI11
  std::vector<CLI::Option*> options_;
  std::vector<CLI::Option*> as_default_;  // an on/off option's flag for its default, else null
  FlagTable flag_table_;
};

}  // namespace fogdrift::app
