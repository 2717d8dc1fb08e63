// The polynomial's trainer on its own (poly_trainer.hpp): no search, the degree the folds pick,
// and the RMSE of every degree tried in its record.
#include "fogdrift/train/poly_trainer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift {
namespace {

TEST(PolyTrainer, PicksTheDegreeTheFoldsScoreBest) {
  const TrainOptions given;
  EXPECT_EQ(PolyTrainer::search(Search::none, given), Search::own);
  EXPECT_THROW(PolyTrainer::search(Search::gwo, given), OptionError);

  const Dataset d = test::synthetic();
  std::vector<std::size_t> rows(d.rows);
  std::iota(rows.begin(), rows.end(), 0);
  const tune::ScaledSplit full = tune::scale_split(d, rows, {});
  TrainOptions o;
  o.method = Method::poly;
  o.trainers.get<PolyTrainer::Options>().max_degree = 3;
  o.tune.cv = {tune::CvScheme::repetition};
  const Trained t = PolyTrainer::train({d, full, o});
  ASSERT_NE(t.summary.record.get<PolyTrainer::Record>(), nullptr);
  const std::vector<double> rmse = t.summary.record.get<PolyTrainer::Record>()->cv_rmse_by_degree;
  EXPECT_EQ(t.summary.record.json()["poly_cv_rmse_by_degree"].get<std::vector<double>>(), rmse);
  ASSERT_EQ(rmse.size(), 3u);
  const auto best = std::min_element(rmse.begin(), rmse.end());
  EXPECT_EQ(t.summary.hyperparameters[0].second, static_cast<double>(best - rmse.begin() + 1));
  EXPECT_EQ(t.summary.fitness_value, *best);
  EXPECT_EQ(t.regressor.get<Poly>().degree, static_cast<std::size_t>(best - rmse.begin() + 1));
  EXPECT_EQ(t.held_description, t.cv);
  o.trainers.get<PolyTrainer::Options>().max_degree = 7;
  EXPECT_THROW(PolyTrainer::validate(o), OptionError);
}

}  // namespace
}  // namespace fogdrift
