// The BP network's trainer (trainer.hpp; docs/method.md §3): a one-hidden-layer tanh network
// (mlp.hpp), early-stopped on the held-out recordings of the last grouped fold. It is not
// refitted, so unless repetition or recording folds are asked for it holds out a third of the
// recordings dealt across temperatures and repetitions, which keeps every temperature and
// start-up condition in training. Its fitness is the validation RMSE.
#pragma once

#include <array>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/train/trainer.hpp"

namespace fogdrift {

struct BpTrainer {
  using Regressor = Mlp;       ///< what it fits
  using Options = MlpOptions;  ///< its seed is set from the search's (tune.optimizer.run.seed)
  /// Its part of the summary (trainer_record.hpp): the network's fit.
  struct Record {
    MlpSummary fit;
  };
  /// {hidden}.
  static OptionTable<Options> option_table();
  static constexpr std::string_view kName = "bp";
  static constexpr std::array<MethodName, 1> kMethods = {{
      {"bp", Search::own,
       "a one-hidden-layer tanh network (the paper's BP), early-stopped on held-out "
       "recordings"},
  }};
  /// own and none; any other is refused: it trains by Adam with early stopping.
  static Search search(Search requested, const TrainOptions& options);
  static void validate(const TrainOptions& options);  ///< the network's (validate(MlpOptions))
  static Trained train(const TrainContext& context);
};

/// {"bp": {epochs, best_epoch, early_stopped, train_rmse}}.
nlohmann::ordered_json to_json(const BpTrainer::Record& record);

}  // namespace fogdrift
