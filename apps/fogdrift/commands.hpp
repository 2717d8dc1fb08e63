// Subcommands of the fogdrift tool. Each file adds one subcommand to the app; the library does
// the work, the command decides what to print.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace fogdrift::app {

void add_simulate(CLI::App& app);
void add_inspect(CLI::App& app);
void add_import(CLI::App& app);
void add_campaign(CLI::App& app);
void add_denoise(CLI::App& app);
void add_demo(CLI::App& app);
void add_svr(CLI::App& app);
void add_train(CLI::App& app);
void add_evaluate(CLI::App& app);
void add_compensate(CLI::App& app);
void add_export_c(CLI::App& app);
void add_northfind(CLI::App& app);
void add_paper(CLI::App& app);
void add_stream(CLI::App& app);

/// fogdrift paper's options; fogdrift demo runs the same command with a smaller budget.
struct PaperArgs {
  std::string out;
  bool force = false;
  std::size_t seeds = 5;
  std::uint64_t first_seed = 1;
  std::size_t population = 10;
  std::size_t iterations = 20;
  std::string fitness = "cv";
  std::string cv = "temperature";
  std::size_t folds = 3;
  double epsilon = 0.05;
  bool search_epsilon = false;
  std::string approach = "calibration";
  std::string cal_approaches = "calibration,soaked,warm,ramping";
  std::string start_ups = "calibration,soaked,warm,ramping";
  int repetitions = 5;
  std::string cal_temps;  ///< empty: the paper's −40 … 60 °C
  std::string nf_temps;   ///< empty: the paper's seven
  int findings = 5;
  bool no_studies = false;
  std::string instrument_file;
  unsigned threads = 0;
  bool json = false;
  bool quiet = false;
};
void add_paper_options(CLI::App* cmd, PaperArgs& args);
void run_paper_command(const PaperArgs& args);

}  // namespace fogdrift::app
