// fogdrift join: bring the columns of a second log (a chamber sheet) into a recording by time.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/io/join.hpp"
#include "fogdrift/io/recording.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct JoinArgs {
  std::string recording;
  std::string log;
  std::string out;
  std::string columns;  ///< empty: every numeric column of the log
  bool replace = false;
  std::string method = "linear";
  double offset_s = 0;
  std::string offset_from;
  double offset_range_s = 0;
  double max_step_s = -1;
  double max_age_s = -1;
  bool quiet = false;
};

void print_summary(const JoinSummary& s, const Recording& recording, const Recording& log) {
  if (s.estimate) {
    const OffsetEstimate& e = *s.estimate;
    std::cout << fmt::format(
        "  clock offset: {:.6g} s estimated (searched {:.6g} .. {:.6g} s; sharp to about ±{:.3g} "
        "s); the difference of the two columns has STD {:.4g} there{}, over {} rows\n",
        e.offset_s, e.searched_from_s, e.searched_to_s, e.half_width_s, e.residual_std,
        std::isnan(e.residual_std_at_start)
            ? std::string()
            : fmt::format(" (at the offset given, {:.6g} s: {:.4g})", e.centre_s,
                          e.residual_std_at_start),
        e.rows_compared);
    if (e.at_edge)
      std::cout << "  warning: the estimate lies at an end of the searched range; widen "
                   "--offset-range-s or give --offset-s near the true offset\n";
    if (e.half_width_s > 0.1 * (e.searched_to_s - e.searched_from_s))
      std::cout << "  warning: the column fixes the offset poorly (it changes too little, or "
                   "at a constant rate); check the estimate or give --offset-s\n";
  } else {
    std::cout << fmt::format("  clock offset: {:.6g} s (t_recording = t_log + offset)\n",
                             s.offset_s);
  }
  std::cout << fmt::format(
      "  overlap: the log spans {:.6g} .. {:.6g} s on the recording's axis, the recording "
      "{:.6g} .. {:.6g} s; {} log samples fall inside\n",
      s.log_from_s, s.log_to_s, recording.time_s.front(), recording.time_s.back(), s.log_rows_used);
  std::cout << fmt::format("  joined {} by {} (limit {:.6g} s): {} of {} rows kept",
                           fmt::join(s.columns, ", "), to_string(s.method), s.limit_s, s.rows_out,
                           s.rows_in);
  if (s.dropped_before + s.dropped_after + s.dropped_inside > 0)
    std::cout << fmt::format("; dropped {} before the log, {} after it, {} inside its gaps",
                             s.dropped_before, s.dropped_after, s.dropped_inside);
  std::cout << "\n";
  if (!s.kept.empty())
    std::cout << fmt::format("  kept the recording's own {} (--replace takes the log's)\n",
                             fmt::join(s.kept, ", "));
  if (!s.skipped.empty())
    std::cout << fmt::format("  not joined (text columns of {}): {}\n", log.source,
                             fmt::join(s.skipped, ", "));
}

}  // namespace

