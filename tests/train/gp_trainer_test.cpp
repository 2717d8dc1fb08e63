// The Gaussian process's trainer on its own (gp_trainer.hpp): which searches each fit takes,
// and the search the model file says apart from the default.
#include "fogdrift/train/gp_trainer.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "fogdrift/base/error.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift {
namespace {

TEST(GpTrainer, TheCvFitIsSearchedTheLikelihoodIsNot) {
  TrainOptions o;
  EXPECT_EQ(GpTrainer::search(Search::own, o), Search::ssa);
  EXPECT_EQ(GpTrainer::search(Search::gwo, o), Search::gwo);
  EXPECT_THROW(GpTrainer::search(Search::none, o), OptionError);
  o.trainers.get<GpOptions>().selection = GpSelection::likelihood;
  EXPECT_EQ(GpTrainer::search(Search::own, o), Search::own);
  EXPECT_THROW(GpTrainer::search(Search::none, o), OptionError);
  EXPECT_THROW(GpTrainer::search(Search::ssa, o), OptionError);
}

TEST(GpTrainer, ASearchOtherThanSsaIsSaid) {
  const Dataset d = test::synthetic();
  std::vector<std::size_t> rows(d.rows);
  std::iota(rows.begin(), rows.end(), 0);
  const tune::ScaledSplit full = tune::scale_split(d, rows, {});
  TrainOptions o;
  o.method = {"gp", Search::pso};
  o.tune.optimizer.algorithm = opt::Algorithm::pso;  // as resolved() sets it
  o.tune.optimizer.run.population = 5;
  o.tune.optimizer.run.iterations = 2;
  o.tune.cv = {tune::CvScheme::repetition};
  o.trainers.get<GpOptions>().max_points = 60;
  const Trained t = GpTrainer::train({d, full, o});
  EXPECT_EQ(t.search, "pso");
  EXPECT_EQ(t.population, 5u);
  ASSERT_NE(t.summary.record.get<GpTrainer::Record>(), nullptr);
  EXPECT_EQ(t.summary.record.get<GpTrainer::Record>()->fit.points, 60u);
  EXPECT_EQ(t.summary.record.json()["gp"]["points"], 60);
  EXPECT_EQ(t.held_folds.size(), 3u);
  // The held-out report takes the folds' predictions the fitness was computed from.
  double sse = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < t.held_folds.size(); ++k) {
    const tune::Fold& f = t.held_folds[k];
    const tune::ScaledSplit split = tune::scale_split(d, f.train_rows, f.test_rows);
    const std::vector<double> p = t.held_predict(split, k);
    for (std::size_t r = 0; r < p.size(); ++r)
      sse += (p[r] - split.test.y[r]) * (p[r] - split.test.y[r]);
    n += p.size();
  }
  EXPECT_NEAR(std::sqrt(sse / static_cast<double>(n)), t.summary.fitness_value, 1e-12);
  o.method.search = Search::ssa;
  o.tune.optimizer.algorithm = opt::Algorithm::ssa;
  EXPECT_EQ(GpTrainer::train({d, full, o}).search, "");
}

}  // namespace
}  // namespace fogdrift
