// The registry (trainers.hpp, src/train/registry.cpp): every registered method goes through the
// same checks, read from the registry and not from a list here, so that a regressor added by
// docs/architecture.md's recipe is tested without an edit to this file. Each is trained on a
// small grouped dataset with its trainer's cheapest search (none where the trainer has one, else
// its own); it must learn something, write a model file that reads back to the same text and
// the same predictions to the bit, and export a C header that compiles as C99 and predicts as
// the library does.
#include "fogdrift/train/trainers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "fogdrift/base/error.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/model/model.hpp"
#include "synthetic_dataset.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

// The cheapest search a trainer accepts: none where it has one, else its own.
Method cheapest(const TrainerEntry& t) {
  try {
    t.search(Search::none, TrainOptions{});
    return {t.name, Search::none};
  } catch (const OptionError&) {
    return {t.name, Search::own};
  }
}

constexpr const char* kDriver = R"(#include <stdio.h>
#include "model.h"
int main(void) {
  double f[FD_MODEL_N_FEATURES];
  int k;
  for (;;) {
    for (k = 0; k < FD_MODEL_N_FEATURES; ++k)
      if (scanf("%lf", &f[k]) != 1) return 0;
    printf("%.17g\n", fd_model_predict_dph(f));
  }
}
)";

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

TEST(Registry, TrainersAndRegressorsAreOneList) {
  const auto trainers = trainer_entries();
  const auto regressors = regressor_entries();
  ASSERT_EQ(trainers.size(), regressors.size());
  ASSERT_GE(trainers.size(), 4u);  // the paper's SVR and BP, the polynomial, the GP
  std::set<std::string_view> types;
  for (std::size_t i = 0; i < trainers.size(); ++i) {
    EXPECT_EQ(trainers[i].regressor, regressors[i].type) << trainers[i].name;
    EXPECT_TRUE(types.insert(regressors[i].type).second) << regressors[i].type;
    EXPECT_TRUE(is_regressor_type(regressors[i].type));
    EXPECT_NE(regressor_types().find(regressors[i].type), std::string::npos);
    EXPECT_EQ(&trainer(trainers[i].name), &trainers[i]);
  }
  EXPECT_EQ(trainers.front().name, "svr");  // the paper's method is the default's
}

TEST(Registry, EveryMethodTrainsSavesLoadsAndExportsAlike) {
  const Dataset d = test::synthetic();
  for (const TrainerEntry& t : trainer_entries()) {
    SCOPED_TRACE(std::string(t.name));
    TrainOptions o;
    o.method = cheapest(t);
    o.held_out = false;
    const CompensationModel model = train(d, test::kDefaultDataset, o).model;

    // It fits what it says it fits, and learns: its error on the training rows is below the
    // spread of the target about its mean.
    EXPECT_EQ(regressor_type(model.regressor), t.regressor);
    EXPECT_EQ(input_count(model.regressor), d.cols());
    const std::vector<double> predicted = model.predict_dph(d, false);
    ASSERT_EQ(predicted.size(), d.rows);
    double mean = 0;
    for (double y : d.y) mean += y / static_cast<double>(d.rows);
    std::vector<double> residual(d.rows), spread(d.rows);
    for (std::size_t i = 0; i < d.rows; ++i) {
      ASSERT_TRUE(std::isfinite(predicted[i])) << i;
      residual[i] = predicted[i] - d.y[i];
      spread[i] = d.y[i] - mean;
    }
    EXPECT_LT(rms(residual), 0.9 * rms(spread));

    // Its file reads back to the same text and the same predictions, bit for bit.
    const std::string text = to_json(model);
    const CompensationModel back = compensation_model_from_json(text, "m.json");
    EXPECT_EQ(to_json(back), text);
    EXPECT_EQ(back.predict_dph(d, false), predicted);

    // Its C compiles as strict C99 and predicts as the library, to 1e-13 of the largest drift.
    test::TempDir dir;
    test::write_file(dir / "model.h", to_c_header(model, "fd_model"));
    test::write_file(dir / "driver.c", kDriver);
    std::ostringstream rows;
    rows.precision(17);
    for (std::size_t i = 0; i < d.rows; ++i) {
      for (double v : d.row(i)) rows << v << ' ';
      rows << '\n';
    }
    std::istringstream out(test::compile_and_run_c(dir, rows.str()));
    const std::vector<double> expected = model.predict_dph(d);
    double worst = 0, scale = 0;
    std::size_t n = 0;
    for (double v; out >> v; ++n) {
      ASSERT_LT(n, expected.size());
      worst = std::max(worst, std::abs(v - expected[n]));
      scale = std::max(scale, std::abs(expected[n]));
    }
    EXPECT_EQ(n, d.rows);
    EXPECT_LE(worst, 1e-13 * scale);
  }
}

}  // namespace
}  // namespace fogdrift
