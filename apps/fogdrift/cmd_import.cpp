// fogdrift import: turn a foreign logger CSV into a fogdrift recording.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/io/import.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/regrid.hpp"
#include "fogdrift/signal/hampel.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  std::string out;
  std::vector<std::string> maps;
  std::vector<std::string> units;
  std::string delimiter = ",";
  bool decimal_comma = false;
  bool time_from_zero = false;
  bool drop_extra = false;
  std::size_t skip_lines = 0;
  double time_from_rate_hz = 0;
  std::string time_zero;
  bool partial = false;
  std::string comment;
  bool hold_empty = false;
  bool split_at_reset = false;
  double rate_hz = 0;
  double step_s = 0;
  std::string method = "auto";
  double max_gap_s = -1;
  bool hampel = false;
  std::size_t hampel_half_window = signal::HampelOptions{}.half_window;
  double hampel_sigma = signal::HampelOptions{}.n_sigma;
  std::string outlier_columns;  ///< empty: gyro_dph and every thermometer the file has
  bool quiet = false;
};

/// How import treated one file, for people: spikes, grid, gaps and segments.
void report(const ImportReport& imported, const std::vector<RegridSummary>& grids) {
  for (const std::string& note : imported.notes) std::cout << fmt::format("  note: {}\n", note);
  if (!imported.missing.empty())
    std::cout << fmt::format(
        "  a log to join: it has no {}; 'fogdrift join RECORDING LOG -o OUT' brings its columns "
        "into a recording by time\n",
        fmt::join(imported.missing, " and no "));
  for (const auto& [column, count] : imported.held)
    std::cout << fmt::format("  empty cells: {} in {} took the value before\n", count, column);
  for (const auto& r : imported.outliers) {
    if (r.lines.empty()) {
      std::cout << fmt::format("  spikes: none in {}\n", r.column);
      continue;
    }
    // The largest first: the ones a user checks against the logger's own notes.
    std::vector<std::size_t> order(r.lines.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return std::fabs(r.was[x] - r.now[x]) > std::fabs(r.was[y] - r.now[y]);
    });
    std::cout << fmt::format("  spikes: {} replaced in {}", r.lines.size(), r.column);
    for (std::size_t k = 0; k < std::min<std::size_t>(order.size(), 5); ++k)
      std::cout << fmt::format("{} line {} {:.6g} -> {:.6g}", k ? "," : ":", r.lines[order[k]],
                               r.was[order[k]], r.now[order[k]]);
    std::cout << (r.lines.size() > 5 ? ", ...\n" : "\n");
  }
  // Each column is looked at on its own, so one glitch seen by two channels counts twice, and a
  // thermometer's spike counts beside the gyro's (docs/logs.md, "Spikes").
  std::size_t total = 0, columns = 0;
  for (const auto& r : imported.outliers) {
    total += r.lines.size();
    columns += r.lines.empty() ? 0 : 1;
  }
  if (columns > 1)
    std::cout << fmt::format(
        "  spikes in all: {} samples in {} columns, each column looked at on its own\n", total,
        columns);
  for (const RegridSummary& g : grids) {
    std::cout << fmt::format(
        "  grid: {} samples (median step {:.6g} s, jitter up to {:.1f} %) -> {} samples every "
        "{:.6g} s by {}\n",
        g.input_samples, g.input_median_step_s, 100 * g.input_max_jitter, g.output_samples,
        g.step_s, to_string(g.method));
    std::size_t bridged = 0, split = 0;
    for (const auto& gap : g.gaps) (gap.bridged ? bridged : split) += 1;
    if (!g.gaps.empty())
      std::cout << fmt::format(
          "  gaps: {} bridged by interpolation, {} split (limit --max-gap-s "
          "{:.6g} s)\n",
          bridged, split, g.max_gap_s);
    for (std::size_t k = 0; k < g.gaps.size() && k < 10; ++k) {
      const auto& gap = g.gaps[k];
      std::cout << fmt::format(
          "    {:.6g} .. {:.6g} s ({:.6g} s): {}\n", gap.start_s, gap.end_s, gap.length_s(),
          gap.bridged ? fmt::format("bridged, {} samples interpolated", gap.filled)
                      : std::string("split"));
    }
    if (g.gaps.size() > 10) std::cout << fmt::format("    ... {} more\n", g.gaps.size() - 10);
    if (g.dropped_segments)
      std::cout << fmt::format("  dropped {} segment(s) of a single sample\n", g.dropped_segments);
    if (!g.dropped_columns.empty())
      std::cout << fmt::format("  not carried onto the grid (text columns): {}\n",
                               fmt::join(g.dropped_columns, ", "));
  }
}

