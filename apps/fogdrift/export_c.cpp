// fogdrift export-c: a compensation model as a self-contained C99 header for firmware.
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "commands.hpp"
#include "fogdrift/atomic_file.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/model.hpp"

namespace fogdrift::app {
namespace {

struct ExportArgs {
  std::string model;
  std::string output;
  std::string prefix = "fogdrift_model";
  bool quiet = false;
};

void run(const ExportArgs& a) {
  const CompensationModel model = load_compensation_model(a.model);
  std::string header;
  try {
    header = to_c_header(model, a.prefix);
  } catch (const OptionError& e) {
    throw OptionError("--prefix", fmt::format("'{}' is not a C identifier (letters, digits and "
                                              "'_', not starting with a digit)",
                                              a.prefix));
  }
  write_text_atomically(a.output, header);
  if (!a.quiet)
    std::cout << fmt::format("wrote {}: {}_predict_dph(features[{}]) for {} ({}), C99, no heap\n",
                             a.output, a.prefix, model.inputs(), a.model,
                             to_string(model.provenance.method));
}

}  // namespace

void add_export_c(CLI::App& app) {
  auto args = std::make_shared<ExportArgs>();
  auto* cmd = app.add_subcommand(
      "export-c",
      "Write a compensation model as a self-contained C99 header for an instrument's processor:\n"
      "the scalers and the regressor (support vectors, network weights or polynomial) as static\n"
      "const tables with every double to 17 digits, and an inline PREFIX_predict_dph(features)\n"
      "that needs only <math.h>, no heap and no state. The header's comment lists the features\n"
      "in order with their units; compute them as fogdrift does (docs/signal.md).\n"
      "Example:\n"
      "  fogdrift export-c model.json -o unit42.h --prefix unit42   # unit42_predict_dph(...)");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  cmd->add_option("-o,--output", args->output, "Header to write (atomically)")->required();
  cmd->add_option("--prefix", args->prefix, "C name prefix of every symbol")->capture_default_str();
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->callback([args] { run(*args); });
}

}  // namespace fogdrift::app
