// The Gaussian process's trainer (trainer.hpp; docs/gp.md): hyperparameters by the grouped
// folds through a search (gp_search.hpp) or by the marginal likelihood of the rows kept
// (gp.hpp, {gp_fit}). Its fitness is the RMSE over the folds of a GP with those hyperparameters
// fitted on each fold's training rows, as the held-out report scores it.
#pragma once

#include <array>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/regress/gp.hpp"
#include "fogdrift/train/trainer.hpp"

namespace fogdrift {

struct GpTrainer {
  using Regressor = Gp;  ///< what it fits
  using Options = GpOptions;
  /// Its part of the summary (trainer_record.hpp): the fit's search.
  struct Record {
    GpSummary fit;
  };
  /// {gp_points}, {gp_fit}, {gp_kernel}.
  static OptionTable<Options> option_table();
  static constexpr std::string_view kName = "gp";
  static constexpr std::array<MethodName, 1> kMethods = {{
      {"gp", Search::own,
       "a Gaussian process, its length scale and noise searched by ssa unless {search} names "
       "another (docs/gp.md)"},
  }};
  /// The cv fit: own is ssa, none is refused; the likelihood fit: own only.
  static Search search(Search requested, const TrainOptions& options);
  /// The GP's options, and the search's budget for the cv fit.
  static void validate(const TrainOptions& options);
  static Trained train(const TrainContext& context);
};

/// {"gp": {points, log_likelihood, iterations, evaluations, fold_fits, raced, converged}}.
nlohmann::ordered_json to_json(const GpTrainer::Record& record);

}  // namespace fogdrift
