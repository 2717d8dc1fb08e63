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
  // The trainer's own keys (its record, trainer_record.hpp); what a searched SVR records every
  // summary has, empty for the others.
  const nlohmann::ordered_json record = s.record.json();
  for (const auto& [key, value] : record.items()) j[key] = value;
  if (!j.contains("search")) j["search"] = nullptr;
  if (!j.contains("box_edges")) j["box_edges"] = nlohmann::ordered_json::array();
  if (!j.contains("boxes_searched")) j["boxes_searched"] = nlohmann::ordered_json::array();
  if (!j.contains("fits")) j["fits"] = 0;
  nlohmann::ordered_json notes = nlohmann::ordered_json::array();
  for (const CampaignNote& n : trained.notes)
    notes.push_back(n.text + " (" + words.field(n.field) + ")");
  j["notes"] = notes;
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
  j["seconds"] = s.seconds;
  return j;
}

}  // namespace fogdrift
