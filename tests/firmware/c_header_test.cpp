// The C99 header export (c_header.hpp): its names, prefixes and float checks. That every
// registered regressor's header compiles and predicts as the library is the registry's suite
// (tests/train/registry_test.cpp).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/train/train.hpp"
#include "synthetic_dataset.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

TEST(CHeader, NamesTheFeaturesAndRejectsBadPrefixes) {
  TrainOptions o;
  o.method = Method::svr;
  const CompensationModel model = train(test::synthetic(), test::kDefaultDataset, o).model;
  const std::string h = to_c_header(model, "unit7");
  EXPECT_NE(h.find("#define UNIT7_N_FEATURES 3"), std::string::npos);
  EXPECT_NE(h.find("static const char* const unit7_feature_names[3] = {\"T_fog_degc\", "
                   "\"T_acc1_degc\", \"T_acc2_degc\"};"),
            std::string::npos);
  EXPECT_NE(h.find("static inline unit7_real unit7_predict_dph("), std::string::npos);
  EXPECT_EQ(h.find("malloc"), std::string::npos);
  EXPECT_THROW(to_c_header(model, "7unit"), OptionError);
  EXPECT_THROW(to_c_header(model, "my-model"), OptionError);
  EXPECT_THROW(to_c_header(model, ""), OptionError);
  // Found by an attack (issue 57): _math gave the guard _MATH_H, which hides <math.h>.
  EXPECT_THROW(to_c_header(model, "_math"), OptionError);
  EXPECT_THROW(to_c_header(model, "_x"), OptionError);
}

// Found by an attack (issue 57): axes that made members named twice, `1` or `int`.
TEST(CHeader, AxesMustBeDistinctPlainIdentifiers) {
  EXPECT_NO_THROW(check_targets({"gyro_dph", "gyro_y_dph", "accel_x_g"}, "--targets"));
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"gyro_dph", "gyro_gyro_dph"},
                                             {"gyro_accel_x_dph", "accel_x_g"},
                                             {"gyro_1_dph"},
                                             {"gyro_int_dph"},
                                             {"gyro_comp_dph"},
                                             {"gyro_y_comp_dph"},
                                             {"gyro_dph", "gyro_dph"},
                                             {}}) {
    try {
      check_targets(bad, "--targets");
      ADD_FAILURE() << fmt::format("{}", fmt::join(bad, ","));
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "--targets");
    }
  }
}

// A float header is compared with its model on the model's own inputs (c_header.hpp): the
// default model passes; one whose inputs vary by micro-degrees about 25 °C does not.
TEST(CHeader, FloatIsCheckedOnTheModelsOwnInputs) {
  TrainOptions o;
  o.method = Method::svr;
  CompensationModel model = train(test::synthetic(), test::kDefaultDataset, o).model;
  const FloatPrecisionCheck good = check_float_precision(model);
  EXPECT_GT(good.inputs, 0u);
  EXPECT_LE(good.share(), kFloatShareLimit);
  for (std::size_t k = 0; k < model.inputs(); ++k) {
    model.x_scaler.mean[k] = 25.0 + model.x_scaler.mean[k] * 1e-6;
    model.x_scaler.scale[k] *= 1e-6;
  }
  const FloatPrecisionCheck micro = check_float_precision(model);
  EXPECT_GT(micro.share(), kFloatShareLimit) << micro.share();
}

}  // namespace
}  // namespace fogdrift
