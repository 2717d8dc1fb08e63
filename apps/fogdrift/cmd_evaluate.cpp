// fogdrift evaluate: the paper's Table 2 view of a compensation model on test recordings.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/eval/evaluation.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/campaign_option_table.hpp"
#include "fogdrift/model/baselines.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/report/evaluation_figures.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct EvaluateArgs {
  ModelLoadOptions load;
  std::string model;
  std::vector<std::string> inputs;
  bool json = false;
  std::shared_ptr<OptionFlags> flags;  // the evaluation's options (eval_option_table.hpp)
  /// What the channels sensed, for recording files (campaign_option_table.hpp).
  std::shared_ptr<OptionFlags> sensed;
  std::string figures;  ///< folder for the figures; empty: none
  bool force = false;   ///< replace that folder
};

/// A metric as printed: n/a where it does not apply (eval::kNotApplicable).
std::string figure(double value, const char* format = "{:.4f}") {
  return std::isfinite(value) ? fmt::format(fmt::runtime(format), value) : "n/a";
}

/// An Allan term is read from the output at the recording's rate; fewer samples than this give
/// a deviation whose short-τ point alone scatters by more than ±10 % (1/√N).
constexpr std::size_t kAllanMinSamples = 100;

bool is_campaign(const std::string& path) {
  return std::filesystem::is_directory(path) || path.ends_with(".json");
}

void print_evaluation(const CompensationModel& model, const eval::Evaluation& e,
                      const std::string& source, const std::string& heading, bool allan);
void write_figures(const std::string& dir, bool force, const std::vector<report::Figure>& figures,
                   bool json);
void print_field_figures(const eval::Evaluation& e);
void print_baselines(const eval::Evaluation& e);
void print_extrapolation(const eval::Evaluation& e);
void print_allan(const std::vector<eval::RecordingEvaluation>& per);

void run(const EvaluateArgs& a) {
  const ModelSet set = load_model_set(a.model, a.load);
  eval::EvaluationOptions options;
  a.flags->apply(eval::evaluation_option_table(), options);
  SensedOptions sensed;
  a.sensed->apply(sensed_option_table(), sensed);
  std::optional<Campaign> campaign;
  std::vector<RecordingInput> inputs;
  std::string source;
  if (a.inputs.size() == 1 && is_campaign(a.inputs[0])) {
    if (sensed.input_rate_dph)
      throw OptionError("--input-rate-dph",
                        "applies to recording files; a campaign says its input rate in "
                        "campaign.json (fogdrift campaign --input-rate-dph)");
    if (!sensed.references.empty())
      throw OptionError("--reference",
                        "applies to recording files; a campaign says its references in "
                        "campaign.json (fogdrift campaign --reference)");
    campaign = read_campaign(a.inputs[0]);
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
      in.input_rate_dph = sensed.input_rate_dph;
      in.references = sensed.references;
      inputs.push_back(std::move(in));
    }
    source = fmt::format("{} recording file{}", inputs.size(), inputs.size() == 1 ? "" : "s");
  }
  if (!a.figures.empty()) {
    check_output_not_input(a.figures, "--figures");
    options.series = true;
  } else if (a.force) {
    throw OptionError("--force", "replaces the folder of --figures; give --figures DIR with it");
  }
  // One evaluation per axis the model compensates (model_set.hpp).
  std::vector<std::string> axes;  // --json: each axis's evaluation
  std::vector<report::Figure> figures;
  std::vector<std::pair<std::string, std::string>> verdicts;  // target, verdict
  for (const CompensationModel& model : set.models) {
    const eval::Evaluation e = campaign ? eval::evaluate(model, *campaign, options, a.model)
                                        : eval::evaluate(model, inputs, options, a.model);
    const std::string& target = model.dataset.target_column;
    if (options.series)
      for (report::Figure& f : report::evaluation_figures(
               e, model.baselines, model.feature_names,
               set.models.size() > 1 || target != "gyro_dph" ? target + "_" : ""))
        figures.push_back(std::move(f));
    verdicts.emplace_back(target, eval::verdict(e));
    if (a.json) {
      axes.push_back(eval::to_json(e, a.model, source));
    } else {
      print_evaluation(model, e, source,
                       set.models.size() > 1 || target != "gyro_dph" ? target + ": " : "",
                       options.allan);
    }
  }
  // Over several axes, the axes the models harm or do not help, by name.
  std::vector<std::string> harmed_axes, no_better_axes;
  for (const auto& [target, v] : verdicts) {
    if (v == "harms")
      harmed_axes.push_back(target);
    else if (v != "beats its baselines")
      no_better_axes.push_back(target);
  }
  if (!a.json && verdicts.size() > 1) {
    std::cout << "\nverdict over " << verdicts.size() << " axes:";
    for (const auto& [target, v] : verdicts) std::cout << " " << target << " " << v << ";";
    std::cout << "\n";
  }
  if (a.json && axes.size() == 1) {
    std::cout << axes.front() << "\n";
  } else if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.model;
    j["source"] = source;
    j["targets"] = set.targets();
    j["harmed_axes"] = harmed_axes;
    j["no_better_axes"] = no_better_axes;
    j["axes"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < axes.size(); ++i) {
      nlohmann::ordered_json one = {{"target", set.models[i].dataset.target_column}};
      const nlohmann::ordered_json axis = nlohmann::ordered_json::parse(axes[i]);
      for (const auto& [k, v] : axis.items())
        if (k != "model" && k != "source") one[k] = v;
      j["axes"].push_back(one);
    }
    std::cout << j.dump(2) << "\n";
  }
  if (!a.figures.empty()) write_figures(a.figures, a.force, figures, a.json);
}

