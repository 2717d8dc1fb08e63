#include "fogdrift/model/dataset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "fogdrift/base/earth.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

// Two temperatures, two repetitions, 30 min each: small enough for a unit test.
const sim::SimulatedCampaign& small_campaign() {
  static const sim::SimulatedCampaign c = [] {
    sim::CalibrationOptions o;
    o.temps_degc = {-20, 30};
    o.repetitions = 2;
    o.seed = 4;
    return sim::simulate_calibration(sim::Instrument{}, o);
  }();
  return c;
}

std::vector<RecordingInput> inputs_of(const sim::SimulatedCampaign& c, bool with_azimuth) {
  std::vector<RecordingInput> out;
  for (std::size_t i = 0; i < c.recordings.size(); ++i) {
    const auto& e = c.campaign.recordings[i];
    RecordingInput in;
    in.recording = c.recordings[i];
    in.recording.source = e.file;
    in.info.file = e.file;
    in.info.role = e.role;
    in.info.repetition = e.repetition;
    in.info.initial_temp_degc = e.initial_temp_degc;
    if (with_azimuth) {
      in.latitude_deg = c.campaign.latitude_deg;
      in.true_azimuth_deg = e.true_azimuth_deg;
    }
    out.push_back(std::move(in));
  }
  return out;
}

// The features of the paper's spec, recomputed independently from the recordings: temperatures
// and gradients are plain block means of the columns; rows, groups and times line up.
TEST(Dataset, RowsGroupsAndFeaturesFromTheRecordings) {
  const auto& c = small_campaign();
  const Dataset d = build_dataset(inputs_of(c, true));
  ASSERT_EQ(d.groups.size(), 4u);
  ASSERT_EQ(d.cols(), 9u);
  EXPECT_EQ(d.feature_spec, "T,dT,grad");
  EXPECT_TRUE(d.warnings.empty());
  std::size_t row = 0;
  for (std::size_t g = 0; g < 4; ++g) {
    const Recording& r = c.recordings[g];
    const std::size_t blocks = r.size() / 10;
    for (std::size_t b = 0; b < blocks; ++b, ++row) {
      ASSERT_EQ(d.group[row], g);
      double t_fog = 0, t_acc1 = 0, t_acc2 = 0;
      for (std::size_t j = b * 10; j < b * 10 + 10; ++j) {
        t_fog += r.temp_fog_degc[j] / 10;
        t_acc1 += r.temp_acc1_degc[j] / 10;
        t_acc2 += r.temp_acc2_degc[j] / 10;
      }
      const auto x = d.row(row);
      ASSERT_NEAR(x[0], t_fog, 1e-9);
      ASSERT_NEAR(x[2], t_acc2, 1e-9);
      ASSERT_NEAR(x[6], t_fog - t_acc1, 1e-9);
      ASSERT_NEAR(x[8], t_acc1 - t_acc2, 1e-9);
    }
  }
  EXPECT_EQ(row, d.rows);
  EXPECT_EQ(d.y.size(), d.rows);
  EXPECT_EQ(d.time_s.size(), d.rows);
}

// The target is the denoised gyro minus the Earth rate: it follows the simulator's true drift up
// to the turn-on bias (a constant per recording), within the noise left after denoising.
TEST(Dataset, TargetFollowsTheTrueDrift) {
  const auto& c = small_campaign();
  const auto inputs = inputs_of(c, true);
  const Dataset d = build_dataset(inputs);
  const double earth = kEarthRateDph * std::cos(30.0 * 3.14159265358979323846 / 180.0);
  for (std::size_t g = 0; g < d.groups.size(); ++g) {
    EXPECT_EQ(d.groups[g].target, "earth_rate");
    EXPECT_NEAR(d.groups[g].reference, earth, 1e-9);
    const auto truth = signal::block_average(c.recordings[g].numeric_column("drift_true_dph"), 10);
    const auto raw = signal::block_average(c.recordings[g].gyro_dph, 10);
    std::vector<double> diff, raw_diff;
    for (std::size_t i = 0; i < d.rows; ++i) {
      if (d.group[i] != g) continue;
      raw_diff.push_back(raw[diff.size()] - earth - truth[diff.size()]);
      diff.push_back(d.y[i] - truth[diff.size()]);
    }
    ASSERT_EQ(diff.size(), truth.size());
    auto centred_rms = [](const std::vector<double>& v) {
      const double mean = std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
      double ss = 0;
      for (double e : v) ss += (e - mean) * (e - mean);
      return std::sqrt(ss / double(v.size()));
    };
    // Besides the turn-on bias, what is left is well below the raw gyro's noise in 10 s means
    // (bench/denoise_study measures about 0.35 of it; white noise is removed, flicker is not).
    EXPECT_LT(centred_rms(diff), 0.5 * centred_rms(raw_diff)) << g;
  }
}

