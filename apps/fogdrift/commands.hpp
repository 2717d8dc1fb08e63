// Subcommands of the fogdrift tool. Each file adds one subcommand to the app; the library does
// the work, the command decides what to print.
#pragma once

#include <CLI/CLI.hpp>

namespace fogdrift::app {

void add_simulate(CLI::App& app);
void add_inspect(CLI::App& app);
void add_import(CLI::App& app);
void add_denoise(CLI::App& app);
void add_demo(CLI::App& app);
void add_svr(CLI::App& app);
void add_train(CLI::App& app);
void add_evaluate(CLI::App& app);
void add_compensate(CLI::App& app);
void add_export_c(CLI::App& app);
void add_northfind(CLI::App& app);

}  // namespace fogdrift::app