/// The figures as JSON and PNG in `dir`, all or none (atomic_file.hpp); a PNG gnuplot cannot
/// draw is said on standard error, its JSON still written.
void write_figures(const std::string& dir, bool force, const std::vector<report::Figure>& figures,
                   bool json) {
  std::vector<std::string> problems;
  fill_directory_atomically(dir, force, [&](const std::filesystem::path& folder) {
    problems = report::write_figures(figures, folder);
  });
  (json ? std::cerr : std::cout) << fmt::format("\nWrote {} figures to {}/ (PNG and JSON): {}\n",
                                                figures.size(), dir, [&] {
                                                  std::string names;
                                                  for (const report::Figure& f : figures)
                                                    names += (names.empty() ? "" : ", ") + f.name;
                                                  return names;
                                                }());
  for (const std::string& p : problems) std::cerr << "fogdrift evaluate: no PNG: " << p << "\n";
}

void print_evaluation(const CompensationModel& model, const eval::Evaluation& e,
                      const std::string& source, const std::string& heading, bool allan) {
  const eval::CompensationMetrics& all = e.overall;
  const auto& per = e.recordings;
  const Target target = target_of(e.target);
  const std::string_view unit = target.symbol();
  std::cout << fmt::format("{}{} on {}: {} rows of {} recording{}\n\n", heading, e.method, source,
                           e.rows, per.size(), per.size() == 1 ? "" : "s");
  // Before is what the model was trained to remove: the gyro less its input as logged (train's
  // default), or the denoised drift for a model trained with --denoise (the paper's target).
  std::cout << (model.dataset.denoise_target
                    ? fmt::format("Before (the denoised drift) → after compensation, {}:\n", unit)
                    : fmt::format("Before (the drift as logged, not denoised) → after "
                                  "compensation, {}:\n",
                                  unit))
            << "| recording | T0 (°C) | MAE | STD |\n"
               "|---|---|---|---|\n";
  const auto f = [&](double v) { return target.format(v); };
  for (const eval::RecordingEvaluation& r : per)
    std::cout << fmt::format("| {} | {:g} | {} → {} | {} → {} |\n", r.info.file,
                             r.info.initial_temp_degc, f(r.metrics.mae_before_dph),
                             f(r.metrics.mae_dph), f(r.metrics.std_before_dph),
                             f(r.metrics.std_after_dph));
  std::cout << fmt::format("| **all** | | **{} → {}** | **{} → {}** |\n", f(all.mae_before_dph),
                           f(all.mae_dph), f(all.std_before_dph), f(all.std_after_dph));
  if (per.size() > 1)
    std::cout << fmt::format(
        "(all: STD is the RMS of the recordings' STDs, as Table 2; pooled over every row, offsets "
        "between recordings kept: {} → {})\n",
        f(all.pooled_std_before_dph), f(all.pooled_std_after_dph));
  // The paper's figures belong beside the paper's instrument, the simulator, not a user's data.
  if (e.simulated && e.target == "gyro_dph")
    std::cout << fmt::format(
        "\nTable 2 view: denoised STD {:.4f} °/h, {} STD {:.4f} °/h, MAE {:.4f} °/h "
        "(paper: denoised 0.0134; SSA-SVR 0.0031, MAE 0.0025)\n",
        all.std_before_dph, e.method, all.std_after_dph, all.mae_dph);
  print_baselines(e);
  print_extrapolation(e);
  if (target.kind == TargetKind::gyro) {
    print_field_figures(e);
    if (allan) print_allan(per);
  } else {
    // A four-position finding and the Allan terms printed are a gyro's; they would not apply.
    std::cout << fmt::format(
        "\n(no north-finding figures: a four-position finding reads gyros, "
        "and {} is {} {})\n",
        e.target, target.kind == TargetKind::accelerometer ? "an" : "a", target.what());
    if (allan)
      std::cout << fmt::format("(no Allan terms: --allan gives a gyro's, and {} is not one)\n",
                               e.target);
  }
  for (const auto& w : e.warnings) std::cout << "warning: " << w << "\n";
}

