// Every command's options by name (option_descriptions.hpp; docs/options.md).
#include "fogdrift/report/option_descriptions.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>

#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/io/campaign_option_table.hpp"
#include "fogdrift/io/import_option_table.hpp"
#include "fogdrift/io/inspect_option_table.hpp"
#include "fogdrift/io/join_option_table.hpp"
#include "fogdrift/model/compensate_option_table.hpp"
#include "fogdrift/report/paper_option_table.hpp"
#include "fogdrift/signal/denoise_option_table.hpp"
#include "fogdrift/sim/plan_option_table.hpp"
#include "fogdrift/sim/population_option_table.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "fogdrift/stream/stream_command_option_table.hpp"
#include "fogdrift/svr/libsvm_option_table.hpp"
#include "fogdrift/train/train_option_table.hpp"

namespace fogdrift::report {
namespace {

template <class O>
OptionDescriptions described(const OptionTable<O>& table, const O& defaults = O()) {
  return {specs_of(table), defaults_of(table, defaults)};
}

/// Each command whose options are described, and its table: the one list `fogdrift options`,
/// its --list and docs/options.md (scripts/options_doc.py) go by.
struct Command {
  std::string_view name;
  OptionDescriptions (*describe)();
};
const std::array<Command, 18> kCommands = {{
    {"train", [] { return described(train_option_table()); }},
    {"simulate-calibration", [] { return described(sim::calibration_option_table()); }},
    {"simulate-northfind", [] { return described(sim::northfind_option_table()); }},
    {"simulate-population", [] { return described(sim::population_option_table()); }},
    {"simulate-stable",
     [] { return described(sim::northfind_option_table(), sim::stable_defaults()); }},
    {"compensate", [] { return described(compensate_option_table()); }},
    {"stream", [] { return described(stream_command_option_table()); }},
    {"export-c", [] { return described(export_option_table()); }},
    {"denoise", [] { return described(signal::denoise_option_table()); }},
    {"evaluate", [] { return described(eval::evaluation_option_table()); }},
    {"northfind", [] { return described(eval::finding_option_table()); }},
    {"paper", [] { return described(paper_option_table()); }},
    {"plan", [] { return described(sim::plan_option_table()); }},
    {"join", [] { return described(join_option_table()); }},
    {"svr-train", [] { return described(svr::libsvm_train_option_table()); }},
    {"campaign", [] { return described(campaign_option_table()); }},
    {"import", [] { return described(import_option_table()); }},
    {"inspect", [] { return described(inspect_option_table()); }},
}};

}  // namespace

std::vector<std::string_view> described_commands() {
  std::vector<std::string_view> names;
  for (const Command& c : kCommands) names.push_back(c.name);
  return names;
}

OptionDescriptions option_descriptions(std::string_view command, const std::string& option) {
  for (const Command& c : kCommands)
    if (c.name == command) return c.describe();
  throw OptionError(
      option, fmt::format("'{}' is not one of {}", command, fmt::join(described_commands(), ", ")));
}

nlohmann::ordered_json options_json(const OptionDescriptions& d) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < d.specs.size(); ++i) {
    const OptionRange& r = d.specs[i].range;
    // The bounds the option's parser checks, for a machine: null where there is none.
    const auto bound = [](const std::optional<double>& b) {
      return b ? nlohmann::ordered_json(*b) : nlohmann::ordered_json(nullptr);
    };
    out.push_back({{"keyword", d.specs[i].keyword},
                   {"flag", d.specs[i].flag},
                   {"type", to_string(d.specs[i].type)},
                   {"unit", d.specs[i].unit},
                   {"default", d.defaults[i]},
                   {"allowed", r.text()},
                   {"minimum", bound(r.min)},
                   {"minimum_excluded", r.min_open},
                   {"maximum", bound(r.max)},
                   {"maximum_excluded", r.max_open},
                   {"doc", option_help(d.specs[i], d.specs, false)},
                   {"help", option_help(d.specs[i], d.specs, true)}});
  }
  return out;
}

}  // namespace fogdrift::report
