// The registry of methods (trainer.hpp): each registered trainer with the regressor it fits. The
// one list is src/train/registry.cpp, `Registry<…>` over the trainers in `--method`'s order; it
// defines trainer_entries() here and regressor_entries() (regress/regressors.hpp), so the
// methods train knows and the regressors a model file can hold come from one line each. Adding a
// regressor is its own files, their tests, and two lines there (docs/architecture.md, "Adding a
// regressor").
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "fogdrift/regress/regressors.hpp"
#include "fogdrift/train/trainer.hpp"

namespace fogdrift {

/// A trainer's parts, as the registry calls them.
struct TrainerEntry {
  std::string_view name;
  std::span<const MethodName> methods;
  Search (*search)(Search requested, const TrainOptions& options);
  void (*validate)(const TrainOptions& options);
  Trained (*train)(const TrainContext& context);
  std::string_view regressor;  ///< the model file's type of what it fits
  /// Its own options as options of TrainOptions (T::option_table(), lifted onto
  /// TrainOptions::trainers): train's table appends them.
  OptionTable<TrainOptions> (*options)();
};

/// The entry of trainer T; T that is not a Trainer does not compile.
template <Trainer T>
constexpr TrainerEntry entry_of() {
  return {T::kName, T::kMethods, &T::search, &T::validate, &T::train, T::Regressor::kType, [] {
            return lifted<TrainOptions>(
                T::option_table(),
                [](auto& o) -> auto& { return o.trainers.template get<typename T::Options>(); });
          }};
}

/// The registry's tables for the trainers T…, in their order: theirs and their regressors'.
template <Trainer... T>
struct Registry {
  static constexpr std::array<TrainerEntry, sizeof...(T)> trainers = {entry_of<T>()...};
  static constexpr std::array<RegressorEntry, sizeof...(T)> regressors = {
      regressor_entry_of<typename T::Regressor>()...};
};

/// Every registered trainer, in `--method`'s order (defined by src/train/registry.cpp).
std::span<const TrainerEntry> trainer_entries();

/// The trainer named `name`; OptionError(option) if none is.
const TrainerEntry& trainer(std::string_view name, std::string_view option = "method");

}  // namespace fogdrift