/// "a, b and c".
std::string listed(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return out;
}

/// The model beside raw, the recording mean and the line in T, with the harm it does.
void print_baselines(const eval::Evaluation& e) {
  const Target target = target_of(e.target);
  const auto f = [&](double v) { return std::isfinite(v) ? target.format(v) : "n/a"; };
  const std::string line = e.line_input.empty() ? "line in T" : "line in " + e.line_input;
  std::cout << fmt::format(
      "\nBeside its baselines (docs/compensation.md, \"Judging a model\"), {}: RMSE of each "
      "prediction of the drift; STD of what it leaves\n"
      "| recording | raw | recording mean | {} | model | STD raw / line / model | judged |\n"
      "|---|---|---|---|---|---|---|\n",
      target.symbol(), line);
  auto judged = [](const eval::BaselineComparison& c) {
    if (!c.harms.empty()) return std::string("**HARMS**");
    if (!c.no_better_than.empty()) return "no better than " + listed(c.no_better_than);
    return std::string("better");
  };
  auto row = [&](const std::string& name, const eval::BaselineComparison& c) {
    std::cout << fmt::format("| {} | {} | {} | {} | {} | {} / {} / {} | {} |\n", name,
                             f(c.raw_rmse), f(c.mean_rmse), f(c.line_rmse), f(c.model_rmse),
                             f(c.raw_std), f(c.line_std), f(c.model_std), judged(c));
  };
  for (const eval::RecordingEvaluation& r : e.recordings) row(r.info.file, r.baselines);
  row("**all**", e.overall_baselines);
  if (e.line_input.empty())
    std::cout << (e.ranges_known ? "(no line in T: the model has no temperature input)\n"
                                 : "(no line in T: the model file was written before models kept "
                                   "their baselines; train it again to see one)\n");
  for (const eval::RecordingEvaluation& r : e.recordings)
    for (const std::string& h : r.baselines.harms)
      std::cout << fmt::format("warning: the model harms {}: {}\n", r.info.file,
                               eval::with_unit(h, target.symbol()));
  for (const eval::RecordingEvaluation& r : e.recordings)
    if (!r.baselines.no_better_than.empty())
      std::cout << fmt::format("warning: the model is no better than {} on {}\n",
                               listed(r.baselines.no_better_than), r.info.file);
  for (const std::string& h : e.overall_baselines.harms)
    std::cout << fmt::format("warning: the model harms {} over all recordings: {}\n", e.target,
                             eval::with_unit(h, target.symbol()));
  const std::size_t n = e.recordings.size();
  const std::string v = eval::verdict(e);
  if (v == "harms")
    std::cout << fmt::format(
        "verdict: the model HARMS {} of {} recording{}{}; it makes {} worse where a warning says "
        "so, and should not be shipped for this axis as it is\n",
        e.harmed.size(), n, n == 1 ? "" : "s", e.harmed.empty() ? " (and all pooled)" : "",
        e.target);
  else if (v == "no better than its baselines")
    std::cout << fmt::format(
        "verdict: no better than its baselines on {} of {} recording{} ({}): on {} the model "
        "removes less than {:.0f} % beyond what needs no model\n",
        e.no_better.size(), n, n == 1 ? "" : "s",
        listed(e.overall_baselines.no_better_than.empty() ? std::vector<std::string>{"some"}
                                                          : e.overall_baselines.no_better_than),
        e.target, 100 * eval::kNoBetterShare);
  else
    std::cout << fmt::format("verdict: beats raw, the recording mean{} on every recording\n",
                             e.line_input.empty() ? "" : " and the " + line);
}

