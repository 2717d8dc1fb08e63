// One description of each option a command takes (docs/options.md): its Python keyword, its
// command-line flag, its type, unit, allowed values and help text, and how it reads and sets the
// library's options struct. The command line's flags, the Python function's keywords, the words
// its errors use in each, and docs/options.md's tables are all made from the one table, so they
// cannot disagree (option_table_test, train_option_table_test, tests/python/test_options.py).
//
//   const OptionTable<CampaignTrainOptions>& t = train_option_table();
//   CampaignTrainOptions o;
//   apply_option(t, o, "c_max", "1e4");      // what `--c-max 1e4` and c_max=1e4 both do
//
// Values travel as the text a user writes on a command line ("1e4", "auto", "true"); the Python
// front end turns a keyword's value into that text by the option's type (docs/python.md).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/option_range.hpp"

namespace fogdrift {

/// What values an option takes, and so how each front end spells and checks them.
enum class OptionType {
  whole,            ///< a whole number ≥ 0; Python int
  number,           ///< a finite real number; Python float or int
  seconds_or_auto,  ///< "auto" or a number of seconds > 0; Python "auto", float or int
  whole_or_auto,    ///< "auto" or a whole number; Python "auto" or int
  choice,           ///< one of a few names (OptionSpec::range lists them); Python str
  text,             ///< free text with a grammar of its own (OptionSpec::doc); Python str
  names,            ///< comma-separated names; Python str or a list of str
  numbers,          ///< comma-separated finite numbers; Python a list of numbers or a str
  on_off,           ///< a switch; Python bool. On the command line a flag that turns it on, or,
                    ///< for a switch on by default, a flag --no-NAME that turns it off
  number_or_none,   ///< "none" (not given) or a finite number; Python None or a number
  assignments,      ///< NAME=VALUE items, the flag repeated for each (a NAME or VALUE may hold
                    ///< commas); Python a dict or a list of "NAME=VALUE"
};

/// "whole", "number", "seconds or auto", "whole or auto", "choice", "text", "names", "numbers",
/// "on/off", "number or none", "assignments".
std::string_view to_string(OptionType type);

/// How an option is described to its users.
struct OptionSpec {
  std::string keyword;  ///< the Python keyword, and the option's name in docs and messages
  std::string flag;     ///< the command line's flag, e.g. "--c-max" or "--no-racing"
  OptionType type = OptionType::text;
  std::string unit;  ///< "s", "MB", …; empty for a pure number or a name
  /// The values allowed (option_range.hpp): bounds the parser checks, between(1, 4), or a note
  /// ("cv, train"); range.text() is how users read it.
  OptionRange range;
  /// What it does, in a sentence or a few (the --help text). "{keyword}" names another option
  /// and is shown in each front end's own word for it (option_help).
  std::string doc;
  /// The library's own names for what the option sets, where they differ from the keyword
  /// (rate_window_s sets window_s): an OptionError naming one of them is about this option.
  std::vector<std::string> fields;
};

/// One option of an options struct `O`: its description, its value in an `O` as a user would
/// write it, and how a user's text sets it.
template <class O>
struct Option {
  OptionSpec spec;
  std::function<std::string(const O&)> text_of;
  /// Parses the text as spec.type says and sets the field; OptionError(spec.keyword) if the
  /// text is not of that type. Ranges are checked where the library validates the options.
  std::function<void(O&, const std::string&)> set;
};

/// The options of one command, in the order they are applied: an option whose parsing needs
/// another (features needs thermometers) comes after it.
template <class O>
using OptionTable = std::vector<Option<O>>;

/// The table's descriptions, in order.
template <class O>
std::vector<OptionSpec> specs_of(const OptionTable<O>& table) {
  std::vector<OptionSpec> specs;
  for (const auto& o : table) specs.push_back(o.spec);
  return specs;
}

/// The options of `table`, which describe a part of `Outer` (`part(o)` returns a reference to
/// it, for a const and a non-const `o`), as options of `Outer`: how a trainer's own table
/// joins train's (trainers.hpp).
template <class Outer, class Inner, class Part>
OptionTable<Outer> lifted(const OptionTable<Inner>& table, Part part) {
  OptionTable<Outer> out;
  for (const Option<Inner>& o : table)
    out.push_back({o.spec, [text_of = o.text_of, part](const Outer& v) { return text_of(part(v)); },
                   [set = o.set, part](Outer& v, const std::string& text) { set(part(v), text); }});
  return out;
}

/// Each option's value in `defaults` (a default-constructed `O` unless given): the defaults
/// users see.
template <class O>
std::vector<std::string> defaults_of(const OptionTable<O>& table, const O& defaults = O()) {
  std::vector<std::string> texts;
  for (const auto& o : table) texts.push_back(o.text_of(defaults));
  return texts;
}

/// The option named `keyword`, or nullptr.
template <class O>
const Option<O>* find_option(const OptionTable<O>& table, std::string_view keyword) {
  for (const auto& o : table)
    if (o.spec.keyword == keyword) return &o;
  return nullptr;
}

/// Sets the option `keyword` of `options` from a user's text; OptionError naming the keyword for
/// a text of the wrong type or an option the table does not have.
template <class O>
void apply_option(const OptionTable<O>& table, O& options, std::string_view keyword,
                  const std::string& text) {
  const Option<O>* o = find_option(table, keyword);
  if (!o) throw OptionError(std::string(keyword), "is not an option");
  o->set(options, text);
}

/// The word a front end uses for what the library calls `field`: the keyword (Python) or the
/// flag (`flag`, the command line) of the option that sets it; `field` itself when no option
/// does (an option the front end names itself, such as --targets).
std::string option_word(const std::vector<OptionSpec>& specs, const std::string& field, bool flag);

/// `text` with every "{keyword}" of an option in `specs` replaced by its word: the flag (`flag`)
/// or the keyword. The library writes advice that names options this way (a held-out warning's
/// "{method} poly"), and each front end shows it in its own words.
std::string in_option_words(std::string text, const std::vector<OptionSpec>& specs, bool flag);

/// f(), with an OptionError it throws named in a front end's words: its field by the keyword
/// (`flag` false) or flag of the option of `specs` that sets it (option_word), and the options
/// its message names as {keyword} likewise (in_option_words).
template <class F>
auto in_option_words_of(const std::vector<OptionSpec>& specs, bool flag, F&& f) {
  try {
    return f();
  } catch (const OptionError& e) {
    throw OptionError(option_word(specs, e.option(), flag),
                      in_option_words(e.message(), specs, flag));
  }
}

/// The option's help text as --help (`flag`) and the docstring show it: doc, then the unit and
/// the values allowed, e.g. "Largest C searched (> --c-min)", every "{keyword}" in them replaced
/// by that option's word (option_word).
std::string option_help(const OptionSpec& spec, const std::vector<OptionSpec>& specs, bool flag);

/// docs/options.md's table of one command's options, a Markdown table with one row per option
/// (keyword, flag, type, unit, default, allowed, description), other options named by keyword.
std::string options_markdown(const std::vector<OptionSpec>& specs,
                             const std::vector<std::string>& defaults);

// The parsers every table's setters use. Each throws OptionError(spec.keyword, …) naming the
// text and what was expected: a text not of the type, or a number outside spec.range's bounds.
std::uint64_t parse_whole_option(const OptionSpec& spec, const std::string& text);
double parse_number_option(const OptionSpec& spec, const std::string& text);
/// nullopt for "auto".
std::optional<double> parse_seconds_or_auto_option(const OptionSpec& spec, const std::string& text);
std::optional<std::uint64_t> parse_whole_or_auto_option(const OptionSpec& spec,
                                                        const std::string& text);
/// The items of a comma-separated list, empty ones kept: "a,,b" is a, "", b; "" is one empty item.
std::vector<std::string> option_items(std::string_view text);
/// "-40,-30,25": one or more finite numbers, comma-separated.
std::vector<double> parse_numbers_option(const OptionSpec& spec, const std::string& text);
/// "true" or "false" (also 1/0, yes/no, on/off).
bool parse_on_off_option(const OptionSpec& spec, const std::string& text);
/// nullopt for "none".
std::optional<double> parse_number_or_none_option(const OptionSpec& spec, const std::string& text);
/// The text of an assignments option, its NAME=VALUE items one to a line (the separator of
/// kAssignmentSeparator), each split at its first '=': "a=1\nb=x=y" is (a, 1), (b, x=y). ""
/// is no item. OptionError for an item without '=' or with an empty NAME.
std::vector<std::pair<std::string, std::string>> parse_assignments_option(const OptionSpec& spec,
                                                                          const std::string& text);
/// What separates an assignments option's items in its text: a line end, which no column name
/// of a CSV header line holds.
inline constexpr char kAssignmentSeparator = '\n';

/// A number as an option's text: the shortest that reads back to the same double.
std::string option_number_text(double value);
/// Numbers as an option's text, comma-separated, each as option_number_text.
std::string option_numbers_text(const std::vector<double>& values);
/// NAME=VALUE items as an assignments option's text.
std::string option_assignments_text(const std::vector<std::pair<std::string, std::string>>& items);

// Options of each type on a field of `O`: `get(o)` returns a reference to the field, and the
// option reads, writes and parses it as its type says.

/// A whole-number option (any integer field).
template <class O, class Get>
Option<O> whole_option(OptionSpec spec, Get get) {
  spec.type = OptionType::whole;
  return {spec, [get](const O& o) { return std::to_string(get(o)); },
          [get, spec](O& o, const std::string& text) {
            using T = std::remove_cvref_t<decltype(get(o))>;
            const std::uint64_t value = parse_whole_option(spec, text);
            // A value the field cannot hold would wrap: -s 4294967299 would read as 3.
            if (value > static_cast<std::uint64_t>(std::numeric_limits<T>::max()))
              throw OptionError(spec.keyword, "'" + text + "' is more than " +
                                                  std::to_string(std::numeric_limits<T>::max()));
            get(o) = static_cast<T>(value);
          }};
}

/// A real-number option.
template <class O, class Get>
Option<O> number_option(OptionSpec spec, Get get) {
  spec.type = OptionType::number;
  return {spec, [get](const O& o) { return option_number_text(get(o)); },
          [get, spec](O& o, const std::string& text) { get(o) = parse_number_option(spec, text); }};
}

/// A list of numbers (a std::vector<double> field).
template <class O, class Get>
Option<O> numbers_option(OptionSpec spec, Get get) {
  spec.type = OptionType::numbers;
  return {
      spec, [get](const O& o) { return option_numbers_text(get(o)); },
      [get, spec](O& o, const std::string& text) { get(o) = parse_numbers_option(spec, text); }};
}

/// An on/off option on a bool field.
template <class O, class Get>
Option<O> on_off_option(OptionSpec spec, Get get) {
  spec.type = OptionType::on_off;
  return {spec, [get](const O& o) { return std::string(get(o) ? "true" : "false"); },
          [get, spec](O& o, const std::string& text) { get(o) = parse_on_off_option(spec, text); }};
}

/// One of a few names: `name(value)` is a value's name, `parse(text, keyword)` the value named
/// (an OptionError naming the keyword for any other text); spec.range lists the names.
template <class O, class Get, class Name, class Parse>
Option<O> choice_option(OptionSpec spec, Get get, Name name, Parse parse) {
  spec.type = OptionType::choice;
  return {
      spec, [get, name](const O& o) { return std::string(name(get(o))); },
      [get, parse, spec](O& o, const std::string& text) { get(o) = parse(text, spec.keyword); }};
}

/// An optional number, unset meaning "none": not given (a campaign's input rate).
template <class O, class Get>
Option<O> number_or_none_option(OptionSpec spec, Get get) {
  spec.type = OptionType::number_or_none;
  return {spec,
          [get](const O& o) {
            const auto& v = get(o);
            return v ? option_number_text(*v) : std::string("none");
          },
          [get, spec](O& o, const std::string& text) {
            get(o) = parse_number_or_none_option(spec, text);
          }};
}

/// An optional number of seconds, unset meaning "auto".
template <class O, class Get>
Option<O> seconds_or_auto_option(OptionSpec spec, Get get) {
  spec.type = OptionType::seconds_or_auto;
  spec.unit = "s";
  return {spec,
          [get](const O& o) {
            const auto& v = get(o);
            return v ? option_number_text(*v) : std::string("auto");
          },
          [get, spec](O& o, const std::string& text) {
            get(o) = parse_seconds_or_auto_option(spec, text);
          }};
}

}  // namespace fogdrift