void add_join(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "join",
      "Bring the columns of a second log into a recording by time: thermometers logged by the\n"
      "chamber or by hand on another machine. Import both first (the sheet with 'import\n"
      "--partial', time-of-day stamps with --unit time_s=clock and --time-zero), then:\n"
      "  fogdrift join unit.csv sheet.csv -o joined.csv --offset-from temp_fog_degc=T_case\n"
      "A row at time t takes the log's values at t - offset (t_recording = t_log + offset), by\n"
      "linear interpolation or from the nearest sample. The offset is given (--offset-s) or\n"
      "estimated from a column both hold (--offset-from). Rows the log does not cover are\n"
      "dropped, and a gap in the log longer than the limit splits the recording (out_1.csv, ...).\n"
      "See docs/logs.md, \"Temperatures from another file\".");
  auto a = std::make_shared<JoinArgs>();
  cmd->add_option("RECORDING", a->recording, "The recording (fogdrift format)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("LOG", a->log,
                  "The log to join: fogdrift format, time_s required ('import "
                  "--partial' writes one)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", a->out, "The joined recording")->required();
  cmd->add_option("--columns", a->columns,
                  "The log's columns to bring in, comma-separated (default: every numeric one)");
  cmd->add_flag("--replace", a->replace,
                "A column the recording has already takes the log's values (default: an error)");
  cmd->add_option("--method", a->method,
                  "linear (interpolate between the log samples either side) or nearest (the "
                  "nearest log sample)")
      ->capture_default_str();
  cmd->add_option("--offset-s", a->offset_s,
                  "Clock offset, s: t_recording = t_log + offset; with --offset-from, the centre "
                  "of the search")
      ->capture_default_str();
  cmd->add_option("--offset-from", a->offset_from,
                  "Estimate the offset from a column both files hold: RECORDING_COLUMN=LOG_COLUMN, "
                  "or one name for both; the offset that minimises the variance of their "
                  "difference");
  cmd->add_option("--offset-range-s", a->offset_range_s,
                  "With --offset-from: search --offset-s ± this, s (default 0: every offset that "
                  "leaves half the shorter file overlapping)")
      ->capture_default_str();
  cmd->add_option("--max-step-s", a->max_step_s,
                  "linear: the longest step between two log samples interpolated across, s "
                  "(default: 1.5 × the log's median step)");
  cmd->add_option("--max-age-s", a->max_age_s,
                  "nearest: the farthest a log sample may be from the row, s (default: the log's "
                  "median step)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] {
    JoinOptions o;
    if (!a->columns.empty()) o.columns = split_list(a->columns);
    o.replace = a->replace;
    try {
      o.method = join_method_from_string(a->method);
    } catch (const OptionError& e) {
      throw OptionError("--method", e.message());
    }
    o.offset_s = a->offset_s;
    o.max_step_s = a->max_step_s;
    o.max_age_s = a->max_age_s;
    if (!a->offset_from.empty()) {
      const auto eq = a->offset_from.find('=');
      OffsetSearch search;
      search.recording_column = a->offset_from.substr(0, eq);
      search.log_column =
          eq == std::string::npos ? search.recording_column : a->offset_from.substr(eq + 1);
      if (search.recording_column.empty() || search.log_column.empty())
        throw OptionError("--offset-from", fmt::format("'{}' is not COLUMN or "
                                                       "RECORDING_COLUMN=LOG_COLUMN",
                                                       a->offset_from));
      search.range_s = a->offset_range_s;
      o.estimate = search;
    } else if (a->offset_range_s != 0) {
      throw OptionError("--offset-range-s", "has no effect without --offset-from");
    }
    const Recording recording = read_log(a->recording);
    const Recording log = read_log(a->log);
    check_output_not_input(a->out, "--output");
    JoinResult r;
    try {
      r = join(recording, log, o);
    } catch (const OptionError& e) {
      const std::string& n = e.option();
      throw OptionError(n == "columns"      ? "--columns"
                        : n == "method"     ? "--method"
                        : n == "offset_s"   ? "--offset-s"
                        : n == "estimate"   ? "--offset-from"
                        : n == "max_step_s" ? "--max-step-s"
                        : n == "max_age_s"  ? "--max-age-s"
                                            : n,
                        e.message());
    }
    for (std::size_t k = 0; k < r.segments.size(); ++k) {
      const fs::path path = piece_path(a->out, k, r.segments.size());
      write_recording(path, r.segments[k]);
      if (!a->quiet)
        std::cout << fmt::format("{} + {} -> {} ({} samples, {:.6g} .. {:.6g} s){}\n",
                                 recording.source, log.source, path.string(), r.segments[k].size(),
                                 r.segments[k].time_s.front(), r.segments[k].time_s.back(),
                                 r.segments[k].partial
                                     ? fmt::format(", still a log to join: no {}",
                                                   fmt::join(missing_required(r.segments[k]), ", "))
                                     : std::string());
    }
    if (!a->quiet) print_summary(r.summary, recording, log);
  });
}

}  // namespace fogdrift::app
