// The fogdrift command set: the description, the version flag and every subcommand, shared by
// the tool's main() and the command-line fuzz target (tests/fuzz/cli_args.cpp); and the tool's
// run, which main() calls.
#include "app.hpp"

#include <CLI/CLI.hpp>
#include <csignal>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/version.hpp"
#include "fogdrift/svr/svr.hpp"

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

int run(int argc, char** argv) {
  // Before any thread starts: inputs noted so that no output replaces one, closed standard
  // descriptors kept closed for outputs, and SIGINT, SIGTERM, SIGHUP removing the run's
  // temporaries (docs/reliability.md, "Outputs").
  begin_guarded_run();
  // Over the file-size limit (ulimit -f) a write fails with EFBIG instead of killing the process
  // with SIGXFSZ, so the atomic writer removes its temporary and says why (docs/reliability.md).
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app;
  add_commands(app);
  // A bad FOGDRIFT_ISA is reported before any command starts work, and --help still works.
  app.parse_complete_callback([] { svr::instruction_set(); });
  try {
    app.parse(argc, argv);
    check_standard_output();
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const InputError& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  } catch (const OptionError& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // An allocation the up-front memory checks did not foresee (docs/reliability.md).
    std::cerr << "fogdrift: error: out of memory: this machine, or its limit (ulimit -v, a "
                 "container), has less memory than the run needs; fewer threads, a smaller "
                 "kernel cache or fewer rows would need less (train: --threads, --cache-mb)\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace fogdrift::app
