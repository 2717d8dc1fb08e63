// How sure `train` is: what a trained model is expected to remove, measured on the rows its
// grouped folds held out, beside the simplest models scored on the same folds
// (docs/tuning.md, "How sure train is").
//
// Every figure is a pooled RMSE of the drift on the held-out rows, each fold standardised with its
// own training rows' statistics, exactly as the search scores a candidate (tune.hpp):
//   mean            the training rows' mean drift (0 in standardised units);
//   line in T_k     a straight line in one temperature input, fitted to the training rows.
// The expected share is 1 − model / mean: the share of the held-out drift's RMS about the
// training mean that the model removes. It is negative when the model does worse than a constant.
// Much of that RMS is the static drift's change between temperatures, which a four-position
// north-finding, made within one start-up, does not see. So the report also gives the share of
// the drift's variation *within* each held-out start-up that the model removes:
//   1 − RMS(e − ē_g) / RMS(y − ȳ_g),  e = model − y, ḡ: the mean over that recording's rows,
// the figure that tells whether compensation will help the north-finder.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/model/dataset.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift {

struct Baseline {
  std::string name;   ///< "mean" or "line in T_fog_degc"
  std::string input;  ///< the temperature input of a line ("T_fog_degc"); empty for the mean
  double rmse = 0;    ///< held-out RMSE, standardised drift
};

struct HeldOutReport {
  std::string folds;  ///< how the rows were held out, e.g. "whole initial temperatures (3 folds)"
  double model_rmse = 0;            ///< the model's held-out RMSE, standardised drift
  std::vector<Baseline> baselines;  ///< the mean first, then one line per temperature input
  double expected_share = 0;        ///< 1 − model_rmse / the mean's RMSE
  /// The share of the drift's variation within each held-out start-up that the model removes.
  double expected_startup_share = 0;
  /// The model removes less than 10 % (or does no better than the mean), and then also when no
  /// temperature line beats the mean by 5 % (no temperature signal); or it does no better than a
  /// straight line in one temperature; or it removes too little of the variation within a
  /// start-up (startup_warning_share). Empty when the model beats them all. Options named in
  /// their advice are written "{keyword}", for each front end to show in its own words
  /// (in_option_words).
  std::vector<std::string> warnings;
};

/// The inputs a straight-line baseline is fitted in: those named T_<thermometer>_degc.
std::vector<std::size_t> temperature_inputs(std::span<const std::string> feature_names);

/// The baselines of `data` over `folds` (each fold with training and held-out rows).
std::vector<Baseline> baseline_scores(const Dataset& data, std::span<const tune::Fold> folds);

/// The model refitted on one fold's training rows, predicting its held-out rows: standardised
/// predictions for split.test, in order.
using FoldPredictor =
    std::function<std::vector<double>(const tune::ScaledSplit& split, std::size_t fold)>;

/// The share of the variation within a start-up below which the report warns that the model may
/// not help the north-finder (docs/tuning.md, "How sure train is"). It is measured against the
/// target the model was trained on, and the gyro's block means as logged keep a noise within each
/// start-up that the denoised target does not: the same model scores lower on them.
double startup_warning_share(bool denoised_target);

/// The report for the model `predict` refits on each fold; the start-up warning fires below
/// `startup_warning_below`.
/// `model_is_a_line`: the model is itself a straight line in one temperature, so the advice to
/// train one instead is not given.
HeldOutReport held_out_report(const Dataset& data, std::span<const tune::Fold> folds,
                              const FoldPredictor& predict, std::string folds_description,
                              double startup_warning_below = startup_warning_share(true),
                              bool model_is_a_line = false);

}  // namespace fogdrift
