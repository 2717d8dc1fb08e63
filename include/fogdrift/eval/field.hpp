// North-finding where the field needs it (docs/field.md): a campaign's start-ups found raw, with
// the simulator's true drift subtracted (the floor no model can pass, when the recordings carry
// drift_true_dph), and compensated; and the share of the removable error a compensation removes,
//
//     removed = (raw² − compensated²) / (raw² − floor²)
//
// on the mean RMSEs over the start-ups: 1 is perfect compensation, 0 none, below 0 worse than
// none. Table 2 cannot show this (it tests on calibration's own protocol); Table 3 under every
// start-up condition can.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/recording.hpp"

namespace fogdrift::eval {

/// (raw² − comp²) / (raw² − floor²), the share of the removable error removed, from RMSEs; NaN
/// when any is not finite or raw ≤ floor (nothing removable).
double share_removed(double raw_deg, double comp_deg, double floor_deg);

/// 1 − Σ(comp − floor)² / Σ(raw − floor)² over paired findings, azimuth errors in degrees: the
/// share of the error the drift itself causes that a compensation removes (docs/field.md,
/// "Finding by finding"). Each finding is compared with itself with the true drift subtracted,
/// so the gyro noise the three share cancels, where share_removed() keeps a cross term of that
/// noise with the drift; north-finding's error is linear in the small biases it sees. NaN when
/// the drift causes no error or a value is not finite; std::invalid_argument when the three
/// differ in length.
double drift_error_removed(std::span<const double> raw_deg, std::span<const double> comp_deg,
                           std::span<const double> floor_deg);

/// Predicted drift at every sample of a recording, °/h (e.g. CompensationModel::predict_dph).
using DriftOf = std::function<std::vector<double>(const Recording&)>;

struct FieldRecording {
  std::string file;
  double initial_temp_degc = 0;
  double raw_rmse_deg = 0;    ///< RMSE of the recording's findings, uncompensated
  double floor_rmse_deg = 0;  ///< with drift_true_dph subtracted; NaN without that column
  double comp_rmse_deg = 0;   ///< with the drift subtracted; NaN without a drift
  /// The findings' azimuth errors, one per finding, as the three RMSEs above pool them; floor
  /// and compensated are empty where their RMSE is NaN.
  std::vector<double> raw_error_deg, floor_error_deg, comp_error_deg;
};

struct FieldSummary {
  std::vector<FieldRecording> recordings;  ///< the northfind recordings, in campaign order
  std::size_t worse_than_raw = 0;          ///< recordings whose compensated RMSE exceeds raw

  double raw_mean_rmse_deg() const;    ///< mean over recordings, as the paper's Table 3 "mean"
  double floor_mean_rmse_deg() const;  ///< NaN if any recording lacks the true drift
  double comp_mean_rmse_deg() const;   ///< NaN without a drift
  /// (raw² − comp²) / (raw² − floor²) on the means; NaN when either is unknown or raw ≤ floor.
  double share_removed() const;
  /// drift_error_removed() over every finding of every recording; NaN when any recording lacks
  /// the floor or the drift.
  double drift_error_removed() const;
  /// Appends another summary's recordings (another seed of the same experiment).
  void accumulate(const FieldSummary& other);
};

/// Finds north on every `northfind` recording of `campaign` (recordings[i] is the file of
/// campaign.recordings[i]). `drift` may be empty (raw and floor only). Throws InputError naming
/// campaign.json when a northfind recording lacks its true azimuth.
FieldSummary field_summary(const Campaign& campaign, const std::vector<Recording>& recordings,
                           const DriftOf& drift);

}  // namespace fogdrift::eval
