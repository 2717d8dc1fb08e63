// A model beside what needs no model (docs/compensation.md, "Judging a model").
//
// On the rows of one recording, with y the drift target (the output less the recording's
// reference, the same basis before and after) and ŷ the model's drift, four predictions of y:
//   raw             0: no compensation; its RMSE is √mean y²
//   recording mean  ȳ, the recording's own mean: an offset known after the fact; its RMSE is the
//                   STD of y, the variation no constant removes
//   line in T       the training rows' line in one temperature (baselines.hpp)
//   model           ŷ
// and, for raw, line and model, the sample STD of what is left, y − prediction, as Table 2's: the
// variation within the recording a four-position north-finding sees (the recording mean leaves
// the raw STD).
//
// Harm. The model makes a recording worse when its RMSE exceeds raw's, when it leaves more
// variation than raw (STD after > STD before: worse than the recording mean), or when its RMSE
// exceeds the line's. It is no better than its baselines when it removes less than
// kNoBetterShare of the variation raw leaves (STD) or of the line's RMSE.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/eval/metrics.hpp"

namespace fogdrift::eval {

/// A model that improves on a baseline by less than this share is no better than it.
inline constexpr double kNoBetterShare = 0.05;

struct BaselineComparison {
  std::size_t rows = 0;
  double raw_rmse = 0, mean_rmse = 0, line_rmse = kNotApplicable, model_rmse = 0;
  double raw_std = 0, line_std = kNotApplicable, model_std = 0;
  /// The rules of harm the model breaks here, each a sentence with its numbers ({unit}: the
  /// target's unit symbol, for the front end to fill in); empty when it does no harm.
  std::vector<std::string> harms;
  /// The baselines it is no better than ("the recording mean", "the line in T_fog_degc"), when it
  /// does no harm.
  std::vector<std::string> no_better_than;
};

/// On one recording's rows: `y` the target, `model` ŷ, `line` the line's drift (empty: no line,
/// whose input is then `line_input` empty too).
BaselineComparison compare_with_baselines(std::span<const double> y, std::span<const double> model,
                                          std::span<const double> line,
                                          const std::string& line_input);

/// Over several recordings: RMSEs pooled over every row, STDs the root mean square of the
/// recordings' (as Table 2), and the rules applied to those.
BaselineComparison pool(std::span<const BaselineComparison> recordings,
                        const std::string& line_input);

}  // namespace fogdrift::eval
