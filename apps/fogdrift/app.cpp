// The fogdrift command set: the description, the version flag and every subcommand, shared by
// the tool's main() and the command-line fuzz target (tests/fuzz/cli_args.cpp).
#include <CLI/CLI.hpp>
#include <string>

#include "commands.hpp"
#include "fogdrift/base/version.hpp"

namespace fogdrift::app {

void add_commands(CLI::App& app) {
  app.description(
      "fogdrift removes the start-up temperature drift of fiber-optic gyroscopes (FOGs) using the\n"
      "instrument's own thermometers (wavelet denoising, temperature features, ε-SVR tuned by\n"
      "sparrow search). Start with 'fogdrift demo', or 'fogdrift SUBCOMMAND --help'.\n\n"
      "Exit status: 0 success; 1 bad input file or option value (the message names the file,\n"
      "line and column, or the option, and the rule broken); 105-115 command-line usage errors.\n\n"
      "Environment: FOGDRIFT_ISA=portable|avx2|avx512 runs the SVR engine on that instruction\n"
      "set instead of the fastest the processor has; every one gives the same model, bit for bit.");
  app.set_version_flag("--version", std::string("fogdrift ") + kVersion);
  app.require_subcommand(1);
  app.fallthrough(false);
  add_simulate(app);
  add_plan(app);
  add_inspect(app);
  add_import(app);
  add_join(app);
  add_campaign(app);
  add_denoise(app);
  add_svr(app);
  add_train(app);
  add_options(app);
  add_evaluate(app);
  add_compensate(app);
  add_stream(app);
  add_export_c(app);
  add_northfind(app);
  add_paper(app);
  add_demo(app);
}

}  // namespace fogdrift::app
