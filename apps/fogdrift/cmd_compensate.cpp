// fogdrift compensate: subtract a model's predicted drift from a recording (docs/method.md §2 step
// 5).
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/eval/metrics.hpp"
#include "fogdrift/model/compensate_file.hpp"
#include "fogdrift/model/compensate_option_table.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct CompensateArgs {
  ModelLoadOptions load;
  std::string model;
  std::string input;
  std::string output;
  bool json = false;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;  ///< compensate's options (compensate_option_table.hpp)
};

/// One axis compensated, with its STD before and after, as evaluate computes them.
struct Axis : CompensatedAxis {
  eval::CompensationMetrics metrics;
};

nlohmann::ordered_json axis_json(const CompensateOptions& options, const Axis& x) {
  nlohmann::ordered_json j;
  const std::vector<double>& drift = x.prediction.drift_dph;
  // Keys in the target's unit: gyro_std_dph, accel_std_g, sf_std_ppm (target.hpp).
  const std::string& column = x.model->dataset.target_column;
  const std::string kind = column.substr(0, column.find('_'));
  const std::string_view unit = target_of(column).unit();
  j["method"] = x.model->provenance.method;
  j["samples"] = drift.size();
  j[fmt::format("{}_std_{}", kind, unit)] = x.metrics.std_before_dph;
  j[fmt::format("{}_comp_std_{}", kind, unit)] = x.metrics.std_after_dph;
  j[fmt::format("drift_first_{}", unit)] = drift.front();
  j[fmt::format("drift_last_{}", unit)] = drift.back();
  j["guard"] = options.guarded;
  j["novelty_outside_share"] =
      static_cast<double>(x.novelty.outside) / static_cast<double>(x.novelty.samples);
  j["novelty_reduced_share"] =
      static_cast<double>(x.novelty.reduced) / static_cast<double>(x.novelty.samples);
  j["novelty_max"] = std::isnan(x.novelty.max_novelty)
                         ? nlohmann::ordered_json(nullptr)
                         : nlohmann::ordered_json(x.novelty.max_novelty);
  return j;
}

void run(const CompensateArgs& a) {
  const ModelSet set = load_model_set(a.model, a.load);
  note_input(a.input);
  check_output_not_input(a.output, "--output");
  CompensateOptions options;
  a.flags->apply(compensate_option_table(), options);
  std::vector<Axis> axes;
  for (CompensatedAxis& c : compensate_file(set, a.input, a.output, options)) {
    const eval::CompensationMetrics metrics =
        eval::compensation_metrics(c.reading, c.prediction.drift_dph);
    axes.push_back({std::move(c), metrics});
  }

  if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.model;
    if (axes.size() == 1) {
      j["method"] = axes[0].model->provenance.method;
      j["input"] = a.input;
      j["output"] = a.output;
      const nlohmann::ordered_json axis = axis_json(options, axes[0]);
      for (const auto& [k, v] : axis.items())
        if (k != "method") j[k] = v;
    } else {
      j["input"] = a.input;
      j["output"] = a.output;
      j["axes"] = nlohmann::ordered_json::array();
      for (const Axis& x : axes) {
        nlohmann::ordered_json one;
        one["target"] = x.model->dataset.target_column;
        one.update(axis_json(options, x));
        j["axes"].push_back(one);
      }
    }
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    for (const Axis& x : axes) {
      const std::vector<double>& drift = x.prediction.drift_dph;
      const Target target = target_of(x.model->dataset.target_column);
      std::cout << fmt::format(
          "{}: {} samples{} compensated with {} ({})\n"
          "  predicted drift {} → {} {} from first to last sample\n"
          "  {} STD {} {}, compensated {} {} (sample rate, noise included)\n"
          "  {}{}\n",
          a.input, drift.size(),
          axes.size() > 1 || target.column != "gyro_dph" ? " of " + target.column : std::string(),
          a.model, x.model->provenance.method, target.format(drift.front()),
          target.format(drift.back()), target.symbol(), target.what(),
          target.format(x.metrics.std_before_dph), target.symbol(),
          target.format(x.metrics.std_after_dph), target.symbol(), x.novelty.line(),
          !options.guarded ? " (guard off: full correction everywhere)" : "");
    }
    std::cout << fmt::format("  wrote {}\n", a.output);
  }
}

}  // namespace

void add_compensate(CLI::App& app) {
  auto args = std::make_shared<CompensateArgs>();
  auto* cmd = app.add_subcommand(
      "compensate",
      "Subtract a compensation model's predicted drift from a recording. Every column of IN is\n"
      "written back as read, followed by drift_dph (the predicted drift, °/h) and gyro_comp_dph\n"
      "(gyro_dph − drift_dph), novelty (how far the sample's inputs lie outside the region the\n"
      "model was trained on: ≤ 1 inside) and guard_weight (the share of the correction applied).\n"
      "Where novelty exceeds the model's full_at the correction is reduced, to none at zero_at, "
      "so\n"
      "that a model that is extrapolating cannot make a start-up worse than uncompensated\n"
      "(docs/field.md); --no-guard applies it in full. The features are computed at the\n"
      "recording's own rate with the model's differentiator: one output row per input row.\n"
      "A model of another axis or target adds its own columns: drift_y_dph, gyro_y_comp_dph,\n"
      "novelty_y, guard_weight_y for gyro_y_dph; drift_accel_x_g, accel_x_comp_g, ... for an\n"
      "accelerometer (docs/logs.md, \"Other targets\").\n"
      "Example:\n"
      "  fogdrift train cal -o model.json && fogdrift compensate model.json cal/cal_r4_20C.csv "
      "-o comp.csv");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  add_model_load_flags(cmd, &args->load);
  cmd->add_option("input", args->input, "Recording CSV")->required();
  cmd->add_option("-o,--output", args->output, "CSV to write (atomically)")->required();
  cmd->add_flag("--json", args->json, "Print a summary as JSON");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  const auto& table = compensate_option_table();
  args->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
