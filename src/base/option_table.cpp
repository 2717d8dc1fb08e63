// Option descriptions: their words, help texts, docs table and parsers (option_table.hpp).
#include "fogdrift/base/option_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/csv.hpp"

namespace fogdrift {

std::string_view to_string(OptionType type) {
  switch (type) {
    case OptionType::whole:
      return "whole";
    case OptionType::number:
      return "number";
    case OptionType::seconds_or_auto:
      return "seconds or auto";
    case OptionType::whole_or_auto:
      return "whole or auto";
    case OptionType::choice:
      return "choice";
    case OptionType::text:
      return "text";
    case OptionType::names:
      return "names";
    case OptionType::numbers:
      return "numbers";
    case OptionType::on_off:
      return "on/off";
    case OptionType::number_or_none:
      return "number or none";
    case OptionType::assignments:
      return "assignments";
  }
  return "?";
}

std::string option_word(const std::vector<OptionSpec>& specs, const std::string& field, bool flag) {
  for (const OptionSpec& s : specs)
    if (s.keyword == field || std::find(s.fields.begin(), s.fields.end(), field) != s.fields.end())
      return flag ? s.flag : s.keyword;
  return field;
}

std::string in_option_words(std::string text, const std::vector<OptionSpec>& specs, bool flag) {
  for (const OptionSpec& s : specs) {
    const std::string mark = "{" + s.keyword + "}";
    for (auto at = text.find(mark); at != std::string::npos; at = text.find(mark, at))
      text.replace(at, mark.size(), flag ? s.flag : s.keyword);
  }
  return text;
}

namespace {

/// A table cell: pipes escaped, so that a cell's text cannot end it, and an assignments
/// option's items on one line.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c == kAssignmentSeparator ? ' ' : c;
  }
  return out;
}

}  // namespace

std::string option_help(const OptionSpec& spec, const std::vector<OptionSpec>& specs, bool flag) {
  std::string what;
  if (!spec.unit.empty()) what = spec.unit;
  const std::string allowed = spec.range.text();
  if (!allowed.empty()) what += (what.empty() ? "" : "; ") + allowed;
  return in_option_words(what.empty() ? spec.doc : fmt::format("{} ({})", spec.doc, what), specs,
                         flag);
}

std::string options_markdown(const std::vector<OptionSpec>& specs,
                             const std::vector<std::string>& defaults) {
  std::string out =
      "| keyword | flag | type | unit | default | allowed | description |\n"
      "|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const OptionSpec& s = specs[i];
    out +=
        fmt::format("| `{}` | `{}` | {} | {} | `{}` | {} | {} |\n", s.keyword, s.flag,
                    to_string(s.type), cell(s.unit), cell(i < defaults.size() ? defaults[i] : ""),
                    cell(in_option_words(s.range.text(), specs, false)),
                    cell(in_option_words(s.doc, specs, false)));
  }
  return out;
}

namespace {

/// A parsed value checked against the option's bounds: "-1 s must be ≥ 0", "200 °C must be
/// between -70 and 100", the value written as
/// every front end writes it (5.0 on a command line and 5 from Python both read "5").
double in_range(const OptionSpec& spec, double value) {
  if (!spec.range.contains(value))
    throw OptionError(spec.keyword, fmt::format("{}{} must be {}", option_number_text(value),
                                                spec.unit.empty() ? "" : " " + spec.unit,
                                                spec.range.bounds_phrase()));
  return value;
}

}  // namespace

std::uint64_t parse_whole_option(const OptionSpec& spec, const std::string& text) {
  const auto v = csv::parse_number(text);
  if (!v || *v < 0 || *v != std::floor(*v) || *v > 9.007199254740992e15)
    throw OptionError(spec.keyword, fmt::format("'{}' is not a whole number ≥ 0", text));
  return static_cast<std::uint64_t>(in_range(spec, *v));
}

double parse_number_option(const OptionSpec& spec, const std::string& text) {
  const auto v = csv::parse_number(text);
  if (!v) throw OptionError(spec.keyword, fmt::format("'{}' is not a finite number", text));
  return in_range(spec, *v);
}

