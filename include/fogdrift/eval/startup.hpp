// Start-up drift statistics of a static recording: how much the (smoothed) gyro output wanders
// during the powered window, and where its start-up dip lies (docs/method.md §1; paper Fig. 1,
// Table 2).
#pragma once

#include <cstddef>
#include <vector>

#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/io/recording.hpp"

namespace fogdrift::eval {

/// Centred moving average over `window` samples (odd; shrinks symmetrically at the ends).
std::vector<double> moving_average(const std::vector<double>& values, std::size_t window);

struct StartupStats {
  double std_dph = 0;           ///< sample STD of the smoothed output over the recording, °/h
  double peak_to_peak_dph = 0;  ///< max − min of the smoothed output, °/h
  double min_time_s = 0;        ///< time of the smoothed minimum, s since power-on
  double start_dph = 0;         ///< smoothed output at the first sample, minus the mean, °/h
  double end_dph = 0;           ///< smoothed output at the last sample, minus the mean, °/h
};

/// Statistics of `values` (e.g. gyro_dph, or a drift column) smoothed over `window` samples.
StartupStats startup_stats(const std::vector<double>& time_s, const std::vector<double>& values,
                           std::size_t window);

/// North-finding errors of every finding in `recording`, degrees (found − true, wrapped).
std::vector<double> northfind_errors_deg(const Recording& recording, double latitude_deg,
                                         double true_azimuth_deg,
                                         const SegmentationOptions& options = {});

/// The same with `drift_dph` (one value per sample) subtracted from the gyro first: a model's
/// compensation, or the simulator's true drift for the floor. Throws std::invalid_argument when
/// `drift_dph` has another length than the recording.
std::vector<double> northfind_errors_deg(const Recording& recording,
                                         const std::vector<double>& drift_dph, double latitude_deg,
                                         double true_azimuth_deg,
                                         const SegmentationOptions& options = {});

}  // namespace fogdrift::eval
