// Subcommands of the fogdrift tool. Each file adds one subcommand to the app; the library does
// the work, the command decides what to print.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
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
void add_plan(CLI::App& app);

class OptionFlags;

/// fogdrift paper's own flags; the experiment's options are the flags of
/// report::paper_option_table(), shown with `defaults`. fogdrift demo runs the same command with
/// its own defaults.
struct PaperArgs {
  std::string out;
  bool force = false;
  std::string instrument_file;
  unsigned threads = 0;
  bool json = false;
  bool quiet = false;
  report::PaperOptions defaults;         ///< what the flags given change
  std::shared_ptr<OptionFlags> options;  ///< the experiment's flags (paper_option_table.hpp)
};
void add_paper_options(CLI::App* cmd, PaperArgs& args);
void run_paper_command(const PaperArgs& args);

}  // namespace fogdrift::app
