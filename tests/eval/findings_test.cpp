// A campaign's north-findings and Table 3 (findings.hpp): every finding of every northfind and
// stable recording, start-ups pooled by temperature, the floor and the share removed.
#include "fogdrift/eval/findings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "test_util.hpp"

namespace fogdrift::eval {
namespace {

sim::NorthfindOptions two_temperatures() {
  sim::NorthfindOptions o;
  o.temps_degc = {-16, 28};
  o.findings = 2;
  o.seed = 5;
  return o;
}

TEST(Findings, PoolsTheStartUpsByTemperatureWithTheirFloor) {
  test::TempDir dir;
  sim::write_campaign(dir.path() / "nf", sim::simulate_northfind({}, two_temperatures()), false);
  const CampaignFindings f = find_north(read_campaign(dir.path() / "nf"));
  ASSERT_EQ(f.recordings.size(), 2u);
  ASSERT_EQ(f.table3.size(), 2u);
  EXPECT_TRUE(f.has_floor);  // simulated recordings carry drift_true_dph
  EXPECT_TRUE(f.method.empty());
  for (std::size_t k = 0; k < 2; ++k) {
    const RecordingFindings& r = f.recordings[k];
    EXPECT_EQ(r.raw_error_deg.size(), 2u);
    EXPECT_EQ(r.floor_error_deg.size(), 2u);
    EXPECT_TRUE(r.compensated_error_deg.empty());
    EXPECT_EQ(f.table3[k].initial_temp_degc, r.initial_temp_degc);
    EXPECT_EQ(f.table3[k].findings, 2u);
    EXPECT_DOUBLE_EQ(f.table3[k].raw_rmse_deg, rms(r.raw_error_deg));
    EXPECT_DOUBLE_EQ(f.table3[k].floor_rmse_deg, rms(r.floor_error_deg));
    EXPECT_TRUE(std::isnan(f.table3[k].compensated_rmse_deg));
  }
  EXPECT_DOUBLE_EQ(f.raw_mean_rmse_deg(),
                   0.5 * (f.table3[0].raw_rmse_deg + f.table3[1].raw_rmse_deg));
  EXPECT_TRUE(std::isnan(f.share_removed()));  // no model
  EXPECT_TRUE(f.stable_error_deg.empty());

  const auto j = nlohmann::json::parse(to_json(f, "nf", ""));
  EXPECT_EQ(j["campaign"], "nf");
  EXPECT_FALSE(j.contains("model"));
  EXPECT_EQ(j["table3"]["temps_degc"], nlohmann::json({-16.0, 28.0}));
  EXPECT_EQ(j["table3"]["raw_rmse_deg"][1].get<double>(), f.table3[1].raw_rmse_deg);
  EXPECT_EQ(j["recordings"][0]["true_drift_subtracted_error_deg"].size(), 2u);
}

TEST(Findings, ADriftIsSubtractedFromTheGyroAndMustMatchIt) {
  const sim::SimulatedCampaign sc = sim::simulate_northfind({}, two_temperatures());
  const Recording& rec = sc.recordings[0];
  const double latitude = sc.campaign.latitude_deg.value();
  const double truth = sc.campaign.recordings[0].true_azimuth_deg.value();
  const std::vector<double> drift = rec.numeric_column("drift_true_dph");
  Recording subtracted = rec;
  for (std::size_t i = 0; i < drift.size(); ++i) subtracted.gyro_dph[i] -= drift[i];
  EXPECT_EQ(northfind_errors_deg(rec, drift, latitude, truth),
            northfind_errors_deg(subtracted, latitude, truth));
  const std::vector<double> short_drift(drift.begin(), drift.end() - 1);
  EXPECT_THROW(northfind_errors_deg(rec, short_drift, latitude, truth), std::invalid_argument);
}

TEST(Findings, TheDriftsOwnErrorRemovedPoolsTheStartUpFindings) {
  CampaignFindings f;
  f.method = "ssa-svr";
  f.has_floor = true;
  f.recordings.push_back(
      {"a.csv", Scenario::northfind, 10, 0, {0.03, 0.01}, {0.02, 0.0}, {0.01, 0.0}});
  f.recordings.push_back({"b.csv", Scenario::northfind, 30, 0, {-0.02}, {-0.01}, {0.0}});
  f.recordings.push_back({"s.csv", Scenario::stable, 25, 0, {0.5}, {0.0}, {0.0}});  // not pooled
  f.table3 = {{10, 2, 0.02, 0.01, 0.007}, {30, 1, 0.02, 0.01, 0.0}};
  // Drift errors 0.02, 0.01, −0.02; left 0.01, 0, −0.01: 1 − 2e-4 / 9e-4.
  EXPECT_NEAR(f.drift_error_removed(), 1 - 2.0 / 9.0, 1e-12);
  const auto j = nlohmann::json::parse(to_json(f, "nf", "model.json"));
  EXPECT_NEAR(j["table3"]["drift_error_removed"].get<double>(), 1 - 2.0 / 9.0, 1e-12);
  EXPECT_EQ(j["table3"]["removable_error_removed"].get<double>(), f.share_removed());
  f.has_floor = false;  // a logged campaign: no true drift, no share
  EXPECT_TRUE(std::isnan(f.drift_error_removed()));
  f.has_floor = true;
  f.method.clear();  // no model
  EXPECT_TRUE(std::isnan(f.drift_error_removed()));
}

TEST(Findings, StableRecordingsStandApartFromTable3) {
  test::TempDir dir;
  sim::NorthfindOptions o = sim::stable_defaults();
  o.findings = 3;
  o.warmup_s = 600;
  sim::write_campaign(dir.path() / "st", sim::simulate_stable({}, o), false);
  const CampaignFindings f = find_north(read_campaign(dir.path() / "st"));
  EXPECT_TRUE(f.table3.empty());
  EXPECT_EQ(f.stable_error_deg.size(), 3u);
  EXPECT_TRUE(std::isnan(f.raw_mean_rmse_deg()));
  const auto j = nlohmann::json::parse(to_json(f, "st", ""));
  EXPECT_DOUBLE_EQ(j["stable_rmse_deg"].get<double>(), rms(f.stable_error_deg));
}

TEST(Findings, ACampaignWithoutFindingsIsAnErrorNamingItsManifest) {
  test::TempDir dir;
  sim::CalibrationOptions o;
  o.temps_degc = {20};
  o.repetitions = 1;
  o.test_repetitions = 0;
  o.powered_s = 300;
  sim::write_campaign(dir.path() / "cal", sim::simulate_calibration({}, o), false);
  try {
    find_north(read_campaign(dir.path() / "cal"));
    FAIL() << "a calibration campaign was found north on";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("campaign.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no northfind or stable recordings"), std::string::npos);
  }
}

}  // namespace
}  // namespace fogdrift::eval
