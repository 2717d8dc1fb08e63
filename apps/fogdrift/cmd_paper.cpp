// fogdrift paper: the paper's experiment end to end on the simulator (report/paper.hpp), printed
// as tables beside the paper's values, and written as report.md, JSON and PNG figures.
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/report/paper_option_table.hpp"
#include "fogdrift/report/paper_report.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {

void add_paper_options(CLI::App* cmd, PaperArgs& a) {
  cmd->add_option("--out,-o", a.out,
                  "Folder for report.md, paper.json and the figures (PNG and JSON); written "
                  "atomically, an existing folder only with --force");
  cmd->add_flag("--force", a.force, "Replace an existing --out folder");
  const auto& table = report::paper_option_table();
  a.options = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table, a.defaults));
  cmd->add_option("--instrument", a.instrument_file,
                  "Instrument parameters (JSON); default built in");
  cmd->add_option("--threads", a.threads, "Threads (0: one per core); results do not depend on it")
      ->capture_default_str();
  cmd->add_flag("--json", a.json, "Print the results as JSON instead of tables");
  cmd->add_flag("-q,--quiet", a.quiet, "Print nothing on success");
}

namespace {

void run_paper_unnamed(const PaperArgs& a, report::PaperOptions o);

}  // namespace

void run_paper_command(const PaperArgs& a) {
  report::PaperOptions o = a.defaults;
  a.options->apply(report::paper_option_table(), o);
  try {
    run_paper_unnamed(a, std::move(o));
  } catch (const OptionError& e) {
    throw a.options->named(e);
  }
}

namespace {

void run_paper_unnamed(const PaperArgs& a, report::PaperOptions o) {
  if (!a.instrument_file.empty())
    o.instrument = sim::instrument_from_json(read_text_file(a.instrument_file), a.instrument_file);
  if (!a.out.empty()) {
    check_output_not_input(a.out, "--out");
    const std::filesystem::path out(a.out);
    std::error_code ec;
    if (std::filesystem::exists(out, ec) && !std::filesystem::is_empty(out, ec) && !a.force)
      throw OptionError("--out", fmt::format("{} exists and is not empty; use --force to "
                                             "replace it",
                                             a.out));
  }
  report::validate(o);
  ThreadPool pool(a.threads);
  o.pool = &pool;
  const bool show_progress = !a.quiet && !a.json && stderr_is_terminal();
  const auto start = std::chrono::steady_clock::now();
  if (show_progress) {
    o.progress = [&](const std::string& stage, double fraction) {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cerr << fmt::format("\r\033[K[{:3.0f} %] {:.0f} s  {}", 100 * fraction, s, stage)
                << std::flush;
    };
  }
  report::PaperResult result;
  try {
    result = report::run_paper(o);
  } catch (...) {
    if (show_progress) std::cerr << "\n";
    throw;
  }
  if (show_progress) std::cerr << "\r\033[K";

  const std::string markdown = report::paper_markdown(result);
  const std::string json = report::paper_json(result);
  std::vector<std::string> figure_problems;
  if (!a.out.empty()) {
    fill_directory_atomically(a.out, a.force, [&](const std::filesystem::path& dir) {
      write_text_atomically(dir / "report.md", markdown);
      write_text_atomically(dir / "paper.json", json);
      figure_problems = report::write_figures(result.figures, dir);
    });
  }
  if (a.json) {
    std::cout << json;
  } else if (!a.quiet) {
    std::cout << markdown;
    if (!a.out.empty())
      std::cout << fmt::format("\nWrote report.md, paper.json and {} figures to {}/\n",
                               result.figures.size(), a.out);
  }
  for (const auto& p : figure_problems) std::cerr << "fogdrift paper: no PNG: " << p << "\n";
}

}  // namespace

void add_paper(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "paper",
      "Reproduce the paper's experiment on the built-in simulator: simulate the calibration\n"
      "campaign, train BP, SVR, PSO-SVR, GWO-SVR and SSA-SVR on repetitions 1-3, evaluate on\n"
      "repetition 4 (Table 2), north-find at -32 … 54 °C during the start-up and at the stable\n"
      "stage (Table 3), with SSA-SVR's C and σ (Table 1); repeat over --seeds seeds and print\n"
      "mean ± SD beside the paper's numbers. The first seed also runs a leave-one-temperature-\n"
      "out study and the training-loss against cross-validation fitness. With --out, writes\n"
      "report.md, paper.json and the figures as PNG (gnuplot) and JSON.\n"
      "Defaults take about 5 minutes on 2 cores. Examples:\n"
      "  fogdrift paper --out paper\n"
      "  fogdrift paper --seeds 10 --population 20 --iterations 50 --json > paper.json\n"
      "  fogdrift paper --fitness train --approach soaked --seeds 3");
  auto a = std::make_shared<PaperArgs>();
  add_paper_options(cmd, *a);
  cmd->callback([a] { run_paper_command(*a); });
}

}  // namespace fogdrift::app
