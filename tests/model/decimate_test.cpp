#include "fogdrift/model/decimate.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

// The option named and a part of the rule, for a decimation_factor that must refuse.
void expect_refused(double model_dt_s, double data_dt_s, const std::string& rule) {
  try {
    decimation_factor(model_dt_s, data_dt_s, "--rate-hz");
    ADD_FAILURE() << data_dt_s << " s should be refused";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--rate-hz");
    EXPECT_NE(e.message().find(rule), std::string::npos) << e.message();
  }
}

TEST(DecimationFactor, WholeFractionsOfTheModelsInterval) {
  EXPECT_EQ(decimation_factor(0.0, 0.01, "rate"), 1u);  // not recorded: the data's own rate
  EXPECT_EQ(decimation_factor(1.0, 1.0, "rate"), 1u);
  EXPECT_EQ(decimation_factor(1.0, 0.01, "rate"), 100u);
  EXPECT_EQ(decimation_factor(1.0, 0.0005, "rate"), 2000u);
  EXPECT_EQ(decimation_factor(1.0, 1.0 / 99.5, "rate"), 100u);  // within 1 %
  EXPECT_EQ(decimation_factor(305.0, 1.0, "rate"), 305u);
}

TEST(DecimationFactor, RefusesWhatTheModelCannotRunAt) {
  expect_refused(1.0, 2.0, "slower than the model's 1 s");
  expect_refused(1.0, 0.4, "not a whole fraction of the model's 1 s");
  expect_refused(1.0, 0.0, "positive and finite");
}

// A model file without its interval runs its filter at the data's rate: up to 1001 samples in
// its window (121 s at 8 Hz), refused beyond (121 s at 10 Hz is 1211), naming the fix.
TEST(DecimationFactor, RefusesAnUnrecordedModelAtAHighRate) {
  FeatureOptions legacy;  // sample_interval_s = 0, window 121 s
  EXPECT_EQ(decimation_factor(legacy, 1.0 / 8, "--rate-hz"), 1u);
  try {
    decimation_factor(legacy, 0.1, "--rate-hz");
    ADD_FAILURE() << "10 Hz should be refused";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--rate-hz");
    EXPECT_NE(e.message().find("1211 samples, too many to set up; train the model again"),
              std::string::npos)
        << e.message();
  }
  FeatureOptions recorded = legacy;
  recorded.sample_interval_s = 1.0;
  EXPECT_EQ(decimation_factor(recorded, 0.001, "--rate-hz"), 1000u);
}

// Blocks in closed form: k = 3 on samples 0 … 7 gives block 0 = {0}, block 1 = {1, 2, 3},
// block 2 = {4, 5, 6}; sample 7 starts a block that is not complete.
TEST(Decimate, FirstSampleAloneThenBlocksOfK) {
  Recording r;
  for (int i = 0; i < 8; ++i) {
    r.time_s.push_back(10.0 + i);
    r.gyro_dph.push_back(2.0 * i);
    r.temp_fog_degc.push_back(i);
    r.temp_acc1_degc.push_back(100.0 + i);
  }
  const Recording d = decimate(r, 3);
  EXPECT_EQ(d.time_s, (std::vector<double>{10, 13, 16}));
  EXPECT_EQ(d.temp_fog_degc, (std::vector<double>{0, 2, 5}));
  EXPECT_EQ(d.temp_acc1_degc, (std::vector<double>{100, 102, 105}));
  EXPECT_EQ(d.gyro_dph, (std::vector<double>{0, 4, 10}));
  EXPECT_TRUE(d.temp_acc2_degc.empty());
  EXPECT_EQ(decimate(r, 1).temp_fog_degc, r.temp_fog_degc);
}

}  // namespace
}  // namespace fogdrift
