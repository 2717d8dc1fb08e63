// fogdrift: start-up temperature-drift compensation for fiber-optic gyroscopes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <csignal>
#include <exception>
#include <iostream>
#include <new>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/svr/svr.hpp"

int main(int argc, char** argv) {
  // Before any thread starts: inputs noted so that no output replaces one, closed standard
  // descriptors kept closed for outputs, and SIGINT, SIGTERM, SIGHUP removing the run's
  // temporaries (docs/reliability.md, "Outputs").
  fogdrift::begin_guarded_run();
  // Over the file-size limit (ulimit -f) a write fails with EFBIG instead of killing the process
  // with SIGXFSZ, so the atomic writer removes its temporary and says why (docs/reliability.md).
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app;
  fogdrift::app::add_commands(app);
  // A bad FOGDRIFT_ISA is reported before any command starts work, and --help still works.
  app.parse_complete_callback([] { fogdrift::svr::instruction_set(); });
  try {
    app.parse(argc, argv);
    fogdrift::app::check_standard_output();
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const fogdrift::InputError& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  } catch (const fogdrift::OptionError& e) {
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
