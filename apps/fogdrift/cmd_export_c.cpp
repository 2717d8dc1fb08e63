// fogdrift export-c: a compensation model as a self-contained C99 header for firmware.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fault_options.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/model/model.hpp"

namespace fogdrift::app {
namespace {

struct ExportArgs {
  ModelLoadOptions load;
  std::string model;
  std::optional<std::string> target;  ///< the axis of a model set
  std::string output;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;  ///< export-c's options (export_option_table.hpp)
};

// The temperature arguments of PREFIX_update, as the summary names them: temp_fog, temp_acc1,
// temp_acc2, then each further thermometer a model reads (docs/logs.md, "More thermometers").
std::string temperature_arguments(const ModelSet& set) {
  std::vector<std::string> names = set.thermometer_columns();
  for (std::string& name : names) name.resize(name.size() - 5);  // temp_NAME without _degc
  return fmt::format("{}", fmt::join(names, ", "));
}

void run(const ExportArgs& a) {
  // One axis (--target, or a model of one), or every axis of a model set in one header.
  const ModelSet set = axes_to_run(load_model_set(a.model, a.load), a.target);
  const CompensationModel& model = set.models.front();
  check_output_not_input(a.output, "--output");
  const ExportOptions o = export_options(*a.flags, model);
  const bool single = o.precision == CPrecision::single;
  const char* precision = single ? "float" : "double";
  std::string header;
  try {
    header = to_c_header(set, o.prefix, o.stream_rate_hz > 0 ? 1.0 / o.stream_rate_hz : 0.0,
                         o.faults, o.precision);
  } catch (const OptionError& e) {
    if (e.option() == "prefix")
      throw OptionError("--prefix", e.message() +
                                        " (letters, digits and '_', starting with a "
                                        "letter)");
    if (e.option() == "targets")
      throw InputError(a.model, 0, 0,
                       fmt::format("cannot be a C header: {}; train it again with other target "
                                   "columns",
                                   e.message()));
    throw OptionError("--stream-rate-hz", e.message());
  }
  // A float header must compute what the model computes (c_header.hpp, FloatPrecisionCheck).
  if (single) {
    for (const CompensationModel& m : set.models) {
      const FloatPrecisionCheck check = check_float_precision(m);
      if (check.share() <= kFloatShareLimit) continue;
      const std::string what = fmt::format(
          "in float, {}'s drift departs from the model's by up to {:.3g} {} on its own training "
          "inputs ({} compared), {:.3g} of the drift's STD (the limit is {:g}): float keeps too "
          "few digits of these inputs (docs/firmware.md, \"Float\")",
          m.dataset.target_column, check.max_error, target_of(m.dataset.target_column).unit(),
          check.inputs, check.share(), kFloatShareLimit);
      if (!o.force_float)
        throw OptionError("--precision",
                          what + "; use --precision double, or --force-float to write it anyway");
      std::cerr << "fogdrift export-c: warning: " << what << "; written anyway (--force-float)\n";
    }
  }
  write_text_atomically(a.output, header);
  // What the header cannot do as fogdrift does is said on standard error, not only in it.
  if (o.stream_rate_hz > 0)
    for (const CompensationModel& m : set.models)
      if (m.dataset.preprocessing.rates.causality != signal::Causality::causal)
        std::cerr << fmt::format(
            "fogdrift export-c: warning: {} ({}) was trained with centred temperature rates; the "
            "header's update computes causal ones, so its drift differs from compensate's (train "
            "with --differentiator causal for firmware)\n",
            a.model, m.dataset.target_column);
  if (!a.quiet && set.models.size() > 1) {
    std::cout << fmt::format(
        "wrote {}: {} axes ({}) of {}, C99 in {}, no heap; each axis's model as "
        "{}_AXIS_predict_UNIT(features){}\n",
        a.output, set.models.size(), fmt::join(set.targets(), ", "), a.model, precision, o.prefix,
        o.stream_rate_hz > 0
            ? fmt::format(", and {}_update(&state, time_s, {}, drift[{}]) for all of them at {} Hz",
                          o.prefix, temperature_arguments(set), set.models.size(), o.stream_rate_hz)
            : std::string());
  } else if (!a.quiet) {
    std::cout << fmt::format(
        "wrote {}: {}_predict_{}(features[{}]) for {} ({}), C99 in {}, no heap\n", a.output,
        o.prefix, target_of(model.dataset.target_column).unit(), model.inputs(), a.model,
        model.provenance.method, precision);
    const std::size_t block = o.stream_rate_hz > 0
                                  ? decimation_factor(model.dataset.preprocessing,
                                                      1.0 / o.stream_rate_hz, "--stream-rate-hz")
                                  : 1;
    if (o.stream_rate_hz > 0)
      std::cout << fmt::format(
          "  and {0}_update(&state, time_s, {6}) "
          "at {1} Hz{5}, causal{2}, with the sensor-fault policy (--bridge-s {3}, --hold-s {4})\n",
          o.prefix, o.stream_rate_hz,
          model.dataset.preprocessing.rates.causality == signal::Causality::causal
              ? ""
              : " (the model was trained with centred rates: train with "
                "--differentiator causal for firmware)",
          o.faults.bridge_s, o.faults.hold_s,
          block > 1 ? fmt::format(" (the model once per {} samples, its {:.6g} s interval)", block,
                                  model.dataset.preprocessing.sample_interval_s)
                    : std::string(),
          temperature_arguments(set));
    if (!model.guard.empty())
      std::cout << fmt::format(
          "  and {}_novelty(features): {} guard prototypes, correction "
          "reduced from novelty {} to none at {}\n",
          o.prefix, model.guard.size(), model.guard.settings.full_at, model.guard.settings.zero_at);
  }
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
      "With --stream-rate-hz the header also computes the features itself, causally, from one\n"
      "sample (time, its temperatures) at a time: PREFIX_update(&state, ...), the streaming\n"
      "compensator in C; train the model with --differentiator causal for it. It runs the\n"
      "sensor-fault policy of fogdrift stream (docs/compensation.md), with the settings below as\n"
      "macros the firmware may redefine; PREFIX_compensated_dph(&state, gyro) and state.flags.\n"
      "A model with a novelty guard (docs/field.md) also gets PREFIX_novelty(features) and\n"
      "PREFIX_target_weight(nu); PREFIX_update then reduces the correction where the inputs are\n"
      "novel, as fogdrift stream does (#define PREFIX_GUARD 0 before the #include: full).\n"
      "Examples:\n"
      "  fogdrift export-c model.json -o unit42.h --prefix unit42   # unit42_predict_dph(...)\n"
      "  fogdrift export-c causal.json -o unit42.h --stream-rate-hz 1  # and unit42_update(...)\n"
      "  fogdrift export-c causal.json -o unit42.h --stream-rate-hz 100 --precision float\n"
      "      # a 1 Hz model on a 100 Hz logger, in float for a Cortex-M4F");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  add_model_load_flags(cmd, &args->load);
  cmd->add_option("-o,--output", args->output, "Header to write (atomically)")->required();
  cmd->add_option("--target", args->target,
                  "With a model of several axes (train --targets): export this one alone, e.g. "
                  "gyro_y_dph (default: every axis in one header, with one update for all)");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  args->flags = add_export_options(cmd);
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
