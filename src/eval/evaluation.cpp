// Table 2 and its field columns for a compensation model (evaluation.hpp).
#include "fogdrift/eval/evaluation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/model/features.hpp"

namespace fogdrift::eval {
namespace {

// From the drift the model predicted for the recording (RecordingPrediction::drift_dph).
AllanComparison allan_comparison(const Recording& rec, const std::vector<double>& drift) {
  const double dt = sample_interval_s(rec);
  std::vector<double> comp(rec.gyro_dph.size());
  for (std::size_t i = 0; i < comp.size(); ++i) comp[i] = rec.gyro_dph[i] - drift[i];
  return {noise_terms(allan_deviation(rec.gyro_dph, dt, 10)),
          noise_terms(allan_deviation(comp, dt, 10))};
}

nlohmann::ordered_json metrics_json(const CompensationMetrics& m) {
  return {{"rows", m.rows},
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
}

/// The metrics of a target in `unit`: the keys above, ending in _dph for a gyro, in _UNIT else.
nlohmann::ordered_json metrics_json(const CompensationMetrics& m, std::string_view unit) {
  nlohmann::ordered_json j = metrics_json(m);
  if (unit == "dph") return j;
  nlohmann::ordered_json out;
  for (const auto& [key, value] : j.items())
    out[key.ends_with("_dph") ? fmt::format("{}_{}", key.substr(0, key.size() - 4), unit) : key] =
        value;
  return out;
}

nlohmann::ordered_json terms_json(const NoiseTerms& t) {
  return {{"arw_deg_per_rt_h", t.arw_deg_per_rt_h},
          {"bias_instability_dph", t.bias_instability_dph},
          {"rrw_dph_per_rt_h", t.rrw_dph_per_rt_h}};
}

}  // namespace

Evaluation evaluate(const CompensationModel& model, const std::vector<RecordingInput>& inputs,
                    const EvaluationOptions& options, const std::string& model_label) {
  const Dataset data = build_dataset(inputs, model.dataset);
  if (data.feature_names != model.feature_names)
    throw InputError(
        model_label, 0, 0,
        fmt::format("features: the model's features ({}) differ from those its "
                    "feature spec gives for this data ({})",
                    fmt::join(model.feature_names, ","), fmt::join(data.feature_names, ",")));
  Evaluation e;
  e.method = model.provenance.method;
  e.target = model.dataset.target_column;
  e.guarded = options.guarded;
  const bool gyro = target_of(e.target).kind == TargetKind::gyro;
  e.rows = data.rows;
  e.warnings = data.warnings;
  const std::vector<CompensationMetrics> per =
      metrics_per_recording(data, model.predict_dph(data, options.guarded));
  e.overall = pool(per);
  for (std::size_t g = 0; g < per.size(); ++g) {
    // The gyro the model compensates: gyro_dph, or another axis (dataset.hpp, with_target).
    Recording other_axis;
    const Recording& rec =
        model.dataset.target_column == "gyro_dph"
            ? inputs[g].recording
            : (other_axis = with_target(inputs[g].recording, model.dataset.target_column));
    RecordingEvaluation r;
    r.info = data.groups[g];
    r.metrics = per[g];
    const RecordingPrediction p = model.predict(rec, options.guarded);
    r.novelty = summarize_novelty(p.novelty, p.weight);
    if (options.allan && gyro) r.allan = allan_comparison(rec, p.drift_dph);
    r.duration_s = rec.time_s.back() - rec.time_s.front();
    r.samples = rec.time_s.size();
    e.recordings.push_back(std::move(r));
  }
  return e;
}

Evaluation evaluate(const CompensationModel& model, const Campaign& campaign,
                    const EvaluationOptions& options, const std::string& model_label) {
  Evaluation e = evaluate(model, read_inputs(campaign, Role::test, Scenario::calibration), options,
                          model_label);
  e.simulated = campaign.generator_json.find("\"fogdrift simulate\"") != std::string::npos;
  return e;
}

std::string to_json(const Evaluation& e, const std::string& model_label,
                    const std::string& source) {
  nlohmann::ordered_json j;
  j["model"] = model_label;
  j["method"] = e.method;
  j["source"] = source;
  const std::string_view unit = target_of(e.target).unit();
  j["overall"] = metrics_json(e.overall, unit);
  j["guard"] = e.guarded;
  j["recordings"] = nlohmann::ordered_json::array();
  for (const RecordingEvaluation& r : e.recordings) {
    nlohmann::ordered_json o = {{"file", r.info.file},
                                {"initial_temp_degc", r.info.initial_temp_degc},
                                {"repetition", r.info.repetition}};
    o.update(metrics_json(r.metrics, unit));
    const double n = static_cast<double>(std::max<std::size_t>(1, r.novelty.samples));
    o["novelty_outside_share"] = static_cast<double>(r.novelty.outside) / n;
    o["novelty_reduced_share"] = static_cast<double>(r.novelty.reduced) / n;
    if (r.allan)
      o["allan"] = {{"raw", terms_json(r.allan->raw)},
                    {"compensated", terms_json(r.allan->compensated)}};
    j["recordings"].push_back(std::move(o));
  }
  j["warnings"] = e.warnings;
  return j.dump(2);
}

}  // namespace fogdrift::eval
