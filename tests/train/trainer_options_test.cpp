// Each trainer's own options (trainer_options.hpp): defaults until set, and copies that own
// their values, as TrainOptions is copied into every task of a study.
#include "fogdrift/train/trainer_options.hpp"

#include <gtest/gtest.h>

#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/train/poly_trainer.hpp"

namespace fogdrift {
namespace {

TEST(TrainerOptions, UnsetOptionsReadAsTheirDefaults) {
  const TrainerOptions none;
  EXPECT_EQ(none.get<PolyTrainer::Options>().max_degree, PolyTrainer::Options{}.max_degree);
  EXPECT_EQ(none.get<MlpOptions>().hidden, MlpOptions{}.hidden);
}

TEST(TrainerOptions, CopiesOwnTheirValues) {
  TrainerOptions a;
  a.get<PolyTrainer::Options>().max_degree = 5;
  a.get<MlpOptions>().hidden = 7;
  TrainerOptions b = a;
  b.get<PolyTrainer::Options>().max_degree = 2;
  EXPECT_EQ(a.get<PolyTrainer::Options>().max_degree, 5u);
  EXPECT_EQ(b.get<PolyTrainer::Options>().max_degree, 2u);
  EXPECT_EQ(std::as_const(b).get<MlpOptions>().hidden, 7u);
  a = b;
  EXPECT_EQ(a.get<PolyTrainer::Options>().max_degree, 2u);
  const TrainerOptions moved = std::move(b);
  EXPECT_EQ(moved.get<MlpOptions>().hidden, 7u);
}

}  // namespace
}  // namespace fogdrift
