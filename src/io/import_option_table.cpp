// `fogdrift import`'s options (import_option_table.hpp). Defaults are ImportOptions',
// HampelOptions' and the grid's; import_recordings() and regrid() check what needs the file.
#include "fogdrift/io/import_option_table.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace fogdrift {
namespace {

/// An assignments option on a map of names: each NAME once, each VALUE non-empty.
template <class Get>
Option<ImportRunOptions> names_map_option(OptionSpec spec, Get get) {
  spec.type = OptionType::assignments;
  return {spec,
          [get](const ImportRunOptions& o) {
            const std::map<std::string, std::string>& m = get(o);
            return option_assignments_text({m.begin(), m.end()});
          },
          [get, spec](ImportRunOptions& o, const std::string& text) {
            std::map<std::string, std::string> out;
            for (const auto& [name, value] : parse_assignments_option(spec, text)) {
              if (value.empty())
                throw OptionError(spec.keyword, fmt::format("{}= names nothing", name));
              if (!out.emplace(name, value).second)
                throw OptionError(spec.keyword, fmt::format("{} is given twice", name));
            }
            get(o) = std::move(out);
          }};
}

OptionTable<ImportRunOptions> make_import_table() {
  using O = ImportRunOptions;
  OptionTable<O> t;
  t.push_back(names_map_option(
      {"map",
       "--map",
       {},
       "",
       {},
       "FOGDRIFT_COLUMN=FOREIGN_COLUMN, the flag repeated for each column: which foreign column "
       "holds a fogdrift column, e.g. gyro_dph=\"Rate X [rad/s]\"; a further channel "
       "(gyro_NAME_dph, temp_NAME_degc, accel_NAME_g, sf_NAME_ppm) too. Columns not mapped are "
       "kept as extra columns",
       {}},
      [](auto& o) -> auto& { return o.read.columns; }));
  t.push_back(names_map_option(
      {"units",
       "--unit",
       {},
       "",
       {},
       "FOGDRIFT_COLUMN=UNIT, the flag repeated for each column: time_s s|ms|us|iso8601|clock; "
       "gyro_dph deg/h|deg/s|rad/s|mrad/s|arcsec/s; temperatures degC|K|degF; accel_*_g "
       "g|mg|m/s2; table_deg deg|rad; any column counts:SCALE:OFFSET (value = counts·SCALE + "
       "OFFSET) or intN:SCALE:OFFSET (a signed register). A column not listed is in fogdrift's "
       "unit already",
       {}},
      [](auto& o) -> auto& { return o.units; }));
  const OptionSpec delimiter{"delimiter", "--delimiter",          OptionType::choice,
                             "",          "',', ';', '|' or tab", "Field separator",
                             {}};
  t.push_back({delimiter,
               [](const O& o) {
                 return o.read.delimiter == '\t' ? std::string("tab")
                                                 : std::string(1, o.read.delimiter);
               },
               [](O& o, const std::string& text) {
                 if (text == "," || text == ";" || text == "|")
                   o.read.delimiter = text[0];
                 else if (text == "\\t" || text == "\t" || text == "tab")
                   o.read.delimiter = '\t';
                 else
                   throw OptionError("delimiter",
                                     fmt::format("'{}' is not one of ',', ';', '|', tab", text));
               }});
  t.push_back(on_off_option<O>(
      {"decimal_comma", "--decimal-comma", {}, "", "", "Numbers use ',' as the decimal point", {}},
      [](auto& o) -> auto& { return o.read.decimal_comma; }));
  t.push_back(on_off_option<O>(
      {"time_from_zero",
       "--time-from-zero",
       {},
       "",
       "",
       "Subtract the first time stamp (for loggers that count from their "
       "own boot)",
       {}},
      [](auto& o) -> auto& { return o.read.time_from_zero; }));
  // keep_extra read the other way round: the flag drops what is kept by default.
  const OptionSpec drop{
      "drop_extra",  "--drop-extra", OptionType::on_off, "", "", "Do not keep unmapped columns",
      {"keep_extra"}};
  t.push_back({drop, [](const O& o) { return std::string(o.read.keep_extra ? "false" : "true"); },
               [drop](O& o, const std::string& text) {
                 o.read.keep_extra = !parse_on_off_option(drop, text);
               }});
  t.push_back(whole_option<O>(
      {"skip_lines",
       "--skip-lines",
       {},
       "",
       "",
       "Lines before the header to skip (a logger's preamble of settings)",
       {}},
      [](auto& o) -> auto& { return o.read.skip_lines; }));
  t.push_back(number_option<O>(
      {"time_from_rate_hz",
       "--time-from-rate-hz",
       {},
       "Hz",
       at_least(0).with("0: the file has a time column"),
       "The file has no time column: time_s = row index / this rate",
       {}},
      [](auto& o) -> auto& { return o.read.time_from_rate_hz; }));
  const OptionSpec time_zero{"time_zero",
                             "--time-zero",
                             OptionType::text,
                             "",
                             "a date and time or a time of day, in the time column's form",
                             "With --unit time_s=iso8601 or clock: time_s counts from this instant "
                             "(e.g. the unit's power-on, '2020-03-07 15:41:07' or '15:41:07') "
                             "instead of from the first stamp, so that logs of one test share a "
                             "time axis",
                             {}};
  t.push_back({time_zero, [](const O& o) { return o.read.time_zero; },
               [](O& o, const std::string& text) { o.read.time_zero = text; }});
  t.push_back(on_off_option<O>(
      {"partial",
       "--partial",
       {},
       "",
       "",
       "The file lacks gyro_dph or temp_fog_degc (a chamber sheet, a "
       "thermometer logger): write it as a log to join into a recording with "
       "'fogdrift join'; its time may start before {time_zero}",
       {"allow_partial"}},
      [](auto& o) -> auto& { return o.read.allow_partial; }));
  const OptionSpec comment{"comment",
                           "--comment",
                           OptionType::text,
                           "",
                           "one character; empty: none",
                           "Lines starting with this character are comments, skipped (e.g. '#')",
                           {}};
  t.push_back(
      {comment,
       [](const O& o) { return o.read.comment ? std::string(1, o.read.comment) : std::string(); },
       [](O& o, const std::string& text) {
         if (text.size() > 1)
           throw OptionError("comment", fmt::format("'{}' is not a single character", text));
         o.read.comment = text.empty() ? '\0' : text[0];
       }});
  t.push_back(on_off_option<O>(
      {"hold_empty",
       "--hold-empty",
       {},
       "",
       "",
       "An empty cell takes the value of the row before (a channel logged "
       "slower than the others); the count per column is reported",
       {}},
      [](auto& o) -> auto& { return o.read.hold_empty; }));
  t.push_back(on_off_option<O>(
      {"split_at_reset",
       "--split-at-reset",
       {},
       "",
       "",
       "A time stamp smaller than the one before is a power cycle: write "
       "one recording per cycle (out.csv -> out_1.csv, out_2.csv, ...)",
       {}},
      [](auto& o) -> auto& { return o.read.split_at_reset; }));
  t.push_back(on_off_option<O>(
      {"hampel",
       "--hampel",
       {},
       "",
       "",
       "Replace spikes by the local median (Hampel filter), before the "
       "grid",
       {}},
      [](auto& o) -> auto& { return o.hampel; }));
  t.push_back(whole_option<O>(
      {"hampel_half_window",
       "--hampel-half-window",
       {},
       "",
       at_least(1),
       "Hampel window: this many samples either side",
       {"half_window"}},
      [](auto& o) -> auto& { return o.hampel_options.half_window; }));
  t.push_back(number_option<O>(
      {"hampel_sigma",
       "--hampel-sigma",
       {},
       "",
       above(0),
       "Hampel threshold, local STDs (3, the textbook value, replaces "
       "0.7-3 % of good samples; see docs/signal.md)",
       {"n_sigma"}},
      [](auto& o) -> auto& { return o.hampel_options.n_sigma; }));
  const OptionSpec outliers{"outlier_columns",
                            "--outlier-columns",
                            OptionType::names,
                            "",
                            "fogdrift columns; empty: gyro_dph and every thermometer the file has",
                            "Columns the Hampel filter looks at, comma-separated",
                            {}};
  t.push_back({outliers,
               [](const O& o) { return fmt::format("{}", fmt::join(o.read.outlier_columns, ",")); },
               [](O& o, const std::string& text) {
                 o.read.outlier_columns.clear();
                 if (!text.empty()) o.read.outlier_columns = option_items(text);
               }});
  t.push_back(number_option<O>(
      {"rate_hz",
       "--rate-hz",
       {},
       "Hz",
       at_least(0).with("0: keep the logger's time stamps"),
       "Put the recording on a uniform grid at this rate; for bursts, "
       "the burst rate, e.g. 1/305 s = 0.0032787",
       {}},
      [](auto& o) -> auto& { return o.rate_hz; }));
  t.push_back(number_option<O>(
      {"step_s",
       "--step-s",
       {},
       "s",
       at_least(0).with("0: not given"),
       "The same as {rate_hz}, given as the grid step (e.g. 60 for bursts "
       "every minute); times are then whole multiples of it",
       {}},
      [](auto& o) -> auto& { return o.step_s; }));
  t.push_back(choice_option<O>(
      {"method",
       "--method",
       {},
       "",
       "auto, mean, linear",
       "Grid filling: mean (bins of the step; anti-aliasing for faster logs), linear "
       "(interpolation; jitter), auto (mean when the log is at least twice as fast)",
       {}},
      [](auto& o) -> auto& { return o.method; }, [](RegridMethod m) { return to_string(m); },
      [](const std::string& text, const std::string&) { return regrid_method_from_string(text); }));
  // 0 is a gap limit too (every gap splits), so not seconds_or_auto's "> 0".
  const OptionSpec gap{"max_gap_s",
                       "--max-gap-s",
                       OptionType::seconds_or_auto,
                       "s",
                       at_least(0),
                       "Longest gap bridged by interpolation; longer gaps split the recording; "
                       "auto: 10 grid steps",
                       {}};
  t.push_back({gap,
               [](const O& o) {
                 return o.max_gap_s ? option_number_text(*o.max_gap_s) : std::string("auto");
               },
               [gap](O& o, const std::string& text) {
                 if (text == "auto")
                   o.max_gap_s.reset();
                 else
                   o.max_gap_s = parse_number_option(gap, text);
               }});
  return t;
}

}  // namespace

