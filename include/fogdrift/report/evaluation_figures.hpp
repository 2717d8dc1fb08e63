// A user's own evaluation drawn (docs/compensation.md, "Figures"): what `fogdrift evaluate
// --figures DIR` and Python's fogdrift.evaluate(figures=DIR) write, as PNG for people and JSON
// for machines (figure.hpp), from an evaluation made with EvaluationOptions::series.
//
//   PREFIXrecordings       a panel per recording: the drift target raw (the output less its
//                          reference) and compensated by the model and by the line in T, against
//                          minutes since power-on
//   PREFIXresidual_vs_T    what the model and the line leave, against the temperature input, every
//                          recording's rows
//   PREFIXregion           the held-out rows over the training region: the temperature input
//                          against its rate, the guard's prototypes (the training rows'
//                          summary) beside each recording's rows, the training ranges dashed
// PREFIX is "" for a file of one gyro_dph model, else the target column and "_".
#pragma once

#include <string>
#include <vector>

#include "fogdrift/eval/evaluation.hpp"
#include "fogdrift/report/figure.hpp"

namespace fogdrift::report {

/// The figures of one axis's evaluation; throws std::invalid_argument when it was made without
/// EvaluationOptions::series. A figure whose inputs the model lacks (no temperature input, no
/// rate) is left out.
std::vector<Figure> evaluation_figures(const eval::Evaluation& evaluation,
                                       const TrainingBaselines& baselines,
                                       const std::vector<std::string>& feature_names,
                                       const std::string& prefix);

}  // namespace fogdrift::report
