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
#include "fogdrift/io/import_option_table.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/regrid.hpp"
#include "fogdrift/signal/hampel.hpp"
#include "option_flags.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  std::string out;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;  // import's options (import_option_table.hpp)
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
  const auto& table = import_option_table();
  a->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] {
    ImportRunOptions given;
    a->flags->apply(import_option_table(), given);
    ImportPlan plan;
    try {
      plan = import_plan(given);
    } catch (const OptionError& e) {
      throw a->flags->named(e);
    }
    const ImportOptions& o = plan.read;
    const std::optional<RegridOptions>& grid = plan.grid;
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
                            : given.step_s != 0    ? "--step-s"
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
