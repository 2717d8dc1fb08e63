// What a training run reports, as JSON: `fogdrift train --json`'s summary and the summary the
// Octave/MATLAB fogdrift.train returns are this one text (docs/architecture.md, "train/").
// Advice and notes name options, and each front end names them in its own words.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "fogdrift/train/train_campaign.hpp"

namespace fogdrift {

/// How a front end names options in the summary's notes and advice.
struct OptionWords {
  /// The front end's word for the option that sets a library field (option_word).
  std::function<std::string(const std::string& field)> field;
  /// A text with each "{keyword}" in the front end's words (in_option_words).
  std::function<std::string(const std::string& text)> text;
};

/// The summary of one trained model: method, fitness, fitness_rmse, cv, hyperparameters,
/// training_rows, recordings, features, the trainer's own record (TrainerRecord::json: "bp",
/// "gp", "poly_cv_rmse_by_degree", or a searched SVR's "search", box_edges, boxes_searched and
/// fits, which every summary has: null, [] and 0 for the others), notes ("TEXT (WORD)"),
/// held_out (its baselines and advice, or {"missing": why}), warnings (the data's, then the
/// held-out advice), block_s, rate_window_s, rate_degree, seconds.
nlohmann::ordered_json summary_json(const CampaignTrainResult& trained, const OptionWords& words);

}  // namespace fogdrift
