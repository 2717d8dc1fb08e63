// A recording file compensated: every column as it was written, then each axis's drift,
// compensated reading, novelty and guard weight (docs/formats.md), written atomically. What
// `fogdrift compensate` and Octave's fogdrift.compensate write.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "fogdrift/model/guard.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"

namespace fogdrift {

/// The columns compensate and stream add for one axis: drift_dph, gyro_comp_dph, novelty and
/// guard_weight for gyro_dph; Target::drift_column, Target::compensated_column, novelty_AXIS
/// and guard_weight_AXIS for another (drift_y_dph, gyro_y_comp_dph, novelty_y, ... for
/// gyro_y_dph; drift_accel_x_g, accel_x_comp_g, novelty_accel_x, ... for accel_x_g).
std::vector<std::string> compensated_columns(const std::string& target);

/// One axis of a compensated file.
struct CompensatedAxis {
  const CompensationModel* model = nullptr;  ///< into the set given
  std::vector<std::string> columns;          ///< the columns added (compensated_columns)
  RecordingPrediction prediction;
  std::vector<double> reading;  ///< the target's values as recorded (target_values); the
                                ///< compensated column is reading − prediction.drift_dph
  NoveltySummary novelty;
};

/// How a file is compensated: `fogdrift compensate`'s options, and those of Octave's
/// Model.predict and Model.compensate (compensate_option_table.hpp).
struct CompensateOptions {
  /// Reduce the correction where the inputs are novel to the model (guard.hpp).
  bool guarded = true;
};

/// Compensates `input` with every model of `set` and writes `output` (the input's fields copied
/// as they are, row by row, then four columns per axis). InputError when the input already has
/// one of the columns it would add, or gains or loses rows while it is read; nothing is
/// written then. The caller checks that `output` is not an input (run_files.hpp).
std::vector<CompensatedAxis> compensate_file(const ModelSet& set,
                                             const std::filesystem::path& input,
                                             const std::filesystem::path& output,
                                             const CompensateOptions& options);

}  // namespace fogdrift