// Rows of a recording logged faster than the model's interval are the rows of its blocks
// (decimate.hpp): 10 Hz data for a 1 Hz model give the rows, features and block times of the
// same start-up decimated by 10, and its target is the decimated target; a rate that is not a
// whole fraction is refused naming the recording.
TEST(Dataset, FasterDataInTheModelsBlocks) {
  sim::NorthfindOptions no;
  no.temps_degc = {20};
  no.findings = 1;
  no.output_rate_hz = 10;
  RecordingInput fast;
  fast.recording = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  fast.input_rate_dph = 0.0;
  DatasetOptions o;
  o.preprocessing.sample_interval_s = 1.0;
  const Dataset d = build_dataset({fast}, o);
  RecordingInput slow = fast;
  slow.recording = decimate(fast.recording, 10);
  DatasetOptions at_model_rate = o;
  at_model_rate.denoise_target = false;  // the decimated target is compared below, not denoised
  o.denoise_target = false;
  const Dataset dn = build_dataset({fast}, o);
  const Dataset ds = build_dataset({slow}, at_model_rate);
  ASSERT_EQ(dn.rows, ds.rows);
  EXPECT_EQ(d.rows, ds.rows);
  EXPECT_EQ(dn.x, ds.x);
  EXPECT_EQ(dn.time_s, ds.time_s);
  for (std::size_t i = 0; i < dn.rows; ++i) EXPECT_NEAR(dn.y[i], ds.y[i], 1e-12) << i;
  fast.recording.time_s.assign(fast.recording.size(), 0.0);
  for (std::size_t i = 0; i < fast.recording.size(); ++i) fast.recording.time_s[i] = 0.4 * i;
  fast.recording.source = "fast.csv";
  try {
    build_dataset({fast}, o);
    ADD_FAILURE() << "0.4 s samples for a 1 s model should be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fast.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a whole fraction"), std::string::npos) << e.what();
  }
}

TEST(Dataset, UnknownInputFallsBackToTheMeanWithAWarning) {
  const auto& c = small_campaign();
  auto inputs = inputs_of(c, false);
  inputs.resize(1);
  const Dataset d = build_dataset(inputs);
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find(inputs[0].info.file +
                               ": no reference for gyro_dph is known, so the target is the gyro "
                               "less its mean"),
            std::string::npos)
      << d.warnings[0];
  EXPECT_EQ(d.groups[0].target, "mean");
  const double mean_y = std::accumulate(d.y.begin(), d.y.end(), 0.0) / double(d.rows);
  EXPECT_NEAR(mean_y, 0.0, 0.01);  // block means of a zero-mean series, minus the dropped tail
  inputs[0].input_rate_dph = 5.0;
  const Dataset e = build_dataset(inputs);
  EXPECT_TRUE(e.warnings.empty());
  EXPECT_EQ(e.groups[0].target, "input_rate");
  EXPECT_EQ(e.groups[0].reference, 5.0);
  inputs[0].references["gyro_dph"] = 7.0;  // a reference for the column comes first
  EXPECT_EQ(build_dataset(inputs).groups[0].reference, 7.0);
}

