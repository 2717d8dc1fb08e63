// Subcommands of the fogdrift tool. Each file adds one subcommand to the app; the library does
// the work, the command decides what to print.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "fogdrift/report/paper.hpp"

namespace fogdrift::app {

/// The whole command set on `app`: description, --version and every subcommand below.
void add_commands(CLI::App& app);

void add_simulate(CLI::App& app);
void add_inspect(CLI::App& app);
void add_import(CLI::App& app);
void add_join(CLI::App& app);
void add_campaign(CLI::App& app);
void add_denoise(CLI::App& app);
void add_demo(CLI::App& app);
void add_svr(CLI::App& app);
void add_train(CLI::App& app);
void add_options(CLI::App& app);
void add_evaluate(CLI::App& app);
void add_compensate(CLI::App& app);
void add_export_c(CLI::App& app);
void add_northfind(CLI::App& app);
void add_paper(CLI::App& app);
void add_stream(CLI::App& app);

/// The experiment's defaults, which paper's flags take as theirs.
const report::PaperOptions& paper_defaults();
/// "a,b,c" of approaches.
std::string approach_list(const std::vector<sim::Approach>& approaches);
/// "a,b,c" of methods.
std::string method_list(const std::vector<Method>& methods);

/// fogdrift paper's options; fogdrift demo runs the same command with a smaller budget.
struct PaperArgs {
  std::string out;
  bool force = false;
  std::size_t seeds = paper_defaults().seeds;
  std::string methods = method_list(paper_defaults().methods);
  std::uint64_t first_seed = paper_defaults().first_seed;
  std::size_t population = paper_defaults().population;
  std::size_t iterations = paper_defaults().iterations;
  std::string fitness = tune::to_string(paper_defaults().fitness);
  std::string cv = tune::to_string(paper_defaults().cv.scheme);
  std::size_t folds = paper_defaults().cv.folds;
  double epsilon = paper_defaults().epsilon;
  bool search_epsilon = paper_defaults().search_epsilon;
  std::string approach = std::string(sim::to_string(paper_defaults().northfind.approach));
  std::string cal_approaches = approach_list(paper_defaults().calibration.approaches);
  std::string start_ups = approach_list(paper_defaults().start_ups);
  int repetitions = paper_defaults().calibration.repetitions;
  std::string cal_temps;  ///< empty: the paper's −40 … 60 °C
  std::string nf_temps;   ///< empty: the paper's seven
  int findings = paper_defaults().northfind.findings;
  bool no_studies = !paper_defaults().studies;
  std::string instrument_file;
  unsigned threads = 0;
  bool json = false;
  bool quiet = false;
};
void add_paper_options(CLI::App* cmd, PaperArgs& args);
void run_paper_command(const PaperArgs& args);

}  // namespace fogdrift::app
