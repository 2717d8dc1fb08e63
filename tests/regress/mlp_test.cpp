#include "fogdrift/regress/mlp.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"

namespace fogdrift {
namespace {

Data smooth(std::uint64_t seed, std::size_t rows, double noise) {
  Data d;
  d.cols = 2;
  Rng rng(seed);
  for (std::size_t i = 0; i < rows; ++i) {
    const double a = rng.uniform(-2, 2), b = rng.uniform(-2, 2);
    d.x.insert(d.x.end(), {a, b});
    d.y.push_back(std::sin(a) + 0.3 * b * b - 0.5 + rng.normal(0, noise));
    ++d.rows;
  }
  return d;
}

double rmse(const Mlp& m, const Data& d) {
  double s = 0;
  for (std::size_t i = 0; i < d.rows; ++i) s += std::pow(m.predict(d.row(i)) - d.y[i], 2);
  return std::sqrt(s / d.rows);
}

// The target's standard deviation is about 0.8; a trained network gets within a few hundredths.
TEST(Mlp, LearnsASmoothFunction) {
  const Data train = smooth(1, 400, 0), valid = smooth(2, 200, 0);
  MlpOptions o;
  o.max_epochs = 4000;
  const MlpFit fit = fit_mlp(train, valid, o);
  EXPECT_LT(rmse(fit.model, valid), 0.05);
  EXPECT_NEAR(rmse(fit.model, valid), fit.summary.validation_rmse, 1e-3);
  EXPECT_LE(fit.summary.best_epoch, fit.summary.epochs);
}

// On noisy data with many units, the validation error stops improving and training stops early;
// the kept weights are those of the best epoch.
TEST(Mlp, StopsEarlyOnHeldOutData) {
  const Data train = smooth(3, 60, 0.3), valid = smooth(4, 200, 0.3);
  MlpOptions o;
  o.hidden = 40;
  o.learning_rate = 0.05;
  o.max_epochs = 20000;
  o.patience = 100;
  const MlpFit fit = fit_mlp(train, valid, o);
  EXPECT_EQ(fit.summary.status, MlpStatus::early_stopped);
  EXPECT_LT(fit.summary.epochs, 20000u);
  EXPECT_EQ(fit.summary.epochs, fit.summary.best_epoch + o.patience + 1);
  EXPECT_NEAR(rmse(fit.model, valid), fit.summary.validation_rmse, 1e-12);
}

// Training computes the hidden layer's tanh from a vectorised exponential (mlp.cpp,
// training_tanh); predictions use std::tanh. After one epoch the kept weights are the initial
// ones, so the validation error training reported and the model's own differ only by the two
// tanh: within a few units of 1e-16.
TEST(Mlp, TrainingTanhAgreesWithStdTanh) {
  for (const std::size_t hidden : {std::size_t{3}, std::size_t{50}}) {
    const Data train = smooth(7, 80, 0.1), valid = smooth(8, 400, 0.1);
    MlpOptions o;
    o.hidden = hidden;
    o.max_epochs = 1;
    o.seed = 3 + hidden;
    const MlpFit fit = fit_mlp(train, valid, o);
    ASSERT_EQ(fit.summary.best_epoch, 0u);
    EXPECT_NEAR(rmse(fit.model, valid), fit.summary.validation_rmse, 1e-15) << hidden;
  }
}

TEST(Mlp, SameSeedSameWeights) {
  const Data train = smooth(5, 100, 0.1), valid = smooth(6, 50, 0.1);
  MlpOptions o;
  o.max_epochs = 300;
  const MlpFit a = fit_mlp(train, valid, o), b = fit_mlp(train, valid, o);
  EXPECT_EQ(a.model.w1, b.model.w1);
  EXPECT_EQ(a.model.w2, b.model.w2);
  o.seed = 2;
  EXPECT_NE(fit_mlp(train, valid, o).model.w1, a.model.w1);
}

TEST(Mlp, RejectsImpossibleOptions) {
  const Data train = smooth(5, 10, 0.1);
  MlpOptions o;
  o.hidden = 0;
  EXPECT_THROW(fit_mlp(train, {}, o), OptionError);
  o = {};
  o.learning_rate = -1;
  EXPECT_THROW(fit_mlp(train, {}, o), OptionError);
  o = {};
  o.patience = 0;
  EXPECT_THROW(fit_mlp(train, {}, o), OptionError);
}

TEST(Mlp, JsonRoundTripAndBadSizes) {
  Mlp m;
  m.inputs = 2;
  m.hidden = 2;
  m.w1 = {0.1, -0.2, 0.3, 0.4};
  m.b1 = {0.01, -0.02};
  m.w2 = {1.5, -0.5};
  m.b2 = 0.25;
  const Mlp back = mlp_from_json(to_json(m), "m.json");
  const double x[2] = {0.7, -1.1};
  EXPECT_EQ(back.predict(x), m.predict(x));  // every double written to round-trip
  m.b1.pop_back();
  try {
    mlp_from_json(to_json(m), "m.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "m.json");
    EXPECT_NE(e.message().find("weights do not match 2 inputs and 2 hidden units"),
              std::string::npos);
  }
  EXPECT_THROW(mlp_from_json(R"({"inputs": 2})", "m.json"), InputError);
}

}  // namespace
}  // namespace fogdrift
