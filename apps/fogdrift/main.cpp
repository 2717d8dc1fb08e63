// fogdrift: start-up temperature-drift compensation for fiber-optic gyroscopes.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "commands.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/version.hpp"

int main(int argc, char** argv) {
  CLI::App app{
      "fogdrift removes the start-up temperature drift of fiber-optic gyroscopes (FOGs) using the\n"
      "instrument's own thermometers (wavelet denoising, temperature features, ε-SVR tuned by\n"
      "sparrow search). Start with 'fogdrift demo', or 'fogdrift SUBCOMMAND --help'.\n\n"
      "Exit status: 0 success; 1 bad input file or option value (the message names the file,\n"
      "line and column, or the option, and the rule broken); 105-115 command-line usage errors."};
  app.set_version_flag("--version", std::string("fogdrift ") + fogdrift::kVersion);
  app.require_subcommand(1);
  app.fallthrough(false);
  fogdrift::app::add_simulate(app);
  fogdrift::app::add_inspect(app);
  fogdrift::app::add_import(app);
  fogdrift::app::add_campaign(app);
  fogdrift::app::add_denoise(app);
  fogdrift::app::add_svr(app);
  fogdrift::app::add_train(app);
  fogdrift::app::add_evaluate(app);
  fogdrift::app::add_compensate(app);
  fogdrift::app::add_stream(app);
  fogdrift::app::add_export_c(app);
  fogdrift::app::add_northfind(app);
  fogdrift::app::add_paper(app);
  fogdrift::app::add_demo(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const fogdrift::InputError& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  } catch (const fogdrift::OptionError& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fogdrift: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
