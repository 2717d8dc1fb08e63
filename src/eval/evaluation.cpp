// Table 2 and its field columns for a compensation model (evaluation.hpp).
#include "fogdrift/eval/evaluation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"

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

/// A comparison's figures with keys in the target's unit, its harms with the unit filled in.
nlohmann::ordered_json baselines_json(const BaselineComparison& c, std::string_view unit,
                                      std::string_view symbol) {
  nlohmann::ordered_json j;
  for (const auto& [key, value] :
       {std::pair{"raw_rmse", c.raw_rmse}, std::pair{"recording_mean_rmse", c.mean_rmse},
        std::pair{"line_rmse", c.line_rmse}, std::pair{"model_rmse", c.model_rmse},
        std::pair{"raw_std", c.raw_std}, std::pair{"line_std", c.line_std},
        std::pair{"model_std", c.model_std}})
    j[fmt::format("{}_{}", key, unit)] =
        std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
  j["harms"] = nlohmann::ordered_json::array();
  for (const std::string& h : c.harms) j["harms"].push_back(with_unit(h, symbol));
  j["no_better_than"] = c.no_better_than;
  return j;
}

nlohmann::ordered_json terms_json(const NoiseTerms& t) {
  return {{"arw_deg_per_rt_h", t.arw_deg_per_rt_h},
          {"bias_instability_dph", t.bias_instability_dph},
          {"rrw_dph_per_rt_h", t.rrw_dph_per_rt_h}};
}

}  // namespace

std::string with_unit(std::string_view text, std::string_view symbol) {
  std::string out(text);
  for (std::size_t at; (at = out.find("{unit}")) != std::string::npos;) out.replace(at, 6, symbol);
  return out;
}

std::string verdict(const Evaluation& e) {
  if (!e.harmed.empty() || !e.overall_baselines.harms.empty()) return "harms";
  if (!e.no_better.empty() || !e.overall_baselines.no_better_than.empty())
    return "no better than its baselines";
  return "beats its baselines";
}

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
  const std::vector<double> predicted = model.predict_dph(data, options.guarded);
  const std::vector<CompensationMetrics> per = metrics_per_recording(data, predicted);
  e.overall = pool(per);
  // The baselines and the training ranges, from the model file (baselines.hpp).
  const auto& line = model.baselines.line;
  e.line_input = line ? line->input : "";
  e.ranges_known = model.baselines.has_ranges();
  const std::vector<double> line_all =
      line ? line_drift(*line, data, model_label) : std::vector<double>{};
  // The inputs the figures draw the training region in.
  const auto index_of = [&](const std::string& name) {
    const auto it = std::find(data.feature_names.begin(), data.feature_names.end(), name);
    return it == data.feature_names.end()
               ? std::string::npos
               : static_cast<std::size_t>(it - data.feature_names.begin());
  };
  std::size_t t_col = std::string::npos, r_col = std::string::npos;
  if (options.series) {
    e.temperature_input = temperature_input_of(data.feature_names);
    if (!e.temperature_input.empty()) {
      // "T_fog_degc" → a rate "dT…_fog_degc_per_s".
      const std::string thermometer =
          e.temperature_input.substr(1, e.temperature_input.size() - 1) + "_per_s";
      for (const std::string& n : data.feature_names)
        if (e.rate_input.empty() && n.starts_with("dT") && n.ends_with(thermometer))
          e.rate_input = n;
    }
    t_col = e.temperature_input.empty() ? std::string::npos : index_of(e.temperature_input);
    r_col = e.rate_input.empty() ? std::string::npos : index_of(e.rate_input);
    const std::size_t d = model.feature_names.size();
    for (std::size_t p = 0; d > 0 && p < model.guard.prototypes.size() / d; ++p) {
      auto unscaled = [&](std::size_t k) {
        return model.guard.prototypes[p * d + k] * model.x_scaler.scale[k] + model.x_scaler.mean[k];
      };
      if (t_col != std::string::npos) e.region_temperature.push_back(unscaled(t_col));
      if (r_col != std::string::npos) e.region_rate.push_back(unscaled(r_col));
    }
  }
  std::vector<std::vector<std::size_t>> rows_of(per.size());
  for (std::size_t i = 0; i < data.rows; ++i) rows_of[data.group[i]].push_back(i);
  std::vector<BaselineComparison> comparisons;
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
    {
      std::vector<double> y, p, l;
      for (std::size_t i : rows_of[g]) {
        y.push_back(data.y[i]);
        p.push_back(predicted[i]);
        if (line) l.push_back(line_all[i]);
      }
      r.baselines = compare_with_baselines(y, p, l, e.line_input);
      comparisons.push_back(r.baselines);
      if (!r.baselines.harms.empty()) e.harmed.push_back(r.info.file);
      if (!r.baselines.no_better_than.empty()) e.no_better.push_back(r.info.file);
      if (options.series) {
        RecordingSeries rs;
        for (std::size_t i : rows_of[g]) {
          rs.time_s.push_back(data.time_s.empty() ? 0.0 : data.time_s[i]);
          if (t_col != std::string::npos) rs.temperature.push_back(data.x[i * data.cols() + t_col]);
          if (r_col != std::string::npos) rs.rate.push_back(data.x[i * data.cols() + r_col]);
        }
        rs.target = std::move(y);
        rs.model = std::move(p);
        rs.line = std::move(l);
        r.series = std::move(rs);
      }
      r.extrapolation = extrapolation(model.baselines, data, rows_of[g]);
      r.outside_training_share = share_outside_any(model.baselines, data, rows_of[g]);
    }
    const RecordingPrediction p = model.predict(rec, options.guarded);
    r.novelty = summarize_novelty(p.novelty, p.weight);
    if (options.allan && gyro) r.allan = allan_comparison(rec, p.drift_dph);
    r.duration_s = rec.time_s.back() - rec.time_s.front();
    r.samples = rec.time_s.size();
    e.recordings.push_back(std::move(r));
  }
  e.overall_baselines = pool(comparisons, e.line_input);
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
  const std::string_view symbol = target_of(e.target).symbol();
  j["baselines"] = baselines_json(e.overall_baselines, unit, symbol);
  j["baselines"]["line_input"] =
      e.line_input.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(e.line_input);
  j["verdict"] = verdict(e);
  j["harmed"] = e.harmed;
  j["no_better"] = e.no_better;
  j["training_ranges_known"] = e.ranges_known;
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
    o["baselines"] = baselines_json(r.baselines, unit, symbol);
    o["outside_training_share"] = r.outside_training_share;
    o["extrapolation"] = nlohmann::ordered_json::array();
    for (const InputExtrapolation& x : r.extrapolation)
      o["extrapolation"].push_back({{"input", x.input},
                                    {"train_min", x.train_min},
                                    {"train_max", x.train_max},
                                    {"min", x.min},
                                    {"max", x.max},
                                    {"share_outside", x.share_outside},
                                    {"farthest_outside", x.farthest_outside}});
    if (r.allan)
      o["allan"] = {{"raw", terms_json(r.allan->raw)},
                    {"compensated", terms_json(r.allan->compensated)}};
    j["recordings"].push_back(std::move(o));
  }
  j["warnings"] = e.warnings;
  return j.dump(2);
}

}  // namespace fogdrift::eval
