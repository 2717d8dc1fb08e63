// The training rows' input ranges and line in T (baselines.hpp), and their place in the model
// file.
#include "fogdrift/model/baselines.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

Dataset two_inputs() {
  Dataset d;
  d.feature_names = {"dT_fog_degc_per_s", "T_fog_degc"};
  for (int i = 0; i < 5; ++i) {
    const double t = -10.0 + 5.0 * i;
    d.x.push_back(0.001 * (i % 2));
    d.x.push_back(t);
    d.y.push_back(2.0 + 0.5 * t + (i % 2 ? 0.1 : -0.1));
    d.group.push_back(0);
  }
  d.rows = 5;
  return d;
}

TEST(TrainingBaselines, RangesAndTheLeastSquaresLineInTheFogTemperature) {
  const Dataset d = two_inputs();
  const TrainingBaselines b = fit_training_baselines(d);
  EXPECT_EQ(b.input_min, (std::vector<double>{0.0, -10.0}));
  EXPECT_EQ(b.input_max, (std::vector<double>{0.001, 10.0}));
  ASSERT_TRUE(b.line.has_value());
  EXPECT_EQ(b.line->input, "T_fog_degc");
  // The ±0.1 alternates over T = −10, −5, 0, 5, 10: Σ(T − T̄)·e = 0, so the line is exact.
  EXPECT_NEAR(b.line->slope, 0.5, 1e-13);
  EXPECT_NEAR(b.line->intercept, 2.0 - 0.1 * (1.0 / 5.0), 1e-13);  // ē = −0.1·3/5 + 0.1·2/5
  const std::vector<double> at = line_drift(*b.line, d, "m.json");
  EXPECT_NEAR(at[4], b.line->intercept + 0.5 * 10.0, 1e-13);
}

TEST(TrainingBaselines, NoTemperatureInputMeansNoLine) {
  Dataset d = two_inputs();
  d.feature_names = {"dT_fog_degc_per_s", "grad_fog_acc1_degc"};
  EXPECT_FALSE(fit_training_baselines(d).line.has_value());
  BaselineLine other{"T_case_degc", 0, 1};
  EXPECT_THROW(line_drift(other, d, "m.json"), InputError);
}

TEST(TrainingBaselines, ExtrapolationInTheInputsOwnUnits) {
  const Dataset d = two_inputs();
  const TrainingBaselines b = fit_training_baselines(d);
  Dataset held = d;
  held.x = {0.0, 12.0, 0.0, -13.0, 0.0, 0.0};  // 2 °C above, 3 °C below, inside
  held.rows = 3;
  const std::vector<std::size_t> rows = {0, 1, 2};
  const std::vector<InputExtrapolation> x = extrapolation(b, held, rows);
  ASSERT_EQ(x.size(), 2u);
  EXPECT_EQ(x[0].share_outside, 0.0);
  EXPECT_EQ(x[1].input, "T_fog_degc");
  EXPECT_NEAR(x[1].share_outside, 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(x[1].farthest_outside, 3.0, 1e-15);
  EXPECT_EQ(x[1].min, -13.0);
  EXPECT_EQ(x[1].max, 12.0);
  EXPECT_NEAR(share_outside_any(b, held, rows), 2.0 / 3.0, 1e-15);
  // A model file without ranges says nothing.
  EXPECT_TRUE(extrapolation({}, held, rows).empty());
}

}  // namespace
}  // namespace fogdrift
