// Flags from option descriptions (option_flags.hpp).
#include "option_flags.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

namespace fogdrift::app {
namespace {

/// What --help shows after a flag for its value.
std::string type_name(const OptionSpec& spec) {
  switch (spec.type) {
    case OptionType::whole:
      return "UINT";
    case OptionType::number:
      return spec.unit.empty() ? "NUMBER" : spec.unit;
    case OptionType::seconds_or_auto:
      return "auto|s";
    case OptionType::whole_or_auto:
      return "auto|UINT";
    case OptionType::choice:
      return "NAME";
    case OptionType::names:
      return "NAME,...";
    case OptionType::numbers:
      return spec.unit.empty() ? "NUMBER,..." : spec.unit + ",...";
    case OptionType::number_or_none:
      return spec.unit.empty() ? "NUMBER" : spec.unit;
    case OptionType::assignments:
      return "NAME=VALUE";
    case OptionType::text:
    case OptionType::on_off:
      break;
  }
  return "TEXT";
}

/// The flag that changes an on/off option from its default `on`: --no-NAME turns it off, --NAME
/// on, whichever way its description spells the flag (demo's studies are off by default, paper's
/// on).
std::string switch_flag(const OptionSpec& spec, bool on) {
  const bool negated = spec.flag.rfind("--no-", 0) == 0;
  if (on && !negated) return "--no-" + spec.flag.substr(2);
  if (!on && negated) return "--" + spec.flag.substr(5);
  return spec.flag;
}

}  // namespace

OptionFlags::OptionFlags(CLI::App* cmd, std::vector<OptionSpec> specs,
                         std::vector<std::string> defaults, const std::string& group)
    : specs_(std::move(specs)), defaults_(std::move(defaults)) {
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    const OptionSpec& s = specs_[i];
    const std::string help = option_help(s, specs_, true);
    texts_.push_back(std::make_unique<std::string>(defaults_[i]));
    std::string flag = s.flag;
    CLI::Option* as_default = nullptr;
    if (s.type == OptionType::on_off) {
      const bool on = defaults_[i] == "true";
      flag = switch_flag(s, on);
      options_.push_back(cmd->add_flag(
          flag,
          on ? fmt::format("Turns {} off, which is on by default. {}", s.keyword, help) : help));
      // The other word, which asks for the default, is accepted and not listed: a script written
      // when the default was the other way still means what it meant.
      as_default = cmd->add_flag(switch_flag(s, !on))->group("");
    } else {
      options_.push_back(cmd->add_option(s.flag, *texts_.back(), help)
                             ->type_name(type_name(s))
                             ->default_str(defaults_[i]));
      // A list may be given in pieces: --offset-from a=b --offset-from c=d is a=b,c=d. An
      // assignment is one piece a flag, whatever commas it holds (--map gyro_dph=rate,x).
      if (s.type == OptionType::names || s.type == OptionType::numbers) options_.back()->join(',');
      if (s.type == OptionType::assignments) options_.back()->join(kAssignmentSeparator);
    }
    as_default_.push_back(as_default);
    if (!group.empty()) options_.back()->group(group);
    flag_table_[s.keyword] = flag;
    for (const std::string& field : s.fields) flag_table_[field] = flag;
  }
}

std::vector<std::pair<std::string, std::string>> OptionFlags::given() const {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < specs_.size(); ++i) {
    if (as_default_[i] != nullptr && as_default_[i]->count() > 0) {
      const bool on = defaults_[i] == "true";
      if (options_[i]->count() > 0)
        throw OptionError(specs_[i].keyword,
                          fmt::format("give {} or {}, not both", switch_flag(specs_[i], on),
                                      switch_flag(specs_[i], !on)));
      out.emplace_back(specs_[i].keyword, defaults_[i]);
    }
    if (options_[i]->count() == 0) continue;
    if (specs_[i].type == OptionType::on_off)
      out.emplace_back(specs_[i].keyword, defaults_[i] == "true" ? "false" : "true");
    else
      out.emplace_back(specs_[i].keyword, *texts_[i]);
  }
  return out;
}

std::string OptionFlags::words(const std::string& text) const {
  return in_option_words(text, specs_, true);
}

OptionError OptionFlags::named(const OptionError& e) const {
  return OptionError(flag_for(e.option(), flag_table_), words(e.message()));
}

}  // namespace fogdrift::app