TEST(Dataset, AnAccelerometerTargetTakesItsOwnReference) {
  const auto& c = small_campaign();
  auto inputs = inputs_of(c, false);
  inputs.resize(1);
  inputs[0].input_rate_dph = 5.0;  // a gyro's input rate is not an accelerometer's reference
  DatasetOptions options;
  options.target_column = "accel_x_g";
  const Dataset d = build_dataset(inputs, options);
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("no reference for accel_x_g is known, so the target is the "
                               "accelerometer less its mean"),
            std::string::npos)
      << d.warnings[0];
  EXPECT_NE(d.warnings[0].find("g); the turn-on bias is lost (give it with fogdrift campaign "
                               "--reference accel_x_g=VALUE (g))"),
            std::string::npos)
      << d.warnings[0];
  EXPECT_EQ(d.groups[0].target, "mean");
  // Level, the axis senses no gravity: the target is the accelerometer's bias and its drift.
  inputs[0].references["accel_x_g"] = 0.0;
  const Dataset e = build_dataset(inputs, options);
  EXPECT_TRUE(e.warnings.empty());
  EXPECT_EQ(e.groups[0].target, "reference");
  const auto& accel = *inputs[0].recording.accel_x_g;
  const double mean_accel = std::accumulate(accel.begin(), accel.end(), 0.0) / double(accel.size());
  const double mean_y = std::accumulate(e.y.begin(), e.y.end(), 0.0) / double(e.rows);
  EXPECT_NEAR(mean_y, mean_accel, 1e-3 * std::abs(mean_accel) + 1e-6);
}

TEST(Dataset, FromACampaignFolderByRole) {
  test::TempDir dir;
  sim::write_campaign(dir.path(), small_campaign(), false);
  const Campaign campaign = read_campaign(dir.path());
  const Dataset train = build_dataset(campaign, Role::train);
  const Dataset test = build_dataset(campaign, Role::test);
  ASSERT_EQ(train.groups.size(), 2u);
  ASSERT_EQ(test.groups.size(), 2u);
  EXPECT_EQ(train.groups[0].repetition, 1);
  EXPECT_EQ(test.groups[0].repetition, 2);
  EXPECT_EQ(test.groups[1].initial_temp_degc, 30.0);
  const Dataset first = train.select_groups(std::vector<std::size_t>{1});
  EXPECT_EQ(first.rows, train.rows / 2);
  EXPECT_EQ(first.group.front(), 1u);
  EXPECT_THROW(build_dataset(campaign, Role::train, Scenario::northfind), InputError);

  // A recording without an accelerometer thermometer: the reader names file, line and column.
  const auto path = campaign.path_of(campaign.recordings[0]);
  std::string text = test::read_file(path);
  text.replace(text.find("temp_acc2_degc"), 14, "temp_other");
  test::write_file(path, text);
  try {
    build_dataset(campaign, Role::train);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("temp_acc2_degc"), std::string::npos) << e.what();
    EXPECT_NE(e.file().find(campaign.recordings[0].file), std::string::npos);
  }
}

TEST(Dataset, StandardizerFromTrainingRowsAndConstantColumns) {
  const std::vector<double> x{1, 10, 2, 10, 3, 10};
  try {
    Standardizer::fit(x, 2, {"a_degc", "b_degc"});
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("b_degc is constant (10) over the 3 training rows"),
              std::string::npos)
        << e.what();
  }
  const std::vector<double> with_nan{1, 10, NAN, 11, 3, 13};
  try {
    Standardizer::fit(with_nan, 2, {"a_degc", "b_degc"});
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("column a_degc has a non-finite value"), std::string::npos)
        << e.what();
  }
  const std::vector<double> y{1, 10, 2, 11, 3, 13};
  const Standardizer s = Standardizer::fit(y, 2, {"a", "b"});
  EXPECT_DOUBLE_EQ(s.mean[0], 2.0);
  EXPECT_DOUBLE_EQ(s.scale[0], 1.0);
  EXPECT_NEAR(s.scale[1], std::sqrt(7.0 / 3.0), 1e-15);
  std::vector<double> z = y;
  s.apply(z);
  EXPECT_DOUBLE_EQ(z[0], -1.0);
  s.invert(z);
  for (std::size_t i = 0; i < y.size(); ++i) EXPECT_NEAR(z[i], y[i], 1e-14);
}

}  // namespace
}  // namespace fogdrift
