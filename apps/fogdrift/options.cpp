// fogdrift options: the options of `fogdrift train` and Python's fogdrift.train, as the one
// description of each gives them (train_option_table.hpp, docs/options.md).
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/tune/train_option_table.hpp"

namespace fogdrift::app {

void add_options(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "options",
      "Print the options of 'fogdrift train' and of Python's fogdrift.train: each one's Python\n"
      "keyword, flag, type, unit, default, allowed values and description, from the one\n"
      "description fogdrift keeps of it. The table in docs/options.md is this output\n"
      "(scripts/options_doc.py writes it there).\n"
      "Example:\n"
      "  fogdrift options --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)))'");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json,
                "Print a JSON array instead of Markdown, one object per option: keyword, flag, "
                "type, unit, default, allowed, doc (other options named by keyword) and help "
                "(as --help shows it, other options named by flag)");
  cmd->callback([json] {
    const auto& table = train_option_table();
    const std::vector<OptionSpec> specs = specs_of(table);
    const std::vector<std::string> defaults = defaults_of(table);
    if (!*json) {
      std::cout << options_markdown(specs, defaults);
      return;
    }
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < specs.size(); ++i)
      out.push_back({{"keyword", specs[i].keyword},
                     {"flag", specs[i].flag},
                     {"type", to_string(specs[i].type)},
                     {"unit", specs[i].unit},
                     {"default", defaults[i]},
                     {"allowed", specs[i].range},
                     {"doc", option_help(specs[i], specs, false)},
                     {"help", option_help(specs[i], specs, true)}});
    std::cout << out.dump(2) << "\n";
  });
}

}  // namespace fogdrift::app