std::pair<std::string, std::string> split_assignment(const std::string& text,
                                                     const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw OptionError(fmt::format("{} {}", option, text),
                      "expected FOGDRIFT_COLUMN=VALUE, e.g. gyro_dph=\"Rate X [rad/s]\"");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

char parse_delimiter(const std::string& text) {
  if (text == "," || text == ";" || text == "|") return text[0];
  if (text == "\\t" || text == "\t" || text == "tab") return '\t';
  throw OptionError("--delimiter", fmt::format("'{}' is not one of ',', ';', '|', tab", text));
}

}  // namespace

void add_import(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "import",
      "Convert foreign logger CSV files into fogdrift recordings: map their columns onto\n"
      "fogdrift's and convert units. Unmapped columns are kept as extra columns. Example:\n"
      "  fogdrift import run7.csv -o run7_fd.csv --map time_s=\"t [ms]\" --unit time_s=ms \\\n"
      "    --map gyro_dph=\"Rate X [rad/s]\" --unit gyro_dph=rad/s \\\n"
      "    --map temp_fog_degc=T0 --unit temp_fog_degc=counts:0.0625:-40 ...\n"
      "Units: time_s s|ms|us|iso8601|clock; gyro_dph deg/h|deg/s|rad/s|mrad/s|arcsec/s; "
      "temperatures\n"
      "degC|K|degF; accel_*_g g|mg|m/s2; table_deg deg|rad; any column counts:SCALE:OFFSET\n"
      "(value = counts·SCALE + OFFSET) or intN:SCALE:OFFSET (a signed register, also when logged\n"
      "as its unsigned bit pattern).\n"
      "Jittery, bursty or gappy logs: --rate-hz R puts them on a uniform grid (what train needs),\n"
      "bridging gaps up to --max-gap-s and splitting at longer ones (out.csv -> out_1.csv, ...).\n"
      "Spikes: --hampel replaces samples more than --hampel-sigma local STDs from the median of\n"
      "their window. Each change is reported. See docs/logs.md for a logger file from end to end.");
  auto a = std::make_shared<ImportArgs>();
  cmd->add_option("INPUT", a->inputs, "Foreign CSV file(s)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", a->out,
                  "Output recording (one input), or an existing folder (several inputs)")
      ->required();
  cmd->add_option("--map", a->maps, "FOGDRIFT_COLUMN=FOREIGN_COLUMN (repeatable)");
  cmd->add_option("--unit", a->units, "FOGDRIFT_COLUMN=UNIT (repeatable)");
  cmd->add_option("--delimiter", a->delimiter, "Field separator: ',' ';' '|' or tab")
      ->capture_default_str();
  cmd->add_flag("--decimal-comma", a->decimal_comma, "Numbers use ',' as the decimal point");
  cmd->add_flag("--time-from-zero", a->time_from_zero,
                "Subtract the first time stamp (for loggers that count from their own boot)");
  cmd->add_flag("--drop-extra", a->drop_extra, "Do not keep unmapped columns");
  cmd->add_option("--skip-lines", a->skip_lines,
                  "Lines before the header to skip (a logger's preamble of settings)")
      ->capture_default_str();
  cmd->add_option("--time-from-rate-hz", a->time_from_rate_hz,
                  "The file has no time column: time_s = row index / this rate, Hz");
  cmd->add_option("--time-zero", a->time_zero,
                  "With --unit time_s=iso8601 or clock: time_s counts from this instant (e.g. "
                  "the unit's power-on, '2020-03-07 15:41:07' or '15:41:07') instead of from the "
                  "first stamp, so that logs of one test share a time axis");
  cmd->add_flag("--partial", a->partial,
                "The file lacks gyro_dph or temp_fog_degc (a chamber sheet, a thermometer "
                "logger): write it as a log to join into a recording with 'fogdrift join'; its "
                "time may start before --time-zero");
  cmd->add_option("--comment", a->comment,
                  "Lines starting with this character are comments, skipped (e.g. '#')");
  cmd->add_flag("--hold-empty", a->hold_empty,
                "An empty cell takes the value of the row before (a channel logged slower than "
                "the others); the count per column is reported");
  cmd->add_flag("--split-at-reset", a->split_at_reset,
                "A time stamp smaller than the one before is a power cycle: write one recording "
                "per cycle (out.csv -> out_1.csv, out_2.csv, ...)");
  cmd->add_option("--rate-hz", a->rate_hz,
                  "Put the recording on a uniform grid at this rate, Hz (0: keep the logger's "
                  "time stamps); for bursts, the burst rate, e.g. 1/305 s = 0.0032787")
      ->capture_default_str();
  cmd->add_option("--step-s", a->step_s,
                  "The same as --rate-hz, given as the grid step, s (e.g. 60 for bursts every "
                  "minute); times are then whole multiples of it");
  cmd->add_option("--method", a->method,
                  "Grid filling: mean (bins of 1/rate; anti-aliasing for faster logs), linear "
                  "(interpolation; jitter), auto (mean when the log is at least twice as fast)")
      ->capture_default_str();
  cmd->add_option("--max-gap-s", a->max_gap_s,
                  "Longest gap bridged by interpolation, s; longer gaps split the recording "
                  "(default: 10 grid steps)");
  cmd->add_flag("--hampel", a->hampel,
                "Replace spikes by the local median (Hampel filter), before --rate-hz");
  cmd->add_option("--hampel-half-window", a->hampel_half_window,
                  "Hampel window: this many samples either side")
      ->capture_default_str();
  cmd->add_option("--hampel-sigma", a->hampel_sigma,
                  "Hampel threshold, local STDs (3, the textbook value, replaces 0.7-3 % of good "
                  "samples; see docs/signal.md)")
      ->capture_default_str();
  cmd->add_option("--outlier-columns", a->outlier_columns,
                  "Columns the Hampel filter looks at, comma-separated (default: gyro_dph and "
                  "every thermometer the file has)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] {
    ImportOptions o;
    for (const auto& m : a->maps) {
      auto [target, source] = split_assignment(m, "--map");
      o.columns[target] = source;
    }
    for (const auto& u : a->units) {
      auto [target, unit] = split_assignment(u, "--unit");
      o.conversions[target] = parse_unit(target, unit);
    }
    o.delimiter = parse_delimiter(a->delimiter);
    o.decimal_comma = a->decimal_comma;
    o.time_from_zero = a->time_from_zero;
    o.keep_extra = !a->drop_extra;
    o.split_at_reset = a->split_at_reset;
    o.skip_lines = a->skip_lines;
    o.time_from_rate_hz = a->time_from_rate_hz;
    o.time_zero = a->time_zero;
    o.allow_partial = a->partial;
    o.hold_empty = a->hold_empty;
    if (a->comment.size() > 1)
      throw OptionError("--comment", fmt::format("'{}' is not a single character", a->comment));
    if (!a->comment.empty()) o.comment = a->comment[0];
    if (a->hampel) {
      o.outliers = signal::HampelOptions{a->hampel_half_window, a->hampel_sigma};
      if (!a->outlier_columns.empty()) o.outlier_columns = split_list(a->outlier_columns);
    } else if (a->hampel_sigma != signal::HampelOptions{}.n_sigma ||
               a->hampel_half_window != signal::HampelOptions{}.half_window) {
      throw OptionError(a->hampel_sigma != signal::HampelOptions{}.n_sigma ? "--hampel-sigma"
                                                                           : "--hampel-half-window",
                        "has no effect without --hampel");
    }
    std::optional<RegridOptions> grid;
    if (a->rate_hz != 0 && a->step_s != 0)
      throw OptionError("--step-s", "give --rate-hz or --step-s, not both");
    if (a->rate_hz < 0)
      throw OptionError("--rate-hz", fmt::format("{} Hz is negative", a->rate_hz));
    if (a->rate_hz != 0 || a->step_s != 0) {
      grid.emplace();
      grid->step_s = a->step_s != 0 ? a->step_s : 1.0 / a->rate_hz;
      grid->max_gap_s = a->max_gap_s;
      try {
        grid->method = regrid_method_from_string(a->method);
      } catch (const OptionError& e) {
        throw OptionError("--method", e.message());
      }
      if (a->max_gap_s < 0 && a->max_gap_s != -1)
        throw OptionError("--max-gap-s", fmt::format("{} s is negative", a->max_gap_s));
    } else if (a->method != "auto" || a->max_gap_s != -1) {
      throw OptionError(a->method != "auto" ? "--method" : "--max-gap-s",
                        "has no effect without --rate-hz R or --step-s S");
    }
    const bool to_folder = a->inputs.size() > 1 || fs::is_directory(a->out);
    if (to_folder && !fs::is_directory(a->out)) {
      throw OptionError("--out", fmt::format("'{}' must be an existing folder when importing "
                                             "several files",
                                             a->out));
    }
    // Read and convert everything first, so a bad file leaves no partial set of outputs.
    struct Converted {
      fs::path target;
      std::vector<Recording> segments;
      ImportReport report;
      std::vector<RegridSummary> grids;  ///< one per power cycle
    };
    std::vector<Converted> converted;
    for (const auto& input : a->inputs) {
      Converted c;
      c.target = to_folder ? fs::path(a->out) / fs::path(input).filename() : fs::path(a->out);
      for (Recording& rec : import_recordings(input, o, &c.report)) {
        if (!grid) {
          c.segments.push_back(std::move(rec));
          continue;
        }
        RegridResult r;
        try {
          r = regrid(rec, *grid);
        } catch (const OptionError& e) {
          throw OptionError(e.option() != "step_s" ? "--max-gap-s"
                            : a->step_s != 0       ? "--step-s"
                                                   : "--rate-hz",
                            e.message());
        }
        for (auto& seg : r.segments) c.segments.push_back(std::move(seg));
        c.grids.push_back(r.summary);
      }
      converted.push_back(std::move(c));
    }
    for (const auto& c : converted)
      for (std::size_t k = 0; k < c.segments.size(); ++k)
        check_output_not_input(piece_path(c.target, k, c.segments.size()), "--out");
    for (const auto& c : converted) {
      for (std::size_t k = 0; k < c.segments.size(); ++k) {
        const fs::path path = piece_path(c.target, k, c.segments.size());
        write_recording(path, c.segments[k]);
        if (!a->quiet)
          std::cout << fmt::format("{} -> {} ({} samples, {:.6g} .. {:.6g} s)\n",
                                   c.segments[k].source, path.string(), c.segments[k].size(),
                                   c.segments[k].time_s.front(), c.segments[k].time_s.back());
      }
      if (!a->quiet) report(c.report, c.grids);
      if (!a->quiet && c.grids.empty() && !c.segments.front().partial &&
          !is_uniformly_sampled(c.segments.front()))
        std::cout << "  note: the time steps are not uniform (within 1 %); train needs that: "
                     "import again with --rate-hz R\n";
    }
  });
}

}  // namespace fogdrift::app
