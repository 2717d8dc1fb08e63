// `fogdrift join`'s options (join_option_table.hpp). Defaults are JoinOptions'; the columns and
// the offset's evidence are checked against the two files by judge_alignment() and join()
// (join.hpp), whose errors name each option by its keyword.
#include "fogdrift/io/join_option_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>
#include <vector>

namespace fogdrift {
namespace {

/// "temp_fog_degc=T_case" (recording column = log column), or one name for both.
std::string pair_text(const OffsetSearch& s) {
  return s.recording_column == s.log_column ? s.recording_column
                                            : s.recording_column + "=" + s.log_column;
}

OptionTable<JoinOptions> make_join_table() {
  using O = JoinOptions;
  OptionTable<O> t;
  const OptionSpec columns{"columns",
                           "--columns",
                           OptionType::names,
                           "",
                           "the log's numeric columns; empty: every one the recording lacks",
                           "The log's columns to bring in, comma-separated; a column the "
                           "recording has already is an error unless {replace}",
                           {}};
  t.push_back({columns, [](const O& o) { return fmt::format("{}", fmt::join(o.columns, ",")); },
               [](O& o, const std::string& text) {
                 o.columns.clear();
                 if (text.empty()) return;
                 for (const std::string& name : option_items(text)) {
                   if (name.empty())
                     throw OptionError("columns", fmt::format("'{}' names an empty column", text));
                   o.columns.push_back(name);
                 }
               }});
  t.push_back(on_off_option<O>(
      {"replace",
       "--replace",
       {},
       "",
       "",
       "A column the recording has already takes the log's values "
       "(default: an error)",
       {}},
      [](auto& o) -> auto& { return o.replace; }));
  t.push_back(choice_option<O>(
      {"method",
       "--method",
       {},
       "",
       "linear, nearest",
       "linear interpolates between the log samples either side of a row; nearest takes the "
       "nearest log sample",
       {}},
      [](auto& o) -> auto& { return o.method; }, [](JoinMethod m) { return to_string(m); },
      [](const std::string& text, const std::string&) { return join_method_from_string(text); }));
  // No default: nothing ties two clocks together.
  const OptionSpec offset{"offset_s",
                          "--offset-s",
                          OptionType::number,
                          "s",
                          "none: estimate it with {offset_from}",
                          "Clock offset, t_recording = t_log + offset (no default: nothing ties "
                          "two clocks together; 0 for two files imported with the same "
                          "--time-zero); with {offset_from}, the centre of the search (0 when "
                          "not given)",
                          {}};
  t.push_back({offset,
               [](const O& o) {
                 return o.offset_s ? option_number_text(*o.offset_s) : std::string("none");
               },
               [offset](O& o, const std::string& text) {
                 o.offset_s = parse_number_option(offset, text);
               }});
  const OptionSpec from{"offset_from",
                        "--offset-from",
                        OptionType::names,
                        "",
                        "RECORDING_COLUMN=LOG_COLUMN, or one name for both",
                        "Estimate the offset from columns both files hold: the offset that "
                        "minimises the variance of their difference. Several pairs "
                        "(comma-separated, or the flag repeated) are each judged, and must agree",
                        {"estimate"}};
  t.push_back({from,
               [](const O& o) {
                 std::vector<std::string> pairs;
                 for (const OffsetSearch& s : o.estimates) pairs.push_back(pair_text(s));
                 return fmt::format("{}", fmt::join(pairs, ","));
               },
               [](O& o, const std::string& text) {
                 o.estimates.clear();
                 if (text.empty()) return;
                 for (const std::string& pair : option_items(text)) {
                   const auto eq = pair.find('=');
                   OffsetSearch s;
                   s.recording_column = pair.substr(0, eq);
                   s.log_column =
                       eq == std::string::npos ? s.recording_column : pair.substr(eq + 1);
                   if (s.recording_column.empty() || s.log_column.empty())
                     throw OptionError(
                         "offset_from",
                         fmt::format("'{}' is not COLUMN or RECORDING_COLUMN=LOG_COLUMN", pair));
                   o.estimates.push_back(s);
                 }
               }});
  const OptionSpec range{"offset_range_s",
                         "--offset-range-s",
                         OptionType::number,
                         "s",
                         at_least(0).with("0: every offset that leaves half the shorter file "
                                          "overlapping"),
                         "With {offset_from}: search {offset_s} ± this",
                         {}};
  t.push_back({range,
               [](const O& o) {
                 return option_number_text(o.estimates.empty() ? 0.0 : o.estimates[0].range_s);
               },
               [range](O& o, const std::string& text) {
                 const double v = parse_number_option(range, text);
                 if (o.estimates.empty() && v != 0)
                   throw OptionError("offset_range_s", "has no effect without {offset_from}");
                 for (OffsetSearch& s : o.estimates) s.range_s = v;
               }});
  t.push_back(on_off_option<O>(
      {"force",
       "--force",
       {},
       "",
       "",
       "Write the join even when the evidence for its offset fails; the failures are printed as "
       "warnings with the result",
       {}},
      [](auto& o) -> auto& { return o.force; }));
  t.push_back(seconds_or_auto_option<O>(
      {"max_step_s",
       "--max-step-s",
       {},
       "",
       "",
       "linear: the longest step between two log samples interpolated across; a longer gap "
       "splits the recording; auto: 1.5 × the log's median step",
       {}},
      [](auto& o) -> auto& { return o.max_step_s; }));
  t.push_back(seconds_or_auto_option<O>(
      {"max_age_s",
       "--max-age-s",
       {},
       "",
       "",
       "nearest: the farthest a log sample may be from the row; auto: the log's median step",
       {}},
      [](auto& o) -> auto& { return o.max_age_s; }));
  return t;
}

}  // namespace

const OptionTable<JoinOptions>& join_option_table() {
  static const OptionTable<JoinOptions> table = make_join_table();
  return table;
}

}  // namespace fogdrift
