// What a model is judged against, kept in its file (docs/compensation.md, "Judging a model").
//
// A compensation model earns its place only where it beats what needs no model. So `train` keeps
// two facts of the training rows beside the regressor, and `evaluate` uses them on any recording:
//   input ranges   each input's smallest and largest value over the training rows, in its own
//                  unit (°C, °C/s, ...): a held-out recording outside them is extrapolation,
//                  reported in the user's units beside the guard's novelty;
//   line in T      the least-squares line  y = a + b·T  of the drift in one temperature input
//                  (T_fog_degc where the model has it, else its first T_<name>_degc), fitted on
//                  the training rows in the target's unit: the simplest model that knows the
//                  temperature, and the bar a model must clear.
// Files written before these were kept load without them; `evaluate` then says the line and
// the ranges are not known (retrain to get them).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/model/dataset.hpp"

namespace fogdrift {

/// y = intercept + slope · x[input], in the target's unit.
struct BaselineLine {
  std::string input;  ///< the feature's name, "T_fog_degc"
  double intercept = 0;
  double slope = 0;  ///< the target's unit per °C
};

struct TrainingBaselines {
  std::vector<double> input_min, input_max;  ///< per feature, own units; empty: not known
  std::optional<BaselineLine> line;          ///< none: the model has no temperature input

  bool has_ranges() const { return !input_min.empty(); }
};

/// The temperature input a line is fitted in, and figures drawn against: T_fog_degc when among
/// `feature_names`, else the first T_<name>_degc; empty when there is none.
std::string temperature_input_of(std::span<const std::string> feature_names);

/// The ranges and the line of a training dataset (see the file comment). The line is absent
/// when no feature is a temperature T_<name>_degc, or when that feature does not vary.
TrainingBaselines fit_training_baselines(const Dataset& data);

/// The line's drift at every row of `data` (whose features are the model's, `feature_names`).
/// Throws InputError naming `source` when the line's input is not among them.
std::vector<double> line_drift(const BaselineLine& line, const Dataset& data,
                               const std::string& source);

/// How far the rows of one recording lie outside the training ranges, per input.
struct InputExtrapolation {
  std::string input;  ///< the feature's name
  double train_min = 0, train_max = 0;
  double min = 0, max = 0;      ///< the recording's own range
  double share_outside = 0;     ///< of its rows, below train_min or above train_max
  double farthest_outside = 0;  ///< the largest distance outside, in the input's unit (0 inside)
};

/// Per input, for the rows of `data` in `rows`.
std::vector<InputExtrapolation> extrapolation(const TrainingBaselines& baselines,
                                              const Dataset& data,
                                              std::span<const std::size_t> rows);

/// The share of `rows` with any input outside its training range.
double share_outside_any(const TrainingBaselines& baselines, const Dataset& data,
                         std::span<const std::size_t> rows);

}  // namespace fogdrift
