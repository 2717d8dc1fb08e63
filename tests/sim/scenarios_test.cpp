#include "fogdrift/sim/scenarios.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/io/campaign.hpp"
#include "test_util.hpp"

namespace fogdrift::sim {
namespace {

// One default calibration campaign shared by the statistics tests (it takes well under a second).
const SimulatedCampaign& default_calibration() {
  static const SimulatedCampaign campaign = [] {
    CalibrationOptions o;
    o.seed = 1;
    return simulate_calibration(Instrument{}, o);
  }();
  return campaign;
}

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

TEST(Calibration, PaperProtocolShape) {
  const auto& c = default_calibration();
  ASSERT_EQ(c.recordings.size(), 44u);
  int train = 0, test = 0;
  for (std::size_t i = 0; i < c.recordings.size(); ++i) {
    const auto& e = c.campaign.recordings[i];
    const auto& r = c.recordings[i];
    (e.role == Role::train ? train : test)++;
    EXPECT_EQ(e.role == Role::test, e.repetition == 4) << e.file;
    EXPECT_EQ(e.scenario, Scenario::calibration);
    ASSERT_EQ(r.size(), 1800u) << e.file;
    EXPECT_EQ(r.time_s.front(), 1.0);
    EXPECT_EQ(r.time_s.back(), 1800.0);
    // The chamber holds the cycle temperature (within its control error) while powered.
    EXPECT_NEAR(r.chamber_degc->front(), e.initial_temp_degc, 1.0);
    EXPECT_TRUE(r.has_column("drift_true_dph"));
  }
  EXPECT_EQ(train, 33);
  EXPECT_EQ(test, 11);
  EXPECT_EQ(c.campaign.recordings[0].file, "cal_r1_m40C.csv");
}

TEST(Calibration, SameSeedSameBytesOtherSeedOtherNoise) {
  CalibrationOptions o;
  o.temps_degc = {-40, 20};
  o.repetitions = 2;
  o.seed = 5;
  const auto a = simulate_calibration(Instrument{}, o);
  const auto b = simulate_calibration(Instrument{}, o);
  o.seed = 6;
  const auto c = simulate_calibration(Instrument{}, o);
  ASSERT_EQ(a.recordings.size(), 4u);
  for (std::size_t i = 0; i < a.recordings.size(); ++i) {
    EXPECT_EQ(to_csv(a.recordings[i]), to_csv(b.recordings[i]));
    EXPECT_NE(to_csv(a.recordings[i]), to_csv(c.recordings[i]));
  }
  EXPECT_EQ(manifest_json(a.campaign), manifest_json(b.campaign));
}

// Start-ups that begin afresh may visit fewer set points than the calibration sweep: each
// repetition's recordings are at its own set points, and a start-up recording is the one the
// full protocol makes at that set point (its seed is its repetition's and place's).
TEST(Calibration, StartUpRepetitionsVisitTheirOwnSetPoints) {
  CalibrationOptions o;
  o.temps_degc = {-40, -30, -20};
  o.repetitions = 2;
  o.test_repetitions = 0;
  o.approaches = {Approach::calibration, Approach::soaked};
  o.powered_s = 120;
  const auto full = simulate_calibration(Instrument{}, o);
  o.start_up_temps_degc = {-40, -20};
  const auto sparse = simulate_calibration(Instrument{}, o);
  ASSERT_EQ(full.recordings.size(), 6u);
  ASSERT_EQ(sparse.recordings.size(), 5u);
  std::vector<double> first, second;
  for (const CampaignEntry& e : sparse.campaign.recordings)
    (e.repetition == 1 ? first : second).push_back(e.initial_temp_degc);
  EXPECT_EQ(first, o.temps_degc);
  EXPECT_EQ(second, o.start_up_temps_degc);
  for (std::size_t i = 0; i < 4; ++i)  // the calibration sweep and the first start-up
    EXPECT_EQ(to_csv(sparse.recordings[i]), to_csv(full.recordings[i])) << i;
  EXPECT_EQ(sparse.campaign.recordings[4].file, "cal_r2_m20C.csv");
  EXPECT_NE(manifest_json(sparse.campaign), manifest_json(full.campaign));  // says so
  o.start_up_temps_degc = {-40, 150};
  EXPECT_THROW(validate(o), OptionError);
}

// The default instrument is paper-like (denoised start-up STD 0.01–0.02 °/h, paper 0.0134;
// docs/simulator.md §5).
TEST(Calibration, StartUpDriftStatisticsArePaperLike) {
  const auto& c = default_calibration();
  std::vector<double> true_std, smooth_std;
  for (std::size_t i = 0; i < c.recordings.size(); ++i) {
    const auto& r = c.recordings[i];
    const auto truth = eval::startup_stats(r.time_s, r.numeric_column("drift_true_dph"), 1);
    const auto smooth = eval::startup_stats(r.time_s, r.gyro_dph, 61);
    true_std.push_back(truth.std_dph);
    smooth_std.push_back(smooth.std_dph);
    // Falls sharply first, then rises: the minimum lies between 100 s and 500 s, and the end
    // is above the start-up minimum by a clear margin.
    EXPECT_GT(truth.min_time_s, 100.0) << c.campaign.recordings[i].file;
    EXPECT_LT(truth.min_time_s, 500.0) << c.campaign.recordings[i].file;
  }
  EXPECT_GT(mean(true_std), 0.010);
  EXPECT_LT(mean(true_std), 0.020);
  EXPECT_GT(mean(smooth_std), 0.010);
  EXPECT_LT(mean(smooth_std), 0.020);
}

TEST(Calibration, StartUpShapeDiffersWithInitialTemperature) {
  const auto& c = default_calibration();
  // Compare the normalised true-drift curves of the coldest and the hottest cycle.
  auto curve = [&](std::size_t i) {
    auto d = c.recordings[i].numeric_column("drift_true_dph");
    const double m = mean(d);
    double s = 0;
    for (double& x : d) x -= m, s += x * x;
    for (double& x : d) x /= std::sqrt(s);
    return d;
  };
  const auto cold = curve(0), hot = curve(10);
  double correlation = 0;
  for (std::size_t k = 0; k < cold.size(); ++k) correlation += cold[k] * hot[k];
  EXPECT_LT(correlation, 0.95);
  const auto cold_stats = eval::startup_stats(c.recordings[0].time_s, cold, 1);
  const auto hot_stats = eval::startup_stats(c.recordings[10].time_s, hot, 1);
  EXPECT_GT(std::abs(cold_stats.min_time_s - hot_stats.min_time_s), 20.0);
}

Instrument ideal_instrument() {
  Instrument in;
  FogParams& f = in.fog;
  f.bias_run_to_run_dph = 0;
  f.static_d1_dph_per_k = f.static_d2_dph_per_k2 = f.static_d3_dph_per_k3 = 0;
  f.rate_r0_dph_per_kps = 0;
  f.shupe_s0_dph_per_kps = 0;
  f.arw_deg_per_rth = f.bias_gm_sigma_dph = f.rrw_deg_per_h_rth = f.quantization_arcsec = 0;
  in.accel_x.noise_g = in.accel_y.noise_g = 0;
  in.accel_x.temp_coeff_g_per_k = in.accel_y.temp_coeff_g_per_k = 0;  // biases held constant
  in.turntable.indexing_error_arcsec = 0;
  return in;
}

TEST(Northfind, ZeroDriftAndNoiseGivesTheTrueAzimuth) {
  NorthfindOptions o;
  o.temps_degc = {-32, 54};
  const auto nf = simulate_northfind(ideal_instrument(), o);
  ASSERT_EQ(nf.recordings.size(), 2u);
  for (std::size_t i = 0; i < nf.recordings.size(); ++i) {
    const auto& e = nf.campaign.recordings[i];
    EXPECT_EQ(e.scenario, Scenario::northfind);
    ASSERT_TRUE(e.true_azimuth_deg.has_value());
    const auto errors = eval::northfind_errors_deg(
        nf.recordings[i], nf.campaign.latitude_deg.value(), *e.true_azimuth_deg);
    ASSERT_EQ(errors.size(), 5u);
    // Constant turn-on bias and accelerometer biases (thermal part included) cancel exactly.
    for (double err : errors) EXPECT_NEAR(err, 0.0, 1e-6) << e.file;
  }
}

TEST(Northfind, StartUpIsWorseThanTheStableStageLikeThePaper) {
  std::vector<double> startup, stable;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    NorthfindOptions o;
    o.seed = seed;
    const auto nf = simulate_northfind(Instrument{}, o);
    for (std::size_t i = 0; i < nf.recordings.size(); ++i) {
      startup.push_back(eval::rms(eval::northfind_errors_deg(
          nf.recordings[i], 30.0, *nf.campaign.recordings[i].true_azimuth_deg)));
    }
    NorthfindOptions s = stable_defaults();
    s.seed = seed;
    const auto st = simulate_stable(Instrument{}, s);
    ASSERT_EQ(st.campaign.recordings[0].scenario, Scenario::stable);
    stable.push_back(eval::rms(eval::northfind_errors_deg(
        st.recordings[0], 30.0, *st.campaign.recordings[0].true_azimuth_deg)));
  }
  // Paper Table 3: start-up raw mean 0.0209°, stable stage 0.012°.
  EXPECT_GT(mean(stable), 0.007);
  EXPECT_LT(mean(stable), 0.016);
  EXPECT_GT(mean(startup), 0.014);
  EXPECT_LT(mean(startup), 0.030);
  EXPECT_GT(mean(startup), 1.6 * mean(stable));
}

// The calibration approach makes a north-finding start-up look like a calibration start-up: at a
// calibration temperature, the thermometers at power-on match the calibration campaign's.
TEST(Northfind, CalibrationApproachPowersOnLikeTheCalibrationCampaign) {
  CalibrationOptions c;
  c.chamber_setpoint_sd_degc = 0.0;
  c.repetitions = 1;
  c.test_repetitions = 0;
  const auto cal = simulate_calibration(Instrument{}, c);
  NorthfindOptions soaked, approach;
  soaked.temps_degc = approach.temps_degc = {20.0};
  soaked.findings = approach.findings = 1;
  soaked.approach = Approach::soaked;
  const auto nf_soaked = simulate_northfind(Instrument{}, soaked);
  const auto nf = simulate_northfind(Instrument{}, approach);
  const double cal_fog = cal.recordings[6].numeric_column("temp_fog_degc")[0];
  ASSERT_EQ(cal.campaign.recordings[6].initial_temp_degc, 20.0);
  EXPECT_LT(cal_fog, 17.0);  // calibration powers on well below the chamber's 20 °C
  EXPECT_NEAR(nf.recordings[0].numeric_column("temp_fog_degc")[0], cal_fog, 0.5);  // of a 5 K lag
  EXPECT_NEAR(nf_soaked.recordings[0].numeric_column("temp_fog_degc")[0], 20.0, 0.05);
  // The manifest says how the start-ups began.
  EXPECT_NE(nf.campaign.generator_json.find(R"("approach":"calibration","soak_s":1200)"),
            std::string::npos)
      << nf.campaign.generator_json;
  EXPECT_NE(nf_soaked.campaign.generator_json.find(R"("approach":"soaked")"), std::string::npos);
  // A sweep from 20 to 40 °C powers on at 40 °C below the chamber too.
  NorthfindOptions sweep;
  sweep.temps_degc = {20.0, 40.0};
  sweep.findings = 1;
  sweep.approach = Approach::sweep;
  const auto nf_sweep = simulate_northfind(Instrument{}, sweep);
  EXPECT_NEAR(nf_sweep.recordings[0].numeric_column("temp_fog_degc")[0], 20.0, 0.05);
  EXPECT_LT(nf_sweep.recordings[1].numeric_column("temp_fog_degc")[0], 38.0);
}

// The 30 °C recording of one calibration sweep over `cal_temps` (set points reached exactly),
// and a north-finding start-up at 30 °C by the calibration approach, on `instrument`.
struct StartUpPair {
  Recording calibration;
  Recording northfind;
};

StartUpPair calibration_and_northfind_at_30(const Instrument& instrument,
                                            const std::vector<double>& cal_temps) {
  CalibrationOptions c;
  c.chamber_setpoint_sd_degc = 0.0;
  c.repetitions = 1;
  c.test_repetitions = 0;
  c.temps_degc = cal_temps;
  auto cal = simulate_calibration(instrument, c);
  const auto at_30 = std::find(cal_temps.begin(), cal_temps.end(), 30.0);
  NorthfindOptions approach;
  approach.temps_degc = {30.0};
  approach.findings = 1;
  auto nf = simulate_northfind(instrument, approach);
  return {std::move(cal.recordings.at(static_cast<std::size_t>(at_30 - cal_temps.begin()))),
          std::move(nf.recordings[0])};
}

// A start-up inherits the whole instrument its history left, not only its node temperatures: with
// a filtered-rate term (a state of its own, τ_F = 126 s), a north-finding start-up by the
// calibration approach begins with the calibration campaign's drift. When only the nodes were
// handed over, the filter restarted at power-on and this test failed at every time checked (on
// population unit 7, seed 1, the two start-ups began 0.04 °/h apart).
TEST(Northfind, AStartUpInheritsTheFilteredRateItsHistoryLeft) {
  Instrument instrument;
  instrument.fog.filtered_rate_dph_per_kps = 20.0;
  instrument.fog.filtered_rate_tau_s = 126.0;
  const StartUpPair p = calibration_and_northfind_at_30(instrument, {0.0, 10.0, 20.0, 30.0});
  const std::vector<double> cal_drift = p.calibration.numeric_column("drift_true_dph");
  const std::vector<double> nf_drift = p.northfind.numeric_column("drift_true_dph");
  // The filtered rate's share at power-on, against which the two must agree.
  const std::vector<double> plain_cal =
      calibration_and_northfind_at_30(Instrument{}, {0.0, 10.0, 20.0, 30.0})
          .calibration.numeric_column("drift_true_dph");
  ASSERT_GT(std::abs(cal_drift[0] - plain_cal[0]), 0.02);
  for (std::size_t k : {0, 60, 300})
    EXPECT_NEAR(nf_drift[k], cal_drift[k], 2e-3) << "t = " << k + 1;
}

// A slow instrument (its housing's unpowered time constant some 85 minutes, as on one member of
// docs/field.md's population) powers on in calibration ever further below the chamber as the
// cycles go on. A north-finding start-up by the calibration approach must carry the same lag,
// which two cycles of history did not build up (docs/simulator.md).
TEST(Northfind, ACalibrationLikeStartUpCarriesTheCalibrationsLag) {
  Instrument slow;
  slow.thermal.capacity_j_per_k[0] = 3500.0;
  slow.thermal.housing_air_w_per_k = 0.7;
  const StartUpPair p = calibration_and_northfind_at_30(slow, CalibrationOptions{}.temps_degc);
  const auto first_minute_mean = [](const std::vector<double>& v) {
    double s = 0.0;
    for (std::size_t k = 0; k < 60; ++k) s += v[k];
    return s / 60.0;
  };
  const double cal_fog = first_minute_mean(p.calibration.numeric_column("temp_fog_degc"));
  const double nf_fog = first_minute_mean(p.northfind.numeric_column("temp_fog_degc"));
  ASSERT_LT(cal_fog, 30.0 - 10.0);  // the lag this test is about
  EXPECT_NEAR(nf_fog, cal_fog, 0.05);
  const std::vector<double> cal_drift = p.calibration.numeric_column("drift_true_dph");
  const std::vector<double> nf_drift = p.northfind.numeric_column("drift_true_dph");
  for (std::size_t k : {0, 60, 300})
    EXPECT_NEAR(nf_drift[k], cal_drift[k], 2e-3) << "t = " << k + 1;
}

TEST(Scenarios, ImpossibleOptionsNameTheField) {
  CalibrationOptions c;
  c.repetitions = 0;
  EXPECT_THROW(simulate_calibration(Instrument{}, c), OptionError);
  c = CalibrationOptions{};
  c.temps_degc = {-40, 150};
  try {
    simulate_calibration(Instrument{}, c);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "calibration.temps_degc");  // the field; the CLI names its flag
  }
  c = CalibrationOptions{};
  c.output_rate_hz = 3.0;  // 1/3 s is not a whole number of 0.1 s steps
  EXPECT_THROW(simulate_calibration(Instrument{}, c), OptionError);
  NorthfindOptions n;
  n.findings = 0;
  EXPECT_THROW(simulate_northfind(Instrument{}, n), OptionError);
  n = NorthfindOptions{};
  n.position_s = 15;
  EXPECT_THROW(simulate_northfind(Instrument{}, n), OptionError);
  n = NorthfindOptions{};
  n.ramp_degc_per_min = 0.0;
  EXPECT_THROW(simulate_northfind(Instrument{}, n), OptionError);
  n = NorthfindOptions{};
  n.soak_s = -1.0;
  try {
    simulate_stable(Instrument{}, n);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "stable.soak_s");
  }
  try {
    approach_from_string("lukewarm", "--approach");
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("--approach"), std::string::npos);
  }
}

TEST(Scenarios, WrittenCampaignIsReadBackAndValid) {
  test::TempDir dir;
  CalibrationOptions o;
  o.temps_degc = {0, 10};
  o.repetitions = 2;
  const auto sim = simulate_calibration(Instrument{}, o);
  write_campaign(dir / "c", sim, false);
  const Campaign back = read_campaign(dir / "c");
  ASSERT_EQ(back.recordings.size(), 4u);
  for (std::size_t i = 0; i < back.recordings.size(); ++i) {
    const Recording r = read_recording(back.path_of(back.recordings[i]));
    EXPECT_EQ(r.gyro_dph, sim.recordings[i].gyro_dph);
    EXPECT_EQ(r.temp_fog_degc, sim.recordings[i].temp_fog_degc);
  }
  EXPECT_EQ(temperature_tag(-2.5), "m2.5C");
  EXPECT_EQ(temperature_tag(25), "25C");
}

}  // namespace
}  // namespace fogdrift::sim
