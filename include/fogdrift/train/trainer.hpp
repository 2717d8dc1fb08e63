// One shape for every way of training a regressor (docs/architecture.md, "Adding a regressor"). A
// trainer is a type T with
//   T::Regressor                the regressor it fits (a Regressor, base/regressor.hpp)
//   T::Options                  its own options, kept in TrainOptions::trainers by their type
//   T::option_table()           their table (base/option_table.hpp): train's flags, Python's
//                               and Octave's keywords and docs/options.md take them from it
//   T::kName                    its name, the method's when it has no search ("svr", "gp")
//   T::kMethods                 the method names it answers to, each with the search it implies
//                               and what it is (method.hpp); one of them implies Search::own
//   T::search(requested, o)     the search it runs for `requested`: own made its own, or
//                               OptionError("search") for one it has no use for
//   T::validate(o)              what can be checked of its options without data: OptionError
//                               naming the field
//   T::train(context)           its regressor fitted on the context's rows: the fitness, the
//                               hyperparameters and the folds the held-out report refits it on
// train() (train.hpp) does what is the same for all: method and search made one, the scalers,
// the novelty guard, the held-out report, the provenance. The registry (src/train/registry.cpp)
// lists the trainers and checks each against the concept: a trainer that lacks a part does not
// compile.
#pragma once

#include <concepts>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/train/train.hpp"

namespace fogdrift {

/// What a trainer is given: the training rows, all of them standardised, and the options with
/// method and search made one (resolved()).
struct TrainContext {
  const Dataset& data;
  const tune::ScaledSplit& full;  ///< every row, with the scalers the model keeps by default
  const TrainOptions& options;
};

/// What a trainer makes of them.
struct Trained {
  AnyRegressor regressor;
  /// The scalers the regressor was fitted with, where not every row's (bp keeps its fold's).
  std::optional<Standardizer> x_scaler, y_scaler;
  /// Its parts of the summary: fitness, fitness_value, hyperparameters, the record, and for a
  /// searched SVR the tuning and the boxes; train() fills the rest.
  TrainSummary summary;
  std::string cv;                              ///< Provenance::cv
  std::size_t population = 0, iterations = 0;  ///< the optimizer's budget, when searched
  std::string search;                          ///< Provenance::search, when not in the name
  /// The folds the held-out report scores the regressor on, how they are described there, and
  /// the regressor refitted on one of them (held_out.hpp). No folds: no report.
  std::vector<tune::Fold> held_folds;
  std::string held_description;
  FoldPredictor held_predict;
};

template <class T>
concept Trainer = Regressor<typename T::Regressor> &&
    requires(Search s, const TrainOptions& o, const TrainContext& c) {
  { T::kName } -> std::convertible_to<std::string_view>;
  { T::option_table() } -> std::same_as<OptionTable<typename T::Options>>;
  {std::span<const MethodName>(T::kMethods)};
  { T::search(s, o) } -> std::same_as<Search>;
  { T::validate(o) } -> std::same_as<void>;
  { T::train(c) } -> std::same_as<Trained>;
};

/// The optimizer of a search (ssa, pso, gwo).
opt::Algorithm optimizer_of(Search search);

/// "whole initial temperatures (3 folds)": how held-out folds are described in models and
/// reports.
std::string describe_folds(std::span<const tune::Fold> folds);

}  // namespace fogdrift
