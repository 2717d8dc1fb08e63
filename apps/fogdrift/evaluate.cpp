// fogdrift evaluate: the paper's Table 2 view of a compensation model on test recordings.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/campaign.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/eval/allan.hpp"
#include "fogdrift/eval/metrics.hpp"
#include "fogdrift/features.hpp"
#include "fogdrift/model.hpp"

namespace fogdrift::app {
namespace {

struct EvaluateArgs {
  bool allow_edited = false;
  std::string model;
  std::vector<std::string> inputs;
  bool json = false;
  bool allan = false;
  bool no_guard = false;
};

// Datasheet noise terms of a recording's gyro output before and after compensation, from the
// overlapping Allan deviation at the recording's own rate.
struct AllanRow {
  eval::NoiseTerms raw, compensated;
};

AllanRow allan_row(const CompensationModel& model, const Recording& rec, bool guarded) {
  const double dt = sample_interval_s(rec);
  const std::vector<double> drift = model.predict_dph(rec, guarded);
  std::vector<double> comp(rec.gyro_dph.size());
  for (std::size_t i = 0; i < comp.size(); ++i) comp[i] = rec.gyro_dph[i] - drift[i];
  return {eval::noise_terms(eval::allan_deviation(rec.gyro_dph, dt, 10)),
          eval::noise_terms(eval::allan_deviation(comp, dt, 10))};
}

bool is_campaign(const std::string& path) {
  return std::filesystem::is_directory(path) || path.ends_with(".json");
}

void run(const EvaluateArgs& a) {
  const CompensationModel model = load_compensation_model(a.model, {a.allow_edited});
  Dataset data;
  std::string source;
  std::vector<RecordingInput> inputs;
  bool simulated = false;  // a campaign fogdrift simulate wrote
  if (a.inputs.size() == 1 && is_campaign(a.inputs[0])) {
    const Campaign campaign = read_campaign(a.inputs[0]);
    simulated = campaign.generator_json.find("\"fogdrift simulate\"") != std::string::npos;
    inputs = read_inputs(campaign, Role::test, Scenario::calibration);
    data = build_dataset(inputs, model.dataset);
    source = a.inputs[0] + " (recordings with role \"test\")";
  } else {
    for (const auto& path : a.inputs) {
      if (is_campaign(path))
        throw OptionError("inputs", fmt::format("{} is a campaign; give one campaign or recording "
                                                "files, not both",
                                                path));
      RecordingInput in;
      in.recording = read_recording(path);
      in.info.file = path;
      inputs.push_back(std::move(in));
    }
    data = build_dataset(inputs, model.dataset);
    source = fmt::format("{} recording file{}", inputs.size(), inputs.size() == 1 ? "" : "s");
  }
  if (data.feature_names != model.feature_names)
    throw InputError(
        a.model, 0, 0,
        fmt::format("features: the model's features ({}) differ from those its "
                    "feature spec gives for this data ({})",
                    fmt::join(model.feature_names, ","), fmt::join(data.feature_names, ",")));
  const bool guarded = !a.no_guard;
  const std::vector<eval::CompensationMetrics> per =
      eval::metrics_per_recording(data, model.predict_dph(data, guarded));
  const eval::CompensationMetrics all = eval::pool(per);
  const std::string method = to_string(model.provenance.method);
  std::vector<AllanRow> allan;
  if (a.allan)
    for (const auto& in : inputs) allan.push_back(allan_row(model, in.recording, guarded));
  // The guard's view of each recording at its own rate, as compensate and stream see it.
  std::vector<NoveltySummary> novelty;
  for (const auto& in : inputs) {
    const RecordingPrediction p = model.predict(in.recording, guarded);
    novelty.push_back(summarize_novelty(p.novelty, p.weight));
  }
  auto terms_json = [](const eval::NoiseTerms& t) {
    return nlohmann::ordered_json{{"arw_deg_per_rt_h", t.arw_deg_per_rt_h},
                                  {"bias_instability_dph", t.bias_instability_dph},
                                  {"rrw_dph_per_rt_h", t.rrw_dph_per_rt_h}};
  };

  if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.model;
    j["method"] = method;
    j["source"] = source;
    // The metrics of one recording or of all, under the same names.
    auto metrics_json = [](const eval::CompensationMetrics& m) {
      return nlohmann::ordered_json{{"rows", m.rows},
                                    {"mae_dph", m.mae_dph},
                                    {"mae_before_dph", m.mae_before_dph},
                                    {"rmse_dph", m.rmse_dph},
                                    {"std_denoised_dph", m.std_before_dph},
                                    {"std_compensated_dph", m.std_after_dph},
                                    {"pooled_std_denoised_dph", m.pooled_std_before_dph},
                                    {"pooled_std_compensated_dph", m.pooled_std_after_dph},
                                    {"startup_residual_before_dph", m.startup_before_dph},
                                    {"startup_residual_after_dph", m.startup_after_dph},
                                    {"opposite_difference_before_dph", m.opposite_before_dph},
                                    {"opposite_difference_after_dph", m.opposite_after_dph}};
    };
    j["overall"] = metrics_json(all);
    j["guard"] = guarded;
    for (std::size_t g = 0; g < per.size(); ++g) {
      nlohmann::ordered_json r = {{"file", data.groups[g].file},
                                  {"initial_temp_degc", data.groups[g].initial_temp_degc},
                                  {"repetition", data.groups[g].repetition}};
      r.update(metrics_json(per[g]));
      const double n = static_cast<double>(std::max<std::size_t>(1, novelty[g].samples));
      r["novelty_outside_share"] = static_cast<double>(novelty[g].outside) / n;
      r["novelty_reduced_share"] = static_cast<double>(novelty[g].reduced) / n;
      j["recordings"].push_back(r);
      if (a.allan)
        j["recordings"].back()["allan"] = {{"raw", terms_json(allan[g].raw)},
                                           {"compensated", terms_json(allan[g].compensated)}};
    }
    j["warnings"] = data.warnings;
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("{} on {}: {} rows of {} recording{}\n\n", method, source, data.rows,
                           data.groups.size(), data.groups.size() == 1 ? "" : "s");
  std::cout << "Before (the denoised drift) → after compensation, °/h:\n"
               "| recording | T0 (°C) | MAE | STD |\n"
               "|---|---|---|---|\n";
  for (std::size_t g = 0; g < per.size(); ++g)
    std::cout << fmt::format("| {} | {:g} | {:.4f} → {:.4f} | {:.4f} → {:.4f} |\n",
                             data.groups[g].file, data.groups[g].initial_temp_degc,
                             per[g].mae_before_dph, per[g].mae_dph, per[g].std_before_dph,
                             per[g].std_after_dph);
  std::cout << fmt::format("| **all** | | **{:.4f} → {:.4f}** | **{:.4f} → {:.4f}** |\n",
                           all.mae_before_dph, all.mae_dph, all.std_before_dph, all.std_after_dph);
  if (per.size() > 1)
    std::cout << fmt::format(
        "(all: STD is the RMS of the recordings' STDs, as Table 2; pooled over every row, offsets "
        "between recordings kept: {:.4f} → {:.4f})\n",
        all.pooled_std_before_dph, all.pooled_std_after_dph);
  // The paper's figures belong beside the paper's instrument, the simulator, not a user's data.
  if (simulated)
    std::cout << fmt::format(
        "\nTable 2 view: denoised STD {:.4f} °/h, {} STD {:.4f} °/h, MAE {:.4f} °/h "
        "(paper: denoised 0.0134; SSA-SVR 0.0031, MAE 0.0025)\n",
        all.std_before_dph, method, all.std_after_dph, all.mae_dph);
  std::cout << "\nWhere north-finding needs it (docs/field.md), before → after, °/h:\n"
               "| recording | first 5 min residual | opposite positions 180 s apart | guard |\n"
               "|---|---|---|---|\n";
  for (std::size_t g = 0; g < per.size(); ++g)
    std::cout << fmt::format(
        "| {} | {:.4f} → {:.4f} | {:.4f} → {:.4f} | {} |\n", data.groups[g].file,
        per[g].startup_before_dph, per[g].startup_after_dph, per[g].opposite_before_dph,
        per[g].opposite_after_dph, g < novelty.size() ? novelty[g].line().substr(9) : "");
  std::cout << fmt::format("| **all** | **{:.4f} → {:.4f}** | **{:.4f} → {:.4f}** | {} |\n",
                           all.startup_before_dph, all.startup_after_dph, all.opposite_before_dph,
                           all.opposite_after_dph, guarded ? "on" : "off (--no-guard)");
  if (a.allan) {
    std::cout
        << "\nAllan deviation of the gyro output at the recording's rate, raw → compensated:\n"
           "| recording | ARW (°/√h) | bias instability (°/h) | RRW (°/h/√h) |\n"
           "|---|---|---|---|\n";
    for (std::size_t g = 0; g < allan.size(); ++g) {
      const auto& r = allan[g].raw;
      const auto& c = allan[g].compensated;
      std::cout << fmt::format("| {} | {:.5f} → {:.5f} | {:.4f} → {:.4f} | {:.4f} → {:.4f} |\n",
                               data.groups[g].file, r.arw_deg_per_rt_h, c.arw_deg_per_rt_h,
                               r.bias_instability_dph, c.bias_instability_dph, r.rrw_dph_per_rt_h,
                               c.rrw_dph_per_rt_h);
    }
    double shortest = std::numeric_limits<double>::infinity(), longest = 0;
    for (const auto& in : inputs) {
      const double d = in.recording.time_s.back() - in.recording.time_s.front();
      shortest = std::min(shortest, d);
      longest = std::max(longest, d);
    }
    const std::string span =
        std::lround(shortest / 60) == std::lround(longest / 60)
            ? fmt::format("{:.0f}-minute", shortest / 60)
            : fmt::format("{:.0f}- to {:.0f}-minute", shortest / 60, longest / 60);
    std::cout << fmt::format(
        "({} recordings read bias instability and RRW from clusters of at most {:.0f} minutes; "
        "compare before and after, not with a datasheet's hours-long runs)\n",
        span, shortest / 120);
  }
  for (const auto& w : data.warnings) std::cout << "warning: " << w << "\n";
}

}  // namespace

void add_evaluate(CLI::App& app) {
  auto args = std::make_shared<EvaluateArgs>();
  auto* cmd = app.add_subcommand(
      "evaluate",
      "Apply a compensation model to test recordings and print the paper's Table 2 view: per\n"
      "recording and overall, the MAE of the predicted drift against the target (denoised gyro\n"
      "minus the input rate, 10 s means), and the STD of the output before and after\n"
      "compensation. A recording's constant offset does not count in the STDs; the overall STDs\n"
      "are the RMS of the per-recording STDs, MAE pools every row. Beside them, what a\n"
      "four-position finding sees: the residual in the first 5 minutes after power-on and the\n"
      "difference between two opposite positions (90 s windows 180 s apart), before and after,\n"
      "and how much of each recording lay outside the model's training region (the guard\n"
      "reduces the correction there; --no-guard applies it in full; docs/field.md).\n"
      "Examples:\n"
      "  fogdrift evaluate model.json cal              # the campaign's role \"test\" recordings\n"
      "  fogdrift evaluate model.json run1.csv run2.csv --json\n"
      "  fogdrift evaluate model.json cal --allan      # datasheet noise terms before and after");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  cmd->add_flag("--allow-edited", args->allow_edited,
                "Load a model file whose content no longer matches its checksum (an edit made on "
                "purpose); its fields are still checked");
  cmd->add_option("inputs", args->inputs, "A campaign folder, or recording CSV files")->required();
  cmd->add_flag("--json", args->json, "Print the metrics as JSON");
  cmd->add_flag("--no-guard", args->no_guard,
                "Apply the model's full correction even where its inputs are novel");
  cmd->add_flag("--allan", args->allan,
                "Also the overlapping Allan deviation of every recording's output before and "
                "after compensation: angle random walk, bias instability, rate random walk");
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
