// Every command's options as they are described once (option_table.hpp, docs/options.md), by
// the command's name: what `fogdrift options` prints, as Markdown or JSON, and what Octave's
// fogdrift.options returns.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/base/option_table.hpp"

namespace fogdrift::report {

/// One command's options and their defaults.
struct OptionDescriptions {
  std::vector<OptionSpec> specs;
  std::vector<std::string> defaults;
};

/// The commands described, in order: train, simulate-calibration, simulate-northfind,
/// simulate-stable, stream, denoise, evaluate, northfind, paper, plan, join, campaign, import.
std::vector<std::string_view> described_commands();

/// The options of `command` (one of described_commands()); OptionError(`option`) naming the
/// commands for another.
OptionDescriptions option_descriptions(std::string_view command,
                                       const std::string& option = "COMMAND");

/// One object per option: keyword, flag, type, unit, default, allowed (as docs/options.md shows
/// it), the bounds the option's parser checks (minimum and maximum, null where there is none;
/// minimum_excluded and maximum_excluded), doc (other options named by keyword) and help (as
/// --help shows it, other options named by flag).
nlohmann::ordered_json options_json(const OptionDescriptions& described);

}  // namespace fogdrift::report
