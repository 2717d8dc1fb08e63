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
#include "fogdrift/report/paper_report.hpp"
#include "fogdrift/sim/instrument.hpp"

namespace fogdrift::app {

void add_paper_options(CLI::App* cmd, PaperArgs& a) {
  cmd->add_option("--out,-o", a.out,
                  "Folder for report.md, paper.json and the figures (PNG and JSON); written "
                  "atomically, an existing folder only with --force");
  cmd->add_flag("--force", a.force, "Replace an existing --out folder");
  cmd->add_option("--seeds", a.seeds, "Independent repetitions of the whole experiment")
      ->capture_default_str();
  cmd->add_option("--methods", a.methods,
                  "Methods of Tables 2-3 and the start-up conditions table, in order, "
                  "comma-separated, of " +
                      method_names() +
                      " (train --help says what each is): the paper's, and any other after "
                      "them; bp and ssa-svr are always needed")
      ->capture_default_str();
  cmd->add_option("--first-seed", a.first_seed, "Seeds are first, first + 1, …")
      ->capture_default_str();
  cmd->add_option("--population", a.population, "Optimizer population of the tuned SVRs")
      ->capture_default_str();
  cmd->add_option("--iterations", a.iterations, "Optimizer iterations of the tuned SVRs")
      ->capture_default_str();
  cmd->add_option("--fitness", a.fitness, "cv (grouped cross-validation) or train (the paper's)")
      ->capture_default_str();
  cmd->add_option("--cv", a.cv,
                  "Folds of the cv fitness: auto or repetition (leave one training repetition "
                  "out), recording (k folds of whole recordings) or temperature (k folds of whole "
                  "calibration temperatures, scoring a model where it was not trained)")
      ->capture_default_str();
  cmd->add_option("--folds", a.folds, "k for --cv recording or temperature")->capture_default_str();
  cmd->add_option("--epsilon", a.epsilon, "ε of the tuned SVRs (standardised target)")
      ->capture_default_str();
  cmd->add_flag("--search-epsilon", a.search_epsilon,
                "The tuned SVRs also search ε in [0.001, 1] (the paper tunes C and σ only)");
  cmd->add_option("--approach", a.approach,
                  "How the Table 3 north-finding start-ups begin: calibration, soaked, warm, "
                  "ramping or sweep (fogdrift simulate northfind --help)")
      ->capture_default_str();
  cmd->add_option("--cal-approaches", a.cal_approaches,
                  "How each calibration repetition's start-ups begin, cycling (fogdrift simulate "
                  "calibration --help): the protocol docs/field.md recommends; the paper's own is "
                  "--cal-approaches calibration --repetitions 4")
      ->capture_default_str();
  cmd->add_option("--repetitions", a.repetitions,
                  "Calibration repetitions; the last one is the test repetition")
      ->capture_default_str();
  cmd->add_option("--start-ups", a.start_ups,
                  "Approaches of the start-up conditions table, comma-separated, or none")
      ->capture_default_str();
  cmd->add_option("--cal-temps", a.cal_temps,
                  "Calibration chamber temperatures, °C, comma-separated")
      ->default_str("-40,-30,…,60");
  cmd->add_option("--nf-temps", a.nf_temps,
                  "North-finding initial temperatures, °C, comma-separated")
      ->default_str("-32,-16,-5,17,28,43,54");
  cmd->add_option("--findings", a.findings, "North-findings per initial temperature")
      ->capture_default_str();
  cmd->add_flag("--no-studies", a.no_studies,
                "Skip the leave-one-temperature-out and fitness studies");
  cmd->add_option("--instrument", a.instrument_file,
                  "Instrument parameters (JSON); default built in");
  cmd->add_option("--threads", a.threads, "Threads (0: one per core); results do not depend on it")
      ->capture_default_str();
  cmd->add_flag("--json", a.json, "Print the results as JSON instead of tables");
  cmd->add_flag("-q,--quiet", a.quiet, "Print nothing on success");
}

namespace {

// The experiment's fields and the flags of paper (and demo) that set them.
const FlagTable kPaperFlags = {{"seeds", "--seeds"},
                               {"methods", "--methods"},
                               {"population", "--population"},
                               {"iterations", "--iterations"},
                               {"epsilon", "--epsilon"},
                               {"cv.folds", "--folds"},
                               {"cv.scheme", "--cv"},
                               {"calibration.temps_degc", "--cal-temps"},
                               {"calibration.repetitions", "--repetitions"},
                               {"calibration.approaches", "--cal-approaches"},
                               {"northfind.temps_degc", "--nf-temps"},
                               {"northfind.findings", "--findings"}};

void run_paper_unnamed(const PaperArgs& a);

}  // namespace

const report::PaperOptions& paper_defaults() {
  static const report::PaperOptions defaults;
  return defaults;
}

std::string method_list(const std::vector<Method>& methods) {
  std::vector<std::string> names;
  for (const Method m : methods) names.push_back(to_string(m));
  return fmt::format("{}", fmt::join(names, ","));
}

std::string approach_list(const std::vector<sim::Approach>& approaches) {
  std::vector<std::string_view> names;
  for (sim::Approach a : approaches) names.push_back(sim::to_string(a));
  return fmt::format("{}", fmt::join(names, ","));
}

void run_paper_command(const PaperArgs& a) {
  with_flags(kPaperFlags, [&] { run_paper_unnamed(a); });
}

namespace {

void run_paper_unnamed(const PaperArgs& a) {
  report::PaperOptions o;
  o.seeds = a.seeds;
  o.methods.clear();
  for (const std::string& m : split_list(a.methods))
    o.methods.push_back(parse_method(m, "--methods"));
  o.first_seed = a.first_seed;
  o.population = a.population;
  o.iterations = a.iterations;
  o.fitness = tune::parse_fitness(a.fitness, "--fitness");
  o.cv.scheme = tune::parse_cv_scheme(a.cv, "--cv");
  o.cv.folds = a.folds;
  o.northfind.approach = sim::approach_from_string(a.approach, "--approach");
  o.calibration.approaches = sim::approaches_from_string(a.cal_approaches, "--cal-approaches");
  o.calibration.repetitions = a.repetitions;
  o.start_ups = a.start_ups == "none" ? std::vector<sim::Approach>{}
                                      : sim::approaches_from_string(a.start_ups, "--start-ups");
  o.studies = !a.no_studies;
  o.epsilon = a.epsilon;
  o.search_epsilon = a.search_epsilon;
  if (!a.cal_temps.empty())
    o.calibration.temps_degc = parse_number_list(a.cal_temps, "--cal-temps");
  if (!a.nf_temps.empty()) o.northfind.temps_degc = parse_number_list(a.nf_temps, "--nf-temps");
  o.northfind.findings = a.findings;
  if (!a.instrument_file.empty())
    o.instrument = sim::instrument_from_json(read_text_file(a.instrument_file), a.instrument_file);
  if (!a.out.empty()) {
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
    const std::string gnuplot = report::find_gnuplot();
    fill_directory_atomically(a.out, a.force, [&](const std::filesystem::path& dir) {
      write_text_atomically(dir / "report.md", markdown);
      write_text_atomically(dir / "paper.json", json);
      for (const report::Figure& f : result.figures) {
        write_text_atomically(dir / (f.name + ".json"), report::to_json(f));
        const std::string problem = report::render_png(f, dir, gnuplot);
        if (!problem.empty()) figure_problems.push_back(problem);
      }
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