/// Each input's training range in its own unit, and how far each recording lies outside it.
void print_extrapolation(const eval::Evaluation& e) {
  if (!e.ranges_known) {
    std::cout << "\n(training ranges not known: the model file was written before models kept "
                 "them; train it again to see how far each recording lies outside them)\n";
    return;
  }
  if (e.recordings.empty() || e.recordings.front().extrapolation.empty()) return;
  std::cout << "\nInputs against their training ranges, in their own units:\n  training:";
  for (const InputExtrapolation& x : e.recordings.front().extrapolation)
    std::cout << fmt::format(" {} {:.4g} .. {:.4g};", x.input, x.train_min, x.train_max);
  std::cout << "\n| recording | rows outside | farthest outside | guard |\n|---|---|---|---|\n";
  for (const eval::RecordingEvaluation& r : e.recordings) {
    std::vector<std::string> far;
    for (const InputExtrapolation& x : r.extrapolation)
      if (x.share_outside > 0)
        far.push_back(fmt::format("{} by {:.3g} ({:.0f} % of rows; {:.4g} .. {:.4g})", x.input,
                                  x.farthest_outside, 100 * x.share_outside, x.min, x.max));
    std::cout << fmt::format(
        "| {} | {:.1f} % | {} | {} |\n", r.info.file, 100 * r.outside_training_share,
        far.empty() ? std::string("inside") : listed(far), r.novelty.line().substr(9));
  }
  std::cout << "(rows outside: any input beyond its training range, at the model's block rate; "
               "guard: the novelty of the inputs together, at the recording's rate, which counts "
               "a sample between calibration temperatures as familiar; docs/field.md)\n";
}

/// Where north-finding needs it: the start-up residual and the opposite-position difference.
void print_field_figures(const eval::Evaluation& e) {
  const eval::CompensationMetrics& all = e.overall;
  const auto& per = e.recordings;
  std::cout << "\nWhere north-finding needs it (docs/field.md), before → after, °/h:\n"
               "| recording | first 5 min residual | opposite positions 180 s apart | guard |\n"
               "|---|---|---|---|\n";
  bool late = false, sparse = false;
  for (const eval::RecordingEvaluation& r : per) {
    const eval::CompensationMetrics& m = r.metrics;
    late = late || !std::isfinite(m.startup_before_dph);
    sparse = sparse || !std::isfinite(m.opposite_before_dph);
    std::cout << fmt::format("| {} | {} → {} | {} → {} | {} |\n", r.info.file,
                             figure(m.startup_before_dph), figure(m.startup_after_dph),
                             figure(m.opposite_before_dph), figure(m.opposite_after_dph),
                             r.novelty.line().substr(9));
  }
  std::cout << fmt::format("| **all** | **{} → {}** | **{} → {}** | {} |\n",
                           figure(all.startup_before_dph), figure(all.startup_after_dph),
                           figure(all.opposite_before_dph), figure(all.opposite_after_dph),
                           e.guarded ? "on" : "off (--no-guard)");
  if (late)
    std::cout << "(n/a first 5 min: the recording starts 5 minutes or more after power-on, its "
                 "time_s; there is no start-up to show)\n";
  if (sparse)
    std::cout << "(n/a opposite positions: the modelling rows are more than 180 s apart, or the "
                 "recording is shorter than three 90 s positions; a four-position finding cannot "
                 "be read from it)\n";
}