const OptionTable<ImportRunOptions>& import_option_table() {
  static const OptionTable<ImportRunOptions> table = make_import_table();
  return table;
}

ImportPlan import_plan(const ImportRunOptions& o) {
  ImportPlan plan{o.read, std::nullopt};
  for (const auto& [column, unit] : o.units)
    plan.read.conversions[column] = parse_unit(column, unit);
  const signal::HampelOptions defaults;
  if (o.hampel) {
    plan.read.outliers = o.hampel_options;
  } else {
    if (o.hampel_options.n_sigma != defaults.n_sigma)
      throw OptionError("hampel_sigma", "has no effect without {hampel}");
    if (o.hampel_options.half_window != defaults.half_window)
      throw OptionError("hampel_half_window", "has no effect without {hampel}");
    if (!o.read.outlier_columns.empty())
      throw OptionError("outlier_columns", "has no effect without {hampel}");
  }
  if (o.rate_hz != 0 && o.step_s != 0)
    throw OptionError("step_s", "give {rate_hz} or {step_s}, not both");
  if (o.rate_hz == 0 && o.step_s == 0) {
    if (o.method != RegridMethod::automatic)
      throw OptionError("method", "has no effect without {rate_hz} R or {step_s} S");
    if (o.max_gap_s)
      throw OptionError("max_gap_s", "has no effect without {rate_hz} R or {step_s} S");
    return plan;
  }
  RegridOptions grid;
  grid.step_s = o.step_s != 0 ? o.step_s : 1.0 / o.rate_hz;
  grid.method = o.method;
  grid.max_gap_s = o.max_gap_s.value_or(-1.0);  // regrid's own "the default"
  plan.grid = grid;
  return plan;
}

}  // namespace fogdrift
