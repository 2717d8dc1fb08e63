// The SVR's trainer on its own (svr_trainer.hpp): its searches, LIBSVM's defaults without one,
// and what it hands train() — the search's record, the boxes, the folds it is scored on.
#include "fogdrift/train/svr_trainer.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "fogdrift/base/error.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift {
namespace {

tune::ScaledSplit everything(const Dataset& d) {
  std::vector<std::size_t> rows(d.rows);
  std::iota(rows.begin(), rows.end(), 0);
  return tune::scale_split(d, rows, {});
}

TEST(SvrTrainer, SearchesAreItsOwnAndNoneIsLibsvmsDefaults) {
  const TrainOptions o;
  EXPECT_EQ(SvrTrainer::search(Search::own, o), Search::own);
  EXPECT_EQ(SvrTrainer::search(Search::none, o), Search::own);
  for (Search s : {Search::ssa, Search::pso, Search::gwo}) EXPECT_EQ(SvrTrainer::search(s, o), s);
}

TEST(SvrTrainer, WithoutASearchItFitsLibsvmsDefaults) {
  const Dataset d = test::synthetic();
  const tune::ScaledSplit full = everything(d);
  TrainOptions o;
  o.method = Method::svr;
  o.tune.cv = {tune::CvScheme::repetition};
  const Trained t = SvrTrainer::train({d, full, o});
  const auto& model = t.regressor.get<svr::Model>();
  EXPECT_DOUBLE_EQ(model.kernel.gamma, 1.0 / static_cast<double>(d.cols()));
  EXPECT_EQ(t.summary.hyperparameters[0], (std::pair<std::string, double>{"C", 1.0}));
  EXPECT_TRUE(t.summary.record.empty());  // nothing searched
  EXPECT_EQ(t.summary.record.get<SvrTrainer::Record>(), nullptr);
  EXPECT_EQ(t.summary.record.json(), nlohmann::ordered_json::object());
  EXPECT_FALSE(t.x_scaler.has_value());  // every row's scalers
  EXPECT_EQ(t.cv, "leave one repetition out (3 folds)");
  EXPECT_EQ(t.held_folds.size(), 3u);
  // Refitted on a fold, it predicts that fold's held-out rows.
  const tune::Fold& f = t.held_folds.front();
  const tune::ScaledSplit split = tune::scale_split(d, f.train_rows, f.test_rows);
  EXPECT_EQ(t.held_predict(split, 0).size(), f.test_rows.size());
}

TEST(SvrTrainer, ASearchRecordsItsRunAndItsBox) {
  const Dataset d = test::synthetic();
  const tune::ScaledSplit full = everything(d);
  TrainOptions o;
  o.method = Method::pso_svr;
  o.tune.optimizer.algorithm = opt::Algorithm::pso;  // as resolved() sets it
  o.tune.optimizer.run.population = 5;
  o.tune.optimizer.run.iterations = 3;
  o.tune.cv = {tune::CvScheme::repetition};
  const Trained t = SvrTrainer::train({d, full, o});
  const SvrTrainer::Record* r = t.summary.record.get<SvrTrainer::Record>();
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->population, 5u);
  EXPECT_EQ(r->boxes.size(), 1u);
  EXPECT_EQ(r->tuning.optimizer.algorithm, opt::Algorithm::pso);
  // Serialised by itself, under train --json's keys.
  const nlohmann::ordered_json j = t.summary.record.json();
  EXPECT_EQ(j["search"]["optimizer"], "pso");
  EXPECT_EQ(j["search"]["population"], 5);
  EXPECT_EQ(j["boxes_searched"].size(), 1u);
  EXPECT_EQ(j["fits"], r->tuning.fits);
  EXPECT_EQ(t.population, 5u);
  EXPECT_EQ(t.iterations, 3u);
  EXPECT_DOUBLE_EQ(t.summary.fitness_value, r->tuning.best_fitness);
  EXPECT_EQ(t.summary.fitness, "cv");
  o.tune.optimizer.run.population = 0;
  EXPECT_THROW(SvrTrainer::validate(o), OptionError);
}

}  // namespace
}  // namespace fogdrift