/// The Allan noise terms of each recording's gyro output, raw and compensated.
void print_allan(const std::vector<eval::RecordingEvaluation>& per) {
  std::cout << "\nAllan deviation of the gyro output at the recording's rate, raw → compensated:\n"
               "| recording | ARW (°/√h) | bias instability (°/h) | RRW (°/h/√h) |\n"
               "|---|---|---|---|\n";
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  std::size_t few = 0;
  for (const eval::RecordingEvaluation& rec : per) {
    const auto& r = rec.allan->raw;
    const auto& c = rec.allan->compensated;
    if (rec.samples < kAllanMinSamples) {
      ++few;
      std::cout << fmt::format("| {} | n/a | n/a | n/a |\n", rec.info.file);
      continue;
    }
    std::cout << fmt::format("| {} | {:.5f} → {:.5f} | {:.4f} → {:.4f} | {:.4f} → {:.4f} |\n",
                             rec.info.file, r.arw_deg_per_rt_h, c.arw_deg_per_rt_h,
                             r.bias_instability_dph, c.bias_instability_dph, r.rrw_dph_per_rt_h,
                             c.rrw_dph_per_rt_h);
    shortest = std::min(shortest, rec.duration_s);
    longest = std::max(longest, rec.duration_s);
  }
  if (few < per.size()) {
    const std::string span =
        std::lround(shortest / 60) == std::lround(longest / 60)
            ? fmt::format("{:.0f}-minute", shortest / 60)
            : fmt::format("{:.0f}- to {:.0f}-minute", shortest / 60, longest / 60);
    std::cout << fmt::format(
        "({} recordings read bias instability and RRW from clusters of at most {:.0f} minutes; "
        "compare before and after, not with a datasheet's hours-long runs)\n",
        span, shortest / 120);
  }
  if (few)
    std::cout << fmt::format(
        "(n/a: {} recording{} of fewer than {} samples, whose Allan deviation scatters by more "
        "than ±10 % at its shortest τ)\n",
        few, few == 1 ? "" : "s", kAllanMinSamples);
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
      "  fogdrift evaluate model.json cal --allan      # datasheet noise terms before and after\n"
      "  fogdrift evaluate model.json cal --figures figs   # PNG and JSON to look at");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  add_model_load_flags(cmd, &args->load);
  cmd->add_option("inputs", args->inputs, "A campaign folder, or recording CSV files")->required();
  const auto& sensed = sensed_option_table();
  args->sensed = std::make_shared<OptionFlags>(
      cmd, specs_of(sensed), defaults_of(sensed),
      "Recording files only: what the channels sensed (a campaign says it in campaign.json)");
  cmd->add_flag("--json", args->json, "Print the metrics as JSON");
  cmd->add_option("--figures", args->figures,
                  "Folder for figures, PNG (gnuplot) and JSON, per axis: each recording raw and "
                  "compensated, the residual against temperature for the model and the line in T, "
                  "and the held-out rows over the training region (docs/compensation.md, "
                  "\"Figures\"); written whole or not at all");
  cmd->add_flag("--force", args->force, "With --figures: replace the folder if it exists");
  const auto& table = eval::evaluation_option_table();
  args->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
