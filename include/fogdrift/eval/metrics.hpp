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
// Beside them, what a user of an uncompensated gyro would see: MAE before = mean |y| (the drift
// with its turn-on offset), and pooled STDs over every row of every recording, offsets between
// recordings kept (for one recording they equal the STDs).
//
// Where north-finding needs it (docs/field.md), with r the output before (y) or after (y − ŷ)
// compensation, less its mean over the recording:
//   start-up residual     RMS of r over the first startup_s after power-on: the drift a finding
//                         made in the first minutes still sees
//   opposite difference   RMS over every start time t of  mean r[t, t + P) − mean r[t + 2P, t + 3P)
//                         with P = position_s: the difference between two opposite positions of
//                         a four-position finding, the part of the drift the azimuth sees
//                         (δψ ≈ difference / (2 Ω_ie cos φ), docs/simulator.md §5)
// Both pool as the root mean square over the recordings they apply to. They do not apply, and are
// NaN (kNotApplicable; null in JSON, "n/a" in print), when a recording starts startup_s or more
// after power-on (no start-up residual), or when its rows are more than 2·position_s apart or
// it is shorter than three positions (no opposite difference).
// The fields are named in °/h, a gyro's unit; a model of another target (target.hpp) gives them
// in that target's unit, and its JSON names them so (evaluation.hpp).
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "fogdrift/model/dataset.hpp"

namespace fogdrift::eval {

struct CompensationMetrics {
  std::size_t rows = 0;
  double mae_dph = 0;
  double rmse_dph = 0;
  double std_before_dph = 0;                       ///< the denoised, uncompensated drift
  double std_after_dph = 0;                        ///< the compensated output
  double mae_before_dph = 0;                       ///< mean |y|: the error with no compensation
  double mean_before_dph = 0, mean_after_dph = 0;  ///< mean of y and of y − ŷ
  /// Sample STD over every row pooled, offsets between recordings kept.
  double pooled_std_before_dph = 0, pooled_std_after_dph = 0;
  /// Start-up residual and opposite-position difference, before and after (0 when the metrics
  /// come without times: compensation_metrics(), or a dataset without time_s).
  double startup_before_dph = 0, startup_after_dph = 0;
  double opposite_before_dph = 0, opposite_after_dph = 0;
};

/// A metric that does not apply to the data (see the file comment).
inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

/// The windows of the north-finding metrics.
struct FindingWindows {
  double startup_s = 300.0;  ///< the first minutes after power-on, s
  double position_s = 90.0;  ///< time per four-position position, s (the paper's protocol)
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
                                                       std::span<const double> predicted_dph,
                                                       const FindingWindows& windows = {});

/// The start-up residual and opposite difference of one recording's output `r` at times
/// `time_s` (uniformly spaced): {startup, opposite}, °/h. The opposite difference is 0 when the
/// recording is shorter than 3 positions.
std::pair<double, double> finding_metrics(std::span<const double> time_s, std::span<const double> r,
                                          const FindingWindows& windows = {});

}  // namespace fogdrift::eval
