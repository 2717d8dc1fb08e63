// One serialiser of a training run's summary (train_summary.hpp).
#include "fogdrift/train/train_summary.hpp"

namespace fogdrift {

nlohmann::ordered_json summary_json(const CampaignTrainResult& trained, const OptionWords& words) {
  const TrainSummary& s = trained.trained.summary;
  const Dataset& data = trained.data;
  const DatasetOptions& dataset = trained.dataset;
  nlohmann::ordered_json j;
  j["method"] = to_string(s.method);
  j["fitness"] = s.fitness;
  j["fitness_rmse"] = s.fitness_value;
  j["cv"] = trained.trained.model.provenance.cv;
  j["hyperparameters"] = nlohmann::ordered_json::object();
  for (const auto& [k, v] : s.hyperparameters) j["hyperparameters"][k] = v;
  j["training_rows"] = s.rows;
  j["recordings"] = data.groups.size();
  j["features"] = data.feature_names;
  for (const auto& [key, value] : s.record.items()) j[key] = value;  // the trainer's own
  if (!j.contains("search")) j["search"] = nullptr;
  nlohmann::ordered_json notes = nlohmann::ordered_json::array();
  for (const CampaignNote& n : trained.notes)
    notes.push_back(n.text + " (" + words.field(n.field) + ")");
  j["notes"] = notes;
  nlohmann::ordered_json edges = nlohmann::ordered_json::array();
  for (const auto& e : s.box_edges)
    edges.push_back({{"parameter", e.parameter},
                     {"edge", e.upper ? "upper" : "lower"},
                     {"value", e.value},
                     {"box", {e.low, e.high}},
                     {"improvement", e.improvement}});
  j["box_edges"] = edges;
  nlohmann::ordered_json boxes = nlohmann::ordered_json::array();
  for (const auto& b : s.boxes)
    boxes.push_back({{"c", {b.c_min, b.c_max}}, {"sigma", {b.sigma_min, b.sigma_max}}});
  j["boxes_searched"] = boxes;
  nlohmann::ordered_json advice = nlohmann::ordered_json::array();
  if (s.held_out) {
    const HeldOutReport& h = *s.held_out;
    for (const auto& w : h.warnings) advice.push_back(words.text(w));
    nlohmann::ordered_json base = nlohmann::ordered_json::array();
    for (const Baseline& b : h.baselines) base.push_back({{"name", b.name}, {"rmse", b.rmse}});
    j["held_out"] = {{"folds", h.folds},
                     {"model_rmse", h.model_rmse},
                     {"expected_share", h.expected_share},
                     {"expected_startup_share", h.expected_startup_share},
                     {"baselines", base},
                     {"warnings", advice}};
  } else {
    j["held_out"] = {{"missing", s.held_out_missing}};
  }
  nlohmann::ordered_json warnings = data.warnings;
  for (const auto& w : advice) warnings.push_back(w);
  j["warnings"] = warnings;
  j["block_s"] = dataset.preprocessing.block.block_s;
  j["rate_window_s"] = dataset.preprocessing.rates.window_s;
  j["rate_degree"] = dataset.preprocessing.rates.poly_order;
  j["fits"] = s.tuning.fits;
  j["seconds"] = s.seconds;
  return j;
}

}  // namespace fogdrift
