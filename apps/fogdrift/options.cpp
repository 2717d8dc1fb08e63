// fogdrift options: the options of the commands whose options are described once (`fogdrift
// train`, `simulate`'s protocols, `stream`'s fault policy, `denoise`, `evaluate`, `northfind`,
// `paper`) and of their Python
// functions, as that one description gives them (option_table.hpp, docs/options.md).
#include <fmt/format.h>

#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/model/fault_option_table.hpp"
#include "fogdrift/report/paper_option_table.hpp"
#include "fogdrift/signal/denoise_option_table.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "fogdrift/tune/train_option_table.hpp"

namespace fogdrift::app {

constexpr const char* kCommands =
    "train, simulate-calibration, simulate-northfind, simulate-stable, stream, denoise, evaluate, "
    "northfind, paper";

namespace {

/// A table's descriptions and defaults as `fogdrift options` prints them.
struct Described {
  std::vector<OptionSpec> specs;
  std::vector<std::string> defaults;
};

template <class O>
Described described(const OptionTable<O>& table, const O& defaults = O()) {
  return {specs_of(table), defaults_of(table, defaults)};
}

/// The commands whose options are described once, by name.
Described of_command(const std::string& command) {
  if (command == "train") return described(train_option_table());
  if (command == "simulate-calibration") return described(sim::calibration_option_table());
  if (command == "simulate-northfind") return described(sim::northfind_option_table());
  if (command == "simulate-stable")
    return described(sim::northfind_option_table(), sim::stable_defaults());
  if (command == "stream") return described(fault_option_table());
  if (command == "denoise") return described(signal::denoise_option_table());
  if (command == "evaluate") return described(eval::evaluation_option_table());
  if (command == "northfind") return described(eval::finding_option_table());
  if (command == "paper") return described(report::paper_option_table());
  throw OptionError("COMMAND", fmt::format("'{}' is not one of {}", command, kCommands));
}

}  // namespace

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
      "defaults, 'fogdrift demo'). The tables in docs/options.md are this output\n"
      "(scripts/options_doc.py writes them there).\n"
      "Example:\n"
      "  fogdrift options --json | python3 -c 'import json,sys; print(len(json.load(sys.stdin)))'");
  auto command = std::make_shared<std::string>("train");
  cmd->add_option("COMMAND", *command, std::string("Whose options: ") + kCommands)
      ->capture_default_str();
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json,
                "Print a JSON array instead of Markdown, one object per option: keyword, flag, "
                "type, unit, default, allowed, doc (other options named by keyword) and help "
                "(as --help shows it, other options named by flag)");
  cmd->callback([command, json] {
    const auto [specs, defaults] = of_command(*command);
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
