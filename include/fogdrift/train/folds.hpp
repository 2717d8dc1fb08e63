// Grouped cross-validation, shared by the SVR's tuner (tune.hpp), the GP's search, the
// baselines and train's held-out report: folds that never split a recording (leave one
// repetition out, k folds of whole recordings, or k folds of whole initial temperatures), and a
// split standardised with its training rows' statistics only (docs/tuning.md).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "fogdrift/model/dataset.hpp"
#include "fogdrift/svr/kernel.hpp"

namespace fogdrift::tune {

enum class CvScheme {
  /// `temperature` (k folds) when the data holds at least max(3, k) initial temperatures; else
  /// `repetition` when it holds two or more repetitions; else `recording`. Temperature folds
  /// score a candidate where it was not trained, which transfers best (docs/tuning.md).
  automatic,
  repetition,  ///< leave one repetition out: as many folds as repetitions
  recording,   ///< k folds of whole recordings, spread over the initial temperatures
  /// k folds of whole initial temperatures: a fold holds out every recording of its temperatures,
  /// so the fitness measures the drift at temperatures the model never saw, as north-finding
  /// at a new temperature does.
  temperature,
};
std::string to_string(CvScheme scheme);
CvScheme parse_cv_scheme(const std::string& text, const std::string& option = "cv");
/// "auto, repetition, recording, temperature": the names parse_cv_scheme takes.
std::string cv_scheme_names();

struct CvOptions {
  CvScheme scheme = CvScheme::automatic;
  /// k of `recording` folds (2 ≤ k ≤ number of recordings) or of `temperature` folds
  /// (2 ≤ k ≤ number of initial temperatures)
  std::size_t folds = 3;
};

struct Fold {
  std::string name;  ///< "repetition 2", "recordings 1/3"
  std::vector<std::size_t> train_rows;
  std::vector<std::size_t> test_rows;
};

/// The folds of `data` (rows grouped by Dataset::group). `recording` folds sort the recordings
/// by (initial temperature, repetition, file) and deal them out in turn, so every fold covers
/// the temperature range. `temperature` folds deal the sorted initial temperatures out in turn,
/// so a held-out temperature lies between two kept ones (except at the ends of the range).
/// Throws OptionError("cv", …) for leave-one-repetition-out with one repetition,
/// OptionError("folds", …) for k outside 2 … recordings (temperatures).
std::vector<Fold> grouped_folds(const Dataset& data, const CvOptions& options = {});

/// Features and target of a train/test split, standardised with the training rows' statistics
/// (the target as the one column "drift_dph").
struct ScaledSplit {
  Standardizer x_scaler;
  Standardizer y_scaler;
  Data train;
  Data test;  ///< empty when no test rows are given
};
ScaledSplit scale_split(const Dataset& data, std::span<const std::size_t> train_rows,
                        std::span<const std::size_t> test_rows);
/// Every fold split and standardised (scale_split), in the folds' order.
std::vector<ScaledSplit> scale_splits(const Dataset& data, std::span<const Fold> folds);

/// Held-out predictions per fold: what a candidate fitted on the fold's training rows predicts
/// for its test rows.
using FoldPredictions = std::vector<std::vector<double>>;

/// A candidate over the grouped folds, as every trainer that cross-validates fits it: `fit`
/// (const Data& train → a regressor with predict(const double*)) on each split's training rows,
/// its predictions for the split's test rows. The held-out report may reuse them (held_out.hpp:
/// it splits the same folds the same way).
template <class Fit>
FoldPredictions fold_predictions(std::span<const ScaledSplit> splits, Fit&& fit) {
  FoldPredictions out;
  out.reserve(splits.size());
  for (const ScaledSplit& split : splits) {
    const auto regressor = fit(split.train);
    std::vector<double>& predicted = out.emplace_back(split.test.rows);
    for (std::size_t r = 0; r < split.test.rows; ++r)
      predicted[r] = regressor.predict(split.test.row(r));
  }
  return out;
}

/// The RMSE of `predicted` against the splits' held-out targets, pooled over every held-out row
/// (a trainer's "cv" fitness).
double pooled_rmse(std::span<const ScaledSplit> splits, const FoldPredictions& predicted);

}  // namespace fogdrift::tune
