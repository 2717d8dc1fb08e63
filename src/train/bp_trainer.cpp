#include "fogdrift/train/bp_trainer.hpp"

#include <fmt/format.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

Search BpTrainer::search(Search requested, const TrainOptions&) {
  if (requested != Search::own && requested != Search::none)
    throw OptionError("search",
                      "bp has no search: it trains by Adam with early stopping (auto "
                      "or none)");
  return Search::own;
}

OptionTable<BpTrainer::Options> BpTrainer::option_table() {
  return {whole_option<Options>(
      {"hidden", "--hidden", {}, "", between(1, 1000), "bp: hidden tanh units", {}},
      [](auto& o) -> auto& { return o.hidden; })};
}

void BpTrainer::validate(const TrainOptions& options) {
  fogdrift::validate(options.trainers.get<Options>());
}

Trained BpTrainer::train(const TrainContext& c) {
  const TrainOptions& options = c.options;
  Trained out;
  TrainSummary& s = out.summary;
  // Early stopping on the held-out recordings of the last grouped fold. BP is not refitted
  // after it, so what the fold holds out is never trained on: it must be like the rest. Whole
  // temperatures, or a repetition that is a start-up condition of its own (a protocol of mixed
  // start-ups), would stop it on data it cannot fit (measured: best epoch 2). So unless
  // repetition or recording folds are asked for, it holds out a third of the recordings, dealt
  // across temperatures and repetitions.
  tune::CvOptions stop = options.tune.cv;
  if (stop.scheme == tune::CvScheme::temperature || stop.scheme == tune::CvScheme::automatic)
    stop = {tune::CvScheme::recording, 3};
  const auto folds = tune::grouped_folds(c.data, stop);
  const tune::Fold& f = folds.back();
  const tune::ScaledSplit split = tune::scale_split(c.data, f.train_rows, f.test_rows);
  MlpOptions mo = options.trainers.get<Options>();
  mo.seed = options.tune.optimizer.run.seed;
  const MlpFit fit = fit_mlp(split.train, split.test, mo);
  out.x_scaler = split.x_scaler;
  out.y_scaler = split.y_scaler;
  out.regressor = fit.model;
  s.fitness = "validation";
  s.fitness_value = fit.summary.validation_rmse;
  out.cv = fmt::format("early stopping on {}", f.name);
  out.held_folds = {f};
  out.held_description = f.name;
  const Mlp net = fit.model;  // trained on this fold's rows, with its scalers
  out.held_predict = [net](const tune::ScaledSplit& split, std::size_t) {
    std::vector<double> predicted(split.test.rows);
    for (std::size_t r = 0; r < split.test.rows; ++r) predicted[r] = net.predict(split.test.row(r));
    return predicted;
  };
  s.hyperparameters = {{"hidden", static_cast<double>(mo.hidden)},
                       {"learning_rate", mo.learning_rate},
                       {"epochs", static_cast<double>(fit.summary.best_epoch)}};
  s.record = TrainerRecord(Record{fit.summary});
  return out;
}

nlohmann::ordered_json to_json(const BpTrainer::Record& record) {
  const MlpSummary& f = record.fit;
  nlohmann::ordered_json j;
  j["bp"] = {{"epochs", f.epochs},
             {"best_epoch", f.best_epoch},
             {"early_stopped", f.status == MlpStatus::early_stopped},
             {"train_rmse", f.train_rmse}};
  return j;
}

}  // namespace fogdrift
