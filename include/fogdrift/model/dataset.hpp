// Modelling data assembled from recordings: inputs X (features.hpp), the drift target y, and the
// group of every row, so that cross-validation can hold out whole recordings (docs/method.md §2).
//
// Target (per recording, at the recording's rate, then block-averaged like the features):
//   y = denoised gyro_dph - input rate
// The input rate is, in order of preference: the manifest's reference for the target column;
// for a gyro, its input_rate_dph; for the FOG axis, the Earth-rate projection
// Omega_e cos(latitude) cos(true_azimuth + table_deg) (the table angle from the recording, 0 if
// it has none; a tilt adds Omega_e sin(latitude) sin(tilt), a constant the model's bias
// absorbs); otherwise the mean of the denoised channel, with a warning, because then the
// turn-on bias cannot be told from the input. Another target (target.hpp) is formed the same
// way in its own unit, its reference what it sensed (docs/logs.md, "Other targets").
//
// Standardisation statistics come from training rows only and travel with the model
// (Standardizer); a feature that is constant over the training data is an error.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/features/features.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/signal/denoise.hpp"

namespace fogdrift {

struct DatasetOptions {
  FeatureSpec features = default_feature_spec();
  FeatureOptions preprocessing;    ///< differentiator and block averaging
  bool denoise_target = true;      ///< wavelet-denoise the gyro before forming the target
  signal::DenoiseOptions denoise;  ///< used when denoise_target
  /// The channel the target is formed from: gyro_dph, another gyro axis a recording carries as
  /// a further channel (gyro_NAME_dph, docs/logs.md, "Every axis"), an accelerometer or a
  /// scale-factor channel (target.hpp).
  std::string target_column = "gyro_dph";
};

/// Where a group of rows came from.
struct GroupInfo {
  std::string file;  ///< recording path as given (manifest-relative for campaigns)
  Scenario scenario = Scenario::calibration;
  Role role = Role::train;
  int repetition = 1;
  double initial_temp_degc = 0;
  /// How y was formed: "reference", "input_rate", "earth_rate" or "mean".
  std::string target;
  /// What was subtracted (its mean over the recording), in the target's unit (°/h for a gyro).
  double reference = 0;
  /// Its first rows in the causal differentiator's warm-up (FeatureTable::warm_rows).
  std::size_t warm_rows = 0;
};

/// One recording with what is known about its input.
struct RecordingInput {
  Recording recording;
  GroupInfo info;                        ///< file, scenario, role, repetition, temperature
  std::optional<double> input_rate_dph;  ///< explicit input rate of every gyro axis, °/h
  /// Per target column, what that channel sensed, in its unit (CampaignEntry::references).
  std::map<std::string, double> references;
  std::optional<double> latitude_deg;  ///< with true_azimuth_deg: the Earth-rate projection
  std::optional<double> true_azimuth_deg;
};

struct Dataset {
  std::vector<std::string> feature_names;
  std::string feature_spec;  ///< FeatureSpec::to_string() of the spec used
  std::size_t rows = 0;
  std::vector<double> x;              ///< rows x feature_names.size(), row-major
  std::vector<double> y;              ///< drift target, the target's unit (°/h for a gyro)
  std::vector<double> time_s;         ///< block-centre time since power-on, s
  std::vector<std::size_t> group;     ///< per row, an index into groups
  std::vector<GroupInfo> groups;      ///< one per recording, in input order
  std::vector<std::string> warnings;  ///< e.g. a target formed by subtracting the mean

  std::size_t cols() const { return feature_names.size(); }
  std::span<const double> row(std::size_t i) const { return {x.data() + i * cols(), cols()}; }
  /// The rows of the given groups, in their original order.
  Dataset select_groups(std::span<const std::size_t> group_indices) const;
};

/// The target of one recording at its own rate, and how it was formed (GroupInfo::target and
/// reference filled in). Validates the denoise options against the recording length.
std::vector<double> drift_target(const RecordingInput& input, const DatasetOptions& options,
                                 GroupInfo& info, std::vector<std::string>& warnings);

/// Builds a dataset from recordings (features and target of each, concatenated), with the
/// default options when none are given.
Dataset build_dataset(const std::vector<RecordingInput>& inputs, const DatasetOptions& options);
Dataset build_dataset(const std::vector<RecordingInput>& inputs);

/// One recording of a campaign with what the manifest knows about it.
RecordingInput recording_input(const Campaign& campaign, const CampaignEntry& entry,
                               Recording recording);

/// The recordings of a campaign held in memory (`recordings` in manifest order) that are of
/// `scenario`, and of `role` if given, each with what the manifest knows about it. Throws
/// InputError naming the campaign when the two lists differ in length.
std::vector<RecordingInput> recording_inputs(const Campaign& campaign,
                                             std::span<const Recording> recordings,
                                             std::optional<Role> role,
                                             Scenario scenario = Scenario::calibration);

/// Memory a command that reads recordings and builds a dataset from them takes, per byte of
/// recording CSV, at its peak: measured on simulated campaigns of 7.5 to 60 MB
/// (docs/reliability.md, "Size limits"), with headroom.
inline constexpr std::uint64_t kMemoryPerCsvByte = 4;

/// Reads the campaign's recordings of `scenario` (and of `role`, if given); read errors name the
/// recording file, and a campaign without such recordings is an InputError naming campaign.json.
/// Before reading, throws ResourceError (memory.hpp) when kMemoryPerCsvByte times the size of
/// those files exceeds the memory available.
std::vector<RecordingInput> read_inputs(const Campaign& campaign, std::optional<Role> role,
                                        Scenario scenario = Scenario::calibration);

/// Reads the campaign's recordings of `scenario` (and of `role`, if given) and builds a dataset;
/// read errors name the recording file. (The default options are one object in the library, not
/// a temporary at each call: GCC 12 warns falsely, -Wmaybe-uninitialized, inside its strings.)
Dataset build_dataset(const Campaign& campaign, std::optional<Role> role, Scenario scenario,
                      const DatasetOptions& options);
Dataset build_dataset(const Campaign& campaign, std::optional<Role> role,
                      Scenario scenario = Scenario::calibration);

/// Per-column standardisation z = (v - mean) / scale, scale the sample standard deviation.
struct Standardizer {
  std::vector<std::string> names;
  std::vector<double> mean;
  std::vector<double> scale;

  /// Statistics of the columns of a row-major matrix. Throws OptionError("features", ...) naming
  /// a column that is constant (scale 0 or below 1e-12 of its mean's magnitude) or non-finite.
  static Standardizer fit(std::span<const double> x, std::size_t cols,
                          std::vector<std::string> names);
  void apply(std::span<double> x) const;   ///< in place, row-major rows of names.size()
  void invert(std::span<double> x) const;  ///< back to original units
};

}  // namespace fogdrift
