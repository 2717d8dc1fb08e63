// The classical baseline's trainer (trainer.hpp): a polynomial in the features (poly.hpp) of
// degree 1 … its max_degree option, the degree chosen by the RMSE over the grouped folds
// and the polynomial refitted on every training row. Its fitness is that RMSE.
#pragma once

#include <array>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/regress/poly.hpp"
#include "fogdrift/train/trainer.hpp"

namespace fogdrift {

struct PolyTrainer {
  using Regressor = Poly;  ///< what it fits
  struct Options {
    std::size_t max_degree = 3;  ///< highest degree tried, 1 … 6
  };
  /// Its part of the summary (trainer_record.hpp): the folds' RMSE of each degree tried.
  struct Record {
    std::vector<double> cv_rmse_by_degree;  ///< degree 1 first
  };
  /// {max_degree}.
  static OptionTable<Options> option_table();
  static constexpr std::string_view kName = "poly";
  static constexpr std::array<MethodName, 1> kMethods = {{
      {"poly", Search::own, "a polynomial of the degree cross-validation picks"},
  }};
  /// own and none; any other is refused: cross-validation picks its degree.
  static Search search(Search requested, const TrainOptions& options);
  static void validate(const TrainOptions& options);  ///< the degree, 1 … 6
  static Trained train(const TrainContext& context);
};

/// {"poly_cv_rmse_by_degree": [...]}.
nlohmann::ordered_json to_json(const PolyTrainer::Record& record);

}  // namespace fogdrift
