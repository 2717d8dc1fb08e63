// The BP network's trainer on its own (bp_trainer.hpp): no search, early stopping on one fold
// whose scalers the model keeps, and its record.
#include "fogdrift/train/bp_trainer.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "fogdrift/base/error.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift {
namespace {

TEST(BpTrainer, HasNoSearch) {
  const TrainOptions o;
  EXPECT_EQ(BpTrainer::search(Search::own, o), Search::own);
  EXPECT_EQ(BpTrainer::search(Search::none, o), Search::own);
  try {
    BpTrainer::search(Search::pso, o);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "search");
    EXPECT_NE(std::string(e.what()).find("early stopping"), std::string::npos);
  }
}

TEST(BpTrainer, StopsEarlyOnOneFoldAndKeepsItsScalers) {
  const Dataset d = test::synthetic();
  std::vector<std::size_t> rows(d.rows);
  std::iota(rows.begin(), rows.end(), 0);
  const tune::ScaledSplit full = tune::scale_split(d, rows, {});
  TrainOptions o;
  o.method = Method::bp;
  o.trainers.get<MlpOptions>().max_epochs = 300;
  const Trained t = BpTrainer::train({d, full, o});
  ASSERT_EQ(t.held_folds.size(), 1u);
  EXPECT_EQ(t.held_description, t.held_folds.front().name);
  EXPECT_EQ(t.cv, "early stopping on " + t.held_folds.front().name);
  // Its scalers are the fold's training rows', not every row's.
  ASSERT_TRUE(t.x_scaler.has_value() && t.y_scaler.has_value());
  const tune::Fold& f = t.held_folds.front();
  const tune::ScaledSplit split = tune::scale_split(d, f.train_rows, f.test_rows);
  EXPECT_EQ(t.x_scaler->mean, split.x_scaler.mean);
  EXPECT_NE(t.x_scaler->mean, full.x_scaler.mean);
  EXPECT_EQ(t.summary.fitness, "validation");
  const BpTrainer::Record* r = t.summary.record.get<BpTrainer::Record>();
  ASSERT_NE(r, nullptr);
  EXPECT_LE(r->fit.best_epoch, r->fit.epochs);
  EXPECT_EQ(t.summary.record.json()["bp"]["epochs"], r->fit.epochs);
  EXPECT_EQ(t.held_predict(split, 0).size(), f.test_rows.size());
  o.trainers.get<MlpOptions>().hidden = 0;
  EXPECT_THROW(BpTrainer::validate(o), OptionError);
}

}  // namespace
}  // namespace fogdrift
