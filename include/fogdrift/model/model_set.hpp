// Every axis in one model file: a model set holds one compensation model per gyro a unit has,
// each with its own target column, search and novelty guard (docs/logs.md, "Every axis").
//
// The file is the models' own files, verbatim, in a list:
//   {"format": "fogdrift-model-set", "version": 1, "targets": ["gyro_dph", "gyro_y_dph"],
//    "models": [ <a model file>, <a model file> ]}
// so each model keeps its checksum (model.hpp), and any one can be cut out and loaded alone.
// A plain model file reads as a set of one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/model/model.hpp"

namespace fogdrift {

inline constexpr int kModelSetVersion = 1;

struct ModelSet {
  std::vector<CompensationModel> models;  ///< one per target column, in the order trained

  /// The target columns, in order (dataset.target_column of each model).
  std::vector<std::string> targets() const;
  /// The thermometer columns any model reads, each once: temp_fog_degc, temp_acc1_degc,
  /// temp_acc2_degc, then each further one in the order the models name them (the arguments of
  /// the set's C update, the columns `stream` reads).
  std::vector<std::string> thermometer_columns() const;
  /// The model for `target`; nullptr when the set has none.
  const CompensationModel* find(std::string_view target) const;
};

/// The set's text. Throws OptionError("targets") when it is empty or two models share a target.
std::string to_json(const ModelSet& set);
void save(const ModelSet& set, const std::filesystem::path& path);  ///< atomic

/// Parses a model set, or a single model file as a set of one; `source` names it in errors.
/// Every model is checked as compensation_model_from_json checks a file (its checksum
/// included); a list of targets that does not match the models' is an InputError.
ModelSet model_set_from_json(const std::string& text, const std::string& source,
                             const ModelLoadOptions& options = {});
ModelSet load_model_set(const std::filesystem::path& path, const ModelLoadOptions& options = {});

/// The one model a command that compensates one gyro uses: the set's model for `target`, or,
/// without a target, its only model. Throws OptionError(`option`) naming the targets when the
/// set has no such model, or several and no target was given.
const CompensationModel& choose_model(const ModelSet& set, const std::optional<std::string>& target,
                                      const std::string& option = "target");

}  // namespace fogdrift
