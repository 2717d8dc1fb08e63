// How well a model compensates the drift (paper Table 2): the error of the predicted drift
// against the target, and the spread of the output before and after compensation.
//
// For one recording with target drift y (the denoised gyro minus the input rate, at the block
// rate; dataset.hpp) and prediction ŷ:
//   MAE  = mean |ŷ − y|                 RMSE = √mean (ŷ − y)²
//   STD before = sample STD of y        STD after = sample STD of y − ŷ (the compensated output)
// A recording's constant offset does not count in the STDs: Table 2's STD is the zero-bias
// stability over the powered window. Over several recordings, MAE and RMSE pool every row and
// the STDs are the root mean square of the per-recording STDs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "fogdrift/dataset.hpp"

namespace fogdrift::eval {

struct CompensationMetrics {
  std::size_t rows = 0;
  double mae_dph = 0;
  double rmse_dph = 0;
  double std_before_dph = 0;  ///< the denoised, uncompensated drift
  double std_after_dph = 0;   ///< the compensated output
};

/// Metrics of one recording. Throws std::invalid_argument for sizes that differ, and needs at
/// least two rows for the STDs (0 with one row).
CompensationMetrics compensation_metrics(std::span<const double> target_dph,
                                         std::span<const double> predicted_dph);

/// Pools per-recording metrics as described above (rows weight MAE and RMSE). Recordings without
/// rows do not count.
CompensationMetrics pool(std::span<const CompensationMetrics> recordings);

/// Metrics of every recording (group) of `data`, in data.groups order, from predictions of its
/// rows; a group without rows (Dataset::select_groups keeps every group) has rows = 0.
std::vector<CompensationMetrics> metrics_per_recording(const Dataset& data,
                                                       std::span<const double> predicted_dph);

}  // namespace fogdrift::eval
