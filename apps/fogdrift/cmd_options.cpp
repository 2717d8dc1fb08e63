// fogdrift options: the options of the commands whose options are described once (`fogdrift
// train`, `simulate`'s protocols, `stream`'s fault policy, `denoise`, `evaluate`, `northfind`,
// `paper`, `plan`'s chamber) and of their Python
// functions, as that one description gives them (option_table.hpp, docs/options.md).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/report/option_descriptions.hpp"

namespace fogdrift::app {

void add_options(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "options",
      "Print the options of a command as the one description fogdrift keeps of each gives them:\n"
      "each one's Python keyword, flag, type, unit, default, allowed values and description.\n"
      "COMMAND is train ('fogdrift train', Python's fogdrift.train; the default) or\n"
      "simulate-calibration, simulate-northfind, simulate-stable ('fogdrift simulate\n"
      "calibration', ..., Python's fogdrift.simulate) or stream (the fault policy of 'fogdrift\n"
      "stream' and 'fogdrift export-c', Python's StreamingCompensator) or denoise ('fogdrift\n"
      "denoise', Python's fogdrift.denoise) or evaluate or northfind (the commands and their\n"
      "Python functions, find_north too) or paper ('fogdrift paper' and, with its own\n"
      "defaults, 'fogdrift demo') or plan (the chamber of 'fogdrift plan') or join\n"
      "('fogdrift join') or campaign (how it cuts a long log) or import (--list lists them all). "
      "Each "
      "option's bounds are checked when it is\n"
      "parsed (--json: minimum, maximum). The tables in docs/options.md are this output\n"
      "(scripts/options_doc.py writes them there).\n"
      "Example:\n"
      "  fogdrift options --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)))'");
  auto command = std::make_shared<std::string>("train");
  cmd->add_option("COMMAND", *command,
                  fmt::format("Whose options: {}", fmt::join(report::described_commands(), ", ")))
      ->capture_default_str();
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json,
                "Print a JSON array instead of Markdown, one object per option: keyword, flag, "
                "type, unit, default, allowed, doc (other options named by keyword) and help "
                "(as --help shows it, other options named by flag)");
  auto list = std::make_shared<bool>(false);
  cmd->add_flag("--list", *list,
                "Print the commands whose options are described, one a line (what COMMAND takes)");
  cmd->callback([command, json, list] {
    if (*list) {
      for (std::string_view name : report::described_commands()) std::cout << name << "\n";
      return;
    }
    const report::OptionDescriptions described = report::option_descriptions(*command);
    if (!*json) {
      std::cout << options_markdown(described.specs, described.defaults);
      return;
    }
    const nlohmann::ordered_json out = report::options_json(described);
    std::cout << out.dump(2) << "\n";
  });
}

}  // namespace fogdrift::app
