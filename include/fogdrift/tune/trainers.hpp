// The registry of trainers (trainer.hpp): the methods `train` knows. Adding a regressor is its
// own file pairs (the regressor in model/, its trainer in tune/), their tests, its line in
// AnyRegressor (regressors.hpp) and its line in kTrainers below; its options are a field of
// TrainOptions and entries of train's option table (train_option_table.cpp).
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "fogdrift/tune/bp_trainer.hpp"
#include "fogdrift/tune/gp_trainer.hpp"
#include "fogdrift/tune/poly_trainer.hpp"
#include "fogdrift/tune/svr_trainer.hpp"

namespace fogdrift {

/// A trainer's parts, as the registry calls them.
struct TrainerEntry {
  std::string_view name;
  std::span<const MethodName> methods;
  Search (*search)(Search requested, const TrainOptions& options);
  void (*validate)(const TrainOptions& options);
  Trained (*train)(const TrainContext& context);
};

/// The entry of trainer T; T that is not a Trainer does not compile.
template <Trainer T>
constexpr TrainerEntry entry_of() {
  return {T::kName, T::kMethods, &T::search, &T::validate, &T::train};
}

/// In the order `--method` lists their names.
inline constexpr std::array kTrainers = {entry_of<SvrTrainer>(), entry_of<BpTrainer>(),
                                         entry_of<PolyTrainer>(), entry_of<GpTrainer>()};

/// The trainer named `name`; OptionError(option) if none is.
const TrainerEntry& trainer(std::string_view name, std::string_view option = "method");

}  // namespace fogdrift