std::optional<double> parse_seconds_or_auto_option(const OptionSpec& spec,
                                                   const std::string& text) {
  if (text == "auto") return std::nullopt;
  const auto v = csv::parse_number(text);
  if (!v || !(*v > 0))
    throw OptionError(spec.keyword,
                      fmt::format("'{}' is neither auto nor a number of seconds > 0", text));
  return in_range(spec, *v);
}

std::optional<std::uint64_t> parse_whole_or_auto_option(const OptionSpec& spec,
                                                        const std::string& text) {
  if (text == "auto") return std::nullopt;
  const auto v = csv::parse_number(text);
  if (!v || *v < 0 || *v != std::floor(*v) || *v > 9.007199254740992e15)
    throw OptionError(spec.keyword, fmt::format("'{}' is neither auto nor a whole number", text));
  return static_cast<std::uint64_t>(in_range(spec, *v));
}

std::vector<std::string> option_items(std::string_view text) {
  std::vector<std::string> items;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = text.find(',', from);
    items.emplace_back(text.substr(from, comma == std::string_view::npos ? comma : comma - from));
    if (comma == std::string_view::npos) return items;
    from = comma + 1;
  }
}

std::vector<double> parse_numbers_option(const OptionSpec& spec, const std::string& text) {
  std::vector<double> values;
  for (const std::string& item : option_items(text)) {
    const auto v = csv::parse_number(item);
    if (!v)
      throw OptionError(spec.keyword, fmt::format("'{}' in '{}' is not a finite number (give a "
                                                  "comma-separated list such as -40,-30,25)",
                                                  item, text));
    values.push_back(in_range(spec, *v));
  }
  return values;
}

bool parse_on_off_option(const OptionSpec& spec, const std::string& text) {
  static constexpr std::string_view kOn[] = {"true", "1", "yes", "on"};
  static constexpr std::string_view kOff[] = {"false", "0", "no", "off"};
  if (std::find(std::begin(kOn), std::end(kOn), text) != std::end(kOn)) return true;
  if (std::find(std::begin(kOff), std::end(kOff), text) != std::end(kOff)) return false;
  throw OptionError(spec.keyword, fmt::format("'{}' is not true or false", text));
}

std::optional<double> parse_number_or_none_option(const OptionSpec& spec, const std::string& text) {
  if (text == "none") return std::nullopt;
  const auto v = csv::parse_number(text);
  if (!v)
    throw OptionError(spec.keyword, fmt::format("'{}' is neither none nor a finite number", text));
  return in_range(spec, *v);
}

std::vector<std::pair<std::string, std::string>> parse_assignments_option(const OptionSpec& spec,
                                                                          const std::string& text) {
  std::vector<std::pair<std::string, std::string>> items;
  if (text.empty()) return items;
  std::size_t from = 0;
  for (;;) {
    const std::size_t end = text.find(kAssignmentSeparator, from);
    const std::string item =
        text.substr(from, end == std::string::npos ? std::string::npos : end - from);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw OptionError(spec.keyword,
                        fmt::format("'{}' is not NAME=VALUE (give one NAME=VALUE each time, the "
                                    "option repeated for more)",
                                    item));
    items.emplace_back(item.substr(0, eq), item.substr(eq + 1));
    if (end == std::string::npos) return items;
    from = end + 1;
  }
}

std::string option_number_text(double value) {
  return fmt::format("{}", value);
}

std::string option_numbers_text(const std::vector<double>& values) {
  std::string out;
  for (const double v : values) {
    if (!out.empty()) out += ',';
    out += option_number_text(v);
  }
  return out;
}

std::string option_assignments_text(const std::vector<std::pair<std::string, std::string>>& items) {
  std::string out;
  for (const auto& [name, value] : items) {
    if (!out.empty()) out += kAssignmentSeparator;
    out += name + "=" + value;
  }
  return out;
}

}  // namespace fogdrift
