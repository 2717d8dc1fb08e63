#include "fogdrift/train/poly_trainer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

Search PolyTrainer::search(Search requested, const TrainOptions&) {
  if (requested != Search::own && requested != Search::none)
    throw OptionError("search",
                      "poly has no search: cross-validation picks its degree (auto or none)");
  return Search::own;
}

OptionTable<PolyTrainer::Options> PolyTrainer::option_table() {
  return {whole_option<Options>(
      {"max_degree",
       "--max-degree",
       {},
       "",
       between(1, 6),
       "poly: highest degree tried",
       {"degree"}},
      [](auto& o) -> auto& { return o.max_degree; })};
}

void PolyTrainer::validate(const TrainOptions& options) {
  const std::size_t max_degree = options.trainers.get<Options>().max_degree;
  if (max_degree < 1 || max_degree > 6)
    throw OptionError("degree", fmt::format("{} is outside 1 … 6", max_degree));
}

Trained PolyTrainer::train(const TrainContext& c) {
  Trained out;
  TrainSummary& s = out.summary;
  const auto folds = tune::grouped_folds(c.data, c.options.tune.cv);
  const std::vector<tune::ScaledSplit> splits = tune::scale_splits(c.data, folds);
  // Degrees with more terms than a fold has training rows cannot be fitted: the search stops
  // below them.
  std::size_t min_rows = c.data.rows;
  for (const auto& sp : splits) min_rows = std::min(min_rows, sp.train.rows);
  std::vector<double> cv_rmse;  // of degree 1, 2, …
  std::size_t best = 1;
  auto best_predictions = std::make_shared<tune::FoldPredictions>();
  const std::size_t max_degree = c.options.trainers.get<Options>().max_degree;
  for (std::size_t degree = 1; degree <= max_degree; ++degree) {
    if (degree > 1 && monomials(c.data.cols(), degree).size() / c.data.cols() > min_rows) break;
    tune::FoldPredictions predicted = tune::fold_predictions(
        splits, [degree](const Data& train) { return fit_poly(train, degree); });
    cv_rmse.push_back(tune::pooled_rmse(splits, predicted));
    if (degree == 1 || cv_rmse.back() < cv_rmse[best - 1]) {
      best = degree;
      *best_predictions = std::move(predicted);
    }
  }
  out.regressor = fit_poly(c.full.train, best);
  s.fitness = "cv";
  s.fitness_value = cv_rmse[best - 1];
  out.cv = describe_folds(folds);
  out.held_folds = folds;
  out.held_description = out.cv;
  // The held-out report splits the same folds the same way: the best degree's fits, reused.
  out.held_predict = [best_predictions](const tune::ScaledSplit&, std::size_t fold) {
    return (*best_predictions)[fold];
  };
  s.hyperparameters = {{"degree", static_cast<double>(best)}};
  s.record = TrainerRecord(Record{cv_rmse});
  return out;
}

nlohmann::ordered_json to_json(const PolyTrainer::Record& record) {
  nlohmann::ordered_json j;
  j["poly_cv_rmse_by_degree"] = record.cv_rmse_by_degree;
  return j;
}

}  // namespace fogdrift
