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
#include "fogdrift/io/join_option_table.hpp"
#include "fogdrift/io/recording.hpp"
#include "option_flags.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct JoinArgs {
  std::string recording;
  std::string log;
  std::string out;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;  // join's options (join_option_table.hpp)
};

/// "a=b", or "a" when both columns have one name.
std::string pair_name(const ColumnMatch& m) {
  return m.recording_column == m.log_column ? m.recording_column
                                            : m.recording_column + "=" + m.log_column;
}

/// What supports the offset: printed before the join, and before a refusal.
void print_evidence(const JoinEvidence& ev) {
  if (ev.given) {
    std::cout << fmt::format("  clock offset: {:.6g} s as given (t_recording = t_log + offset)\n",
                             ev.offset_s);
    return;
  }
  for (const ColumnMatch& m : ev.matches) {
    const OffsetEstimate& e = m.estimate;
    std::cout << fmt::format(
        "  clock offset from {}: {:.6g} s, sharp to ±{:.3g} s (searched {:.6g} .. {:.6g} s)\n"
        "    over {} rows ({:.6g} s): the difference has STD {:.4g} against the column's own "
        "{:.4g} ({:.2g} %){}; the columns stand {:.4g} apart, and vary by {:.4g} and {:.4g}\n",
        pair_name(m), e.offset_s, e.half_width_s, e.searched_from_s, e.searched_to_s,
        e.rows_compared, e.compared_to_s - e.compared_from_s, e.residual_std, e.recording_std,
        e.recording_std > 0 ? 100 * e.residual_std / e.recording_std : 0.0,
        std::isnan(e.residual_std_at_start)
            ? std::string()
            : fmt::format(" (at {:.6g} s: {:.4g})", e.centre_s, e.residual_std_at_start),
        e.mean_difference, e.recording_range, e.log_range);
  }
  if (ev.matches.size() > 1)
    std::cout << fmt::format(
        "  clock offset applied: {:.6g} s, the estimates weighted by their "
        "sharpness\n",
        ev.offset_s);
  std::cout << (ev.founded() ? "  evidence: founded (docs/logs.md, \"The evidence\")\n"
                             : "  evidence: NOT founded (docs/logs.md, \"The evidence\")\n");
}

void print_summary(const JoinSummary& s, const Recording& recording, const Recording& log) {
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
  if (s.forced)
    for (const std::string& f : s.evidence.failures)
      std::cout << fmt::format("warning: written with --force against the evidence: {}\n", f);
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
      "linear interpolation or from the nearest sample. Nothing ties two clocks together, so the\n"
      "offset has no default: give it (--offset-s, 0 when both were imported with the same\n"
      "--time-zero) or estimate it from a column both hold (--offset-from, repeatable). An\n"
      "estimate is judged before anything is written: the two columns must move together, stand\n"
      "no farther apart than they vary, fix the offset sharply, and agree with each other;\n"
      "otherwise join refuses, printing the evidence (--force writes anyway, with warnings).\n"
      "Rows the log does not cover are dropped, and a gap in the log longer than the limit splits\n"
      "the recording (out_1.csv, ...). See docs/logs.md, \"Temperatures from another file\";\n"
      "docs/options.md describes the options.");
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
  const auto& table = join_option_table();
  a->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] {
    JoinOptions o;
    a->flags->apply(join_option_table(), o);
    const Recording recording = read_log(a->recording);
    const Recording log = read_log(a->log);
    check_output_not_input(a->out, "--output");
    JoinResult r;
    try {
      const JoinEvidence evidence = judge_alignment(recording, log, o);
      if (!a->quiet || !evidence.founded()) print_evidence(evidence);
      r = join(recording, log, o, evidence);
    } catch (const OptionError& e) {
      throw a->flags->named(e);  // each library option in its flag's words
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
