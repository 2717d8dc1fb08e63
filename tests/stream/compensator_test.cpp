// The streaming compensator: the causal differentiator bit for bit, and the batch path sample
// for sample. (No allocation per sample is proved in compensator_alloc_test.cpp, a program of
// its own because it replaces the global operator new.)
#include "fogdrift/stream/compensator.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/train.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

TEST(CausalDifferentiator, MatchesTheBatchFilterBitForBit) {
  Rng rng(4);
  std::vector<double> x(1000);
  double level = 20;
  for (double& v : x) v = std::round(100 * (level += 0.01 + rng.normal(0, 0.02))) / 100;
  for (int order : {1, 2, 3}) {
    signal::DifferentiatorOptions o;
    o.window_s = 61;
    o.poly_order = order;
    o.causality = signal::Causality::causal;
    const std::vector<double> batch = signal::differentiate(x, 0.5, o);
    signal::CausalDifferentiator stream(o, 0.5);
    for (std::size_t i = 0; i < x.size(); ++i)
      ASSERT_EQ(stream.push(x[i]), batch[i]) << "order " << order << " sample " << i;
  }
}

// The C header's streaming part (to_c_header with a sample interval), compiled by the C compiler
// and fed the recording sample by sample; returns its drift for every sample.
std::vector<double> c_header_stream(const CompensationModel& model, const Recording& rec,
                                    double dt_s = 1.0, CPrecision precision = CPrecision::double_) {
  test::TempDir dir;
  test::write_file(dir / "model.h", to_c_header(model, "fd", dt_s, {}, precision));
  test::write_file(dir / "driver.c", R"(#include <stdio.h>
#include "model.h"
int main(void) {
  fd_state s;
  double t, fog, acc1, acc2;
  fd_reset(&s);
  while (scanf("%lf %lf %lf %lf", &t, &fog, &acc1, &acc2) == 4)
    printf("%.17g\n", fd_update(&s, t, fog, acc1, acc2));
  return 0;
}
)");
  std::ostringstream samples;
  samples.precision(17);
  for (std::size_t i = 0; i < rec.size(); ++i)
    samples << rec.time_s[i] << ' ' << rec.temp_fog_degc[i] << ' ' << rec.temp_acc1_degc[i] << ' '
            << rec.temp_acc2_degc[i] << '\n';
  std::istringstream in(test::compile_and_run_c(dir, samples.str()));
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

// A model of `method` on causal rates of `features`, calibrated as the chamber does at
// `temps_degc` (`repetitions` sweeps of 900 s start-ups), with the interval of 1 Hz recorded.
CompensationModel causal_model(std::vector<double> temps_degc, int repetitions, Method method,
                               const FeatureSpec& features = default_feature_spec()) {
  sim::CalibrationOptions co;
  co.temps_degc = std::move(temps_degc);
  co.repetitions = repetitions;
  co.test_repetitions = 0;
  co.powered_s = 900;
  const sim::SimulatedCampaign sc = sim::simulate_calibration(sim::Instrument{}, co);
  const std::vector<RecordingInput> inputs =
      recording_inputs(sc.campaign, sc.recordings, std::nullopt);
  DatasetOptions dataset;
  dataset.features = features;
  dataset.preprocessing.rates.causality = signal::Causality::causal;
  dataset.preprocessing.sample_interval_s = 1.0;
  TrainOptions o;
  o.method = method;
  return train(build_dataset(inputs, dataset), dataset, o).model;
}

// A model trained on causal features, streamed over a test recording, gives the batch path's
// drift exactly; the C header's own streaming code gives it too.
TEST(StreamingCompensator, EqualsTheBatchPath) {
  sim::CalibrationOptions co;
  co.temps_degc = {-20, 30};
  co.repetitions = 3;
  co.powered_s = 900;
  const sim::SimulatedCampaign sc = sim::simulate_calibration(sim::Instrument{}, co);
  std::vector<RecordingInput> train_inputs;
  for (std::size_t i = 0; i < sc.recordings.size(); ++i) {
    const CampaignEntry& e = sc.campaign.recordings[i];
    if (e.role != Role::train) continue;
    RecordingInput in;
    in.recording = sc.recordings[i];
    in.info.file = e.file;
    in.info.repetition = e.repetition;
    in.info.initial_temp_degc = e.initial_temp_degc;
    in.latitude_deg = sc.campaign.latitude_deg;
    in.true_azimuth_deg = e.true_azimuth_deg;
    train_inputs.push_back(std::move(in));
  }
  DatasetOptions dataset;
  dataset.features = FeatureSpec::parse("T,dT,grad,TdT(fog)");
  dataset.preprocessing.rates.causality = signal::Causality::causal;
  const Dataset data = build_dataset(train_inputs, dataset);
  for (Method method : {Method::svr, Method::bp, Method::poly}) {
    TrainOptions o;
    o.method = method;
    o.trainers.get<MlpOptions>().max_epochs = 100;
    const CompensationModel model = train(data, dataset, o).model;
    const Recording& test = sc.recordings.back();
    const std::vector<double> batch = model.predict_dph(test);
    StreamingCompensator stream(model, 1.0);
    std::vector<double> streamed(test.size());
    for (std::size_t i = 0; i < test.size(); ++i)
      streamed[i] = stream
                        .update({test.time_s[i], test.gyro_dph[i], test.temp_fog_degc[i],
                                 test.temp_acc1_degc[i], test.temp_acc2_degc[i]})
                        .drift_dph;
    ASSERT_EQ(batch.size(), streamed.size());
    for (std::size_t i = 0; i < batch.size(); ++i)
      ASSERT_EQ(streamed[i], batch[i]) << to_string(method) << " sample " << i;
    stream.reset();
    EXPECT_EQ(stream
                  .update({test.time_s[0], test.gyro_dph[0], test.temp_fog_degc[0],
                           test.temp_acc1_degc[0], test.temp_acc2_degc[0]})
                  .drift_dph,
              batch[0]);

    const std::vector<double> in_c = c_header_stream(model, test);
    ASSERT_EQ(in_c.size(), streamed.size()) << to_string(method);
    double worst = 0, scale = 0;
    for (std::size_t i = 0; i < in_c.size(); ++i) {
      worst = std::max(worst, std::abs(in_c[i] - streamed[i]));
      scale = std::max(scale, std::abs(streamed[i]));
    }
    EXPECT_LE(worst, 1e-12 * scale) << to_string(method);
  }
}

// The rates through a lag (dT@τ, features.hpp LaggedRate): the streaming compensator gives the
// batch drift bit for bit and the C header to 1e-12, also across a bridged gap, where every path
// feeds the lags the gap's interpolated samples.
TEST(StreamingCompensator, ALaggedRateIsTheSameInEveryPath) {
  const CompensationModel model =
      causal_model({-20, 30}, 3, Method::svr, FeatureSpec::parse("T,dT,grad,dT@300(fog),dT@900"));
  sim::NorthfindOptions no;
  no.temps_degc = {10};
  no.findings = 1;
  no.output_rate_hz = 1;
  ASSERT_EQ(model.inputs(), 13u);
  Recording test = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  const std::vector<double> batch = model.predict_dph(test);
  StreamingCompensator stream(model, 1.0);
  std::vector<double> streamed;
  for (std::size_t i = 0; i < test.size(); ++i)
    streamed.push_back(stream
                           .update({test.time_s[i], 0.0, test.temp_fog_degc[i],
                                    test.temp_acc1_degc[i], test.temp_acc2_degc[i]})
                           .drift_dph);
  for (std::size_t i = 0; i < batch.size(); ++i) ASSERT_EQ(streamed[i], batch[i]) << i;
  EXPECT_GT(
      *std::max_element(batch.begin(), batch.end()) - *std::min_element(batch.begin(), batch.end()),
      0.01);  // °/h: a drift that moves, not a constant
  auto agree = [](const std::vector<double>& a, const std::vector<double>& b) {
    EXPECT_EQ(a.size(), b.size());
    double worst = 0, scale = 0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      worst = std::max(worst, std::abs(a[i] - b[i]));
      scale = std::max(scale, std::abs(b[i]));
    }
    EXPECT_LE(worst, 1e-12 * scale);
  };
  agree(c_header_stream(model, test), streamed);

  // Five samples lost 200 s after power-on: bridged, the lags fed the interpolated samples.
  ASSERT_GT(test.size(), 300u);
  for (auto* column : {&test.time_s, &test.gyro_dph, &test.temp_fog_degc, &test.temp_acc1_degc,
                       &test.temp_acc2_degc})
    column->erase(column->begin() + 200, column->begin() + 205);
  stream.reset();
  std::vector<double> gap;
  for (std::size_t i = 0; i < test.size(); ++i)
    gap.push_back(stream
                      .update({test.time_s[i], 0.0, test.temp_fog_degc[i], test.temp_acc1_degc[i],
                               test.temp_acc2_degc[i]})
                      .drift_dph);
  EXPECT_NEAR(gap[250], batch[255], 1e-3 * std::abs(batch[255]) + 1e-6);
  agree(c_header_stream(model, test), gap);
}

// Every axis in one header (to_c_header of a model set): one update gives each axis's drift as
// that axis's StreamingCompensator does, and the compensated gyros follow.
TEST(StreamingCompensator, OneUpdateForEveryAxisInTheHeader) {
  ModelSet set;
  set.models = {causal_model({-20, 30}, 2, Method::poly), causal_model({-20, 30}, 2, Method::svr)};
  set.models[1].dataset.target_column = "gyro_y_dph";
  const Recording test = sim::simulate_calibration(sim::Instrument{},
                                                   [] {
                                                     sim::CalibrationOptions co;
                                                     co.temps_degc = {10};
                                                     co.repetitions = 1;
                                                     co.powered_s = 600;
                                                     return co;
                                                   }())
                             .recordings.front();
  test::TempDir dir;
  test::write_file(dir / "imu.h", to_c_header(set, "imu", 1.0));
  test::write_file(dir / "driver.c", R"(#include <stdio.h>
#include "imu.h"
int main(void) {
  imu_state s;
  double t, fog, acc1, acc2, drift[IMU_N_AXES], gyro[IMU_N_AXES] = {1.0, -2.0}, comp[IMU_N_AXES];
  imu_reset(&s);
  printf("%s %s\n", imu_axis_names[0], imu_axis_names[1]);
  while (scanf("%lf %lf %lf %lf", &t, &fog, &acc1, &acc2) == 4) {
    imu_update(&s, t, fog, acc1, acc2, drift);
    imu_compensated_dph(&s, gyro, comp);
    printf("%.17g %.17g %.17g %.17g\n", drift[0], drift[1], comp[0], comp[1]);
  }
  return 0;
}
)");
  std::ostringstream samples;
  samples.precision(17);
  for (std::size_t i = 0; i < test.size(); ++i)
    samples << test.time_s[i] << ' ' << test.temp_fog_degc[i] << ' ' << test.temp_acc1_degc[i]
            << ' ' << test.temp_acc2_degc[i] << '\n';
  std::istringstream in(test::compile_and_run_c(dir, samples.str()));
  std::string x_name, y_name;
  in >> x_name >> y_name;
  EXPECT_EQ(x_name, "gyro_dph");
  EXPECT_EQ(y_name, "gyro_y_dph");
  StreamingCompensator x(set.models[0], 1.0), y(set.models[1], 1.0);
  double worst = 0, scale = 0;
  std::size_t rows = 0;
  for (double dx, dy, cx, cy; in >> dx >> dy >> cx >> cy; ++rows) {
    ASSERT_LT(rows, test.size());
    const Sample sample{test.time_s[rows], 0.0, test.temp_fog_degc[rows], test.temp_acc1_degc[rows],
                        test.temp_acc2_degc[rows]};
    const double ex = x.update(sample).drift_dph, ey = y.update(sample).drift_dph;
    worst = std::max({worst, std::abs(dx - ex), std::abs(dy - ey)});
    scale = std::max({scale, std::abs(ex), std::abs(ey)});
    ASSERT_EQ(cx, 1.0 - dx);
    ASSERT_EQ(cy, -2.0 - dy);
  }
  EXPECT_EQ(rows, test.size());
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(worst, 1e-12 * scale);
  // A set of one model is that model's own header.
  ModelSet one;
  one.models = {set.models[0]};
  EXPECT_EQ(to_c_header(one, "imu", 1.0), to_c_header(set.models[0], "imu", 1.0));
  EXPECT_THROW(to_c_header(set, "2imu", 1.0), OptionError);
}

// Another target (target.hpp, docs/logs.md "Other targets"): an accelerometer's reading is a fault
// only when it is not a number, in the streaming compensator and in the header, whose names are
// in g and whose range check the firmware may switch on.
TEST(StreamingCompensator, AnAccelerometerReadingIsCheckedForANumber) {
  CompensationModel model = causal_model({-20, 30}, 2, Method::poly);
  model.dataset.target_column = "accel_x_g";
  StreamingCompensator s(model, 1.0);
  const double huge = 1e9;  // beyond any gyro's limit, and not a number to refuse here
  EXPECT_EQ(s.update({0.0, huge, 20, 20, 20}).flags & fault::gyro_bad, 0u);
  EXPECT_NE(s.update({1.0, std::nan(""), 20, 20, 20}).flags & fault::gyro_bad, 0u);
  const std::string h = to_c_header(model, "acc", 1.0);
  EXPECT_NE(h.find("static inline acc_real acc_compensated_g(acc_state* s, acc_real accel_x_g)"),
            std::string::npos);
  EXPECT_NE(h.find("static inline acc_real acc_predict_g("), std::string::npos);
  EXPECT_NE(h.find("#define ACC_READING_LIMIT_G (HUGE_VAL)"), std::string::npos);
  EXPECT_EQ(h.find("_dph"), std::string::npos) << "a name in °/h in an accelerometer's header";
  // The compensator's code (src/firmware/compensator.h) under the header's prefix, none of its own
  // names left.
  EXPECT_NE(h.find("static inline acc_real acc_update_(acc_state* s, double time_s,"),
            std::string::npos);
  EXPECT_EQ(h.find("fds_"), std::string::npos);
  EXPECT_EQ(h.find("FDS_"), std::string::npos);
  test::TempDir dir;
  test::write_file(dir / "acc.h", h);
  // The same reading with the header's default and with a range the firmware sets.
  for (const std::string& define :
       {std::string(), std::string("#define ACC_READING_LIMIT_G 8.0\n")}) {
    test::write_file(dir / "driver.c", define + R"(#include <stdio.h>
#include "acc.h"
int main(void) {
  acc_state s;
  acc_reset(&s);
  acc_update(&s, 0.0, 20.0, 20.0, 20.0);
  acc_compensated_g(&s, 1e9);
  printf("%u ", s.flags & ACC_FAULT_GYRO_BAD ? 1u : 0u);
  acc_compensated_g(&s, 0.5);
  printf("%u\n", s.flags & ACC_FAULT_GYRO_BAD ? 1u : 0u);
  return 0;
}
)");
    std::istringstream out(test::compile_and_run_c(dir, ""));
    unsigned huge_bad = 2, small_bad = 2;
    out >> huge_bad >> small_bad;
    EXPECT_EQ(huge_bad, define.empty() ? 0u : 1u) << define;
    EXPECT_EQ(small_bad, define.empty() ? 0u : 1u) << "the flag stays until the next update";
  }
}

// A fourth thermometer (docs/logs.md, "More thermometers"): a case heater cycling with its own
// phase in every recording, read by temp_case_degc and by none of the three, and a drift term in
// the case's difference from the coil. `add_case` gives a recording that column and that term.
void add_case(Recording& r, double phase, std::vector<double>* truth = nullptr) {
  ExtraColumn column{"temp_case_degc", {}};
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double excess = 3.0 * std::sin(2 * std::acos(-1.0) * r.time_s[i] / 400.0 + phase);
    column.cells.push_back(fmt::format("{:.17g}", r.temp_fog_degc[i] + excess));
    r.gyro_dph[i] += 4.0 * excess / 3.0;  // 4 °/h at the heater's peak
    if (truth != nullptr) truth->push_back(4.0 * excess / 3.0);
  }
  r.extra.push_back(std::move(column));
}

// A model that reads the fourth thermometer removes the term the three cannot see; the batch
// path, the streaming compensator (at 1 Hz and on blocks of a 10 Hz logger) and the C header,
// whose update takes the fourth temperature, agree.
TEST(StreamingCompensator, AFourthThermometerIsReadEverywhere) {
  sim::CalibrationOptions co;
  co.temps_degc = {-20, 10, 40};
  co.repetitions = 2;
  co.test_repetitions = 0;
  co.powered_s = 900;
  sim::SimulatedCampaign sc = sim::simulate_calibration(sim::Instrument{}, co);
  std::vector<RecordingInput> inputs;
  for (std::size_t i = 0; i < sc.recordings.size(); ++i) {
    add_case(sc.recordings[i], 0.9 * static_cast<double>(i));
    inputs.push_back(recording_input(sc.campaign, sc.campaign.recordings[i], sc.recordings[i]));
  }
  auto trained = [&](const std::vector<std::string>& thermometers) {
    DatasetOptions dataset;
    dataset.features = FeatureSpec::parse("T,dT,grad", thermometers);
    dataset.preprocessing.rates.causality = signal::Causality::causal;
    dataset.preprocessing.sample_interval_s = 1.0;
    TrainOptions o;
    o.method = Method::poly;
    return train(build_dataset(inputs, dataset), dataset, o).model;
  };
  const CompensationModel three = trained({}), four = trained({"fog", "acc1", "acc2", "case"});
  ASSERT_EQ(four.dataset.features.further, std::vector<std::string>{"case"});
  EXPECT_EQ(four.dataset.features.to_string(),
            "T(fog,acc1,acc2,case),dT(fog,acc1,acc2,case),grad(fog,acc1,acc2,case)");
  EXPECT_EQ(four.inputs(), 14u);  // 4 T, 4 dT, 6 gradients

  // A start-up the calibration did not hold, with its own heater phase.
  sim::NorthfindOptions no;
  no.temps_degc = {25};
  no.findings = 1;
  no.output_rate_hz = 1;
  Recording test = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  std::vector<double> case_term;
  add_case(test, 2.0, &case_term);
  const std::vector<double> truth = test.numeric_column("drift_true_dph");
  auto error_rms = [&](const std::vector<double>& drift) {  // the turn-on bias aside
    double mean = 0, var = 0;
    const auto n = static_cast<double>(drift.size());
    for (std::size_t i = 0; i < drift.size(); ++i) mean += (drift[i] - truth[i] - case_term[i]) / n;
    for (std::size_t i = 0; i < drift.size(); ++i)
      var += std::pow(drift[i] - truth[i] - case_term[i] - mean, 2) / n;
    return std::sqrt(var);
  };
  const std::vector<double> batch = four.predict_dph(test);
  const double with_case = error_rms(batch), without = error_rms(three.predict_dph(test));
  EXPECT_LT(with_case, 0.5 * without)
      << with_case << " °/h with the case, " << without << " °/h without";

  // The streaming compensator, given the case column sample by sample, gives the batch drift.
  auto streams_as_batch = [&](const Recording& rec, double dt_s) {
    const std::vector<double> expected = four.predict_dph(rec);
    const std::vector<double> case_degc = rec.numeric_column("temp_case_degc");
    StreamingCompensator stream(four, dt_s);
    for (std::size_t i = 0; i < rec.size(); ++i)
      ASSERT_EQ(
          stream
              .update({rec.time_s[i], rec.gyro_dph[i], rec.temp_fog_degc[i], rec.temp_acc1_degc[i],
                       rec.temp_acc2_degc[i], std::span<const double>(&case_degc[i], 1)})
              .drift_dph,
          expected[i])
          << "every " << dt_s << " s, sample " << i;
  };
  streams_as_batch(test, 1.0);

  const std::vector<double> further = test.numeric_column("temp_case_degc");
  {  // A sample without the fourth temperature is a faulty reading, bridged, not a crash.
    StreamingCompensator stream(four, 1.0);
    for (std::size_t i = 0; i < 200; ++i) {
      const StreamOutput out =
          i == 150
              ? stream.update({test.time_s[i], 0.0, test.temp_fog_degc[i], test.temp_acc1_degc[i],
                               test.temp_acc2_degc[i]})
              : stream.update({test.time_s[i], 0.0, test.temp_fog_degc[i], test.temp_acc1_degc[i],
                               test.temp_acc2_degc[i], std::span<const double>(&further[i], 1)});
      EXPECT_EQ((out.flags & fault::temp_bad) != 0, i == 150) << i;
      EXPECT_TRUE(std::isfinite(out.drift_dph)) << i;
    }
  }
  test::TempDir dir;
  test::write_file(dir / "model.h", to_c_header(four, "fd", 1.0));
  test::write_file(dir / "driver.c", R"(#include <stdio.h>
#include "model.h"
int main(void) {
  fd_state s;
  double t, fog, acc1, acc2, case_degc;
  fd_reset(&s);
  while (scanf("%lf %lf %lf %lf %lf", &t, &fog, &acc1, &acc2, &case_degc) == 5)
    printf("%.17g\n", fd_update(&s, t, fog, acc1, acc2, case_degc));
  return 0;
}
)");
  std::ostringstream samples;
  samples.precision(17);
  for (std::size_t i = 0; i < test.size(); ++i)
    samples << test.time_s[i] << ' ' << test.temp_fog_degc[i] << ' ' << test.temp_acc1_degc[i]
            << ' ' << test.temp_acc2_degc[i] << ' ' << further[i] << '\n';
  std::istringstream in(test::compile_and_run_c(dir, samples.str()));
  std::size_t rows = 0;
  for (double v; in >> v; ++rows) {
    ASSERT_LT(rows, batch.size());
    ASSERT_NEAR(v, batch[rows], 1e-12 * std::abs(batch[rows]) + 1e-15) << rows;
  }
  EXPECT_EQ(rows, batch.size());

  // Every axis in one header: the set's update takes the union of the axes' thermometers, and
  // an axis that reads three is given three.
  ModelSet set;
  set.models = {four, three};
  set.models[1].dataset.target_column = "gyro_y_dph";
  test::write_file(dir / "imu.h", to_c_header(set, "imu", 1.0));
  test::write_file(dir / "driver.c", R"(#include <stdio.h>
#include "imu.h"
int main(void) {
  imu_state s;
  double t, fog, acc1, acc2, case_degc, drift[IMU_N_AXES];
  imu_reset(&s);
  while (scanf("%lf %lf %lf %lf %lf", &t, &fog, &acc1, &acc2, &case_degc) == 5) {
    imu_update(&s, t, fog, acc1, acc2, case_degc, drift);
    printf("%.17g %.17g\n", drift[0], drift[1]);
  }
  return 0;
}
)");
  std::istringstream both(test::compile_and_run_c(dir, samples.str()));
  const std::vector<double> y_batch = three.predict_dph(test);
  rows = 0;
  for (double x, y; both >> x >> y; ++rows) {
    ASSERT_LT(rows, batch.size());
    ASSERT_NEAR(x, batch[rows], 1e-12 * std::abs(batch[rows]) + 1e-15) << rows;
    ASSERT_NEAR(y, y_batch[rows], 1e-12 * std::abs(y_batch[rows]) + 1e-15) << rows;
  }
  EXPECT_EQ(rows, batch.size());

  // A 10 Hz logger: blocks of 10 samples, the fourth thermometer averaged with the others.
  no.output_rate_hz = 10;
  Recording fast = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  add_case(fast, 2.0);
  streams_as_batch(fast, 0.1);
}

// A model trained at 1 Hz runs on a 10 Hz logger on blocks of 10 samples (decimate.hpp): the
// batch path, the streaming compensator and the C header agree sample for sample, the drift
// changes only where a block completes, and it is close to the 1 Hz drift of the same start-up.
TEST(StreamingCompensator, RunsAFasterLoggerOnBlocks) {
  const CompensationModel model = causal_model({-20, 30}, 3, Method::poly);

  sim::NorthfindOptions no;
  no.temps_degc = {5};
  no.findings = 1;
  no.output_rate_hz = 10;
  const Recording fast = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  const RecordingPrediction batch = model.predict(fast);
  ASSERT_EQ(batch.drift_dph.size(), fast.size());
  StreamingCompensator stream(model, 0.1);
  for (std::size_t i = 0; i < fast.size(); ++i) {
    const StreamOutput out = stream.update({fast.time_s[i], fast.gyro_dph[i], fast.temp_fog_degc[i],
                                            fast.temp_acc1_degc[i], fast.temp_acc2_degc[i]});
    ASSERT_EQ(out.drift_dph, batch.drift_dph[i]) << i;
    ASSERT_EQ(out.flags, 0u) << i;
    if (i % 10 != 0) {
      ASSERT_EQ(batch.drift_dph[i], batch.drift_dph[i - 1]) << i;
    }
  }
  const std::vector<double> in_c = c_header_stream(model, fast, 0.1);
  ASSERT_EQ(in_c.size(), fast.size());
  for (std::size_t i = 0; i < fast.size(); ++i)
    ASSERT_NEAR(in_c[i], batch.drift_dph[i], 1e-12 * std::abs(batch.drift_dph[i]) + 1e-15) << i;

  // The same start-up logged at 1 Hz: the block means are less noisy samples of the same
  // temperatures, so the drift at 10 Hz follows the simulator's true drift no worse (STD of the
  // error, the turn-on bias aside).
  no.output_rate_hz = 1;
  const Recording slow = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  auto error_std = [](const std::vector<double>& drift, const std::vector<double>& truth) {
    std::vector<double> e;
    for (std::size_t i = 0; i < drift.size(); ++i) e.push_back(drift[i] - truth[i]);
    double mean = 0, var = 0;
    for (double v : e) mean += v / static_cast<double>(e.size());
    for (double v : e) var += (v - mean) * (v - mean) / static_cast<double>(e.size());
    return std::sqrt(var);
  };
  const double at_10hz = error_std(batch.drift_dph, fast.numeric_column("drift_true_dph"));
  const double at_1hz = error_std(model.predict_dph(slow), slow.numeric_column("drift_true_dph"));
  EXPECT_LT(at_10hz, 1.05 * at_1hz) << at_10hz << " °/h against " << at_1hz << " °/h at 1 Hz";
}

// The header in float (export-c --precision float), on the host: every drift within 1e-3 of the
// drift's STD of the library's (tests/firmware runs it on a Cortex-M4F).
TEST(StreamingCompensator, FloatHeaderWithinAThousandthOfTheDriftsStd) {
  for (const Method method : {Method::poly, Method::svr}) {
    const CompensationModel model = causal_model({-20, 10, 40}, 2, method);
    sim::NorthfindOptions no;
    no.temps_degc = {25};
    no.findings = 2;
    const Recording test = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
    const std::vector<double> batch = model.predict_dph(test);
    const std::vector<double> in_float = c_header_stream(model, test, 1.0, CPrecision::single);
    ASSERT_EQ(in_float.size(), batch.size());
    double mean = 0, var = 0, worst = 0;
    for (double v : batch) mean += v / static_cast<double>(batch.size());
    for (double v : batch) var += (v - mean) * (v - mean) / static_cast<double>(batch.size());
    for (std::size_t i = 0; i < batch.size(); ++i)
      worst = std::max(worst, std::abs(in_float[i] - batch[i]));
    EXPECT_LT(worst, 1e-3 * std::sqrt(var)) << to_string(method);
    EXPECT_GT(worst, 0.0) << "float should differ from double somewhere";
  }
}

// A start-up unlike the calibration (soaked at 45 °C, where the model saw only the chamber's
// protocol at 0, 10 and 20 °C) trips the novelty guard from the first sample, while the rate
// window still fills; the guarded drift is the same in the batch path, the streaming compensator
// and the compiled C header, and where the weight is 0 the correction is the constant mean drift
// only.
TEST(StreamingCompensator, GuardsNovelStartUpsAlikeInEveryPath) {
  const CompensationModel model = causal_model({0, 10, 20}, 2, Method::svr);
  ASSERT_FALSE(model.guard.empty());

  sim::NorthfindOptions no;
  no.temps_degc = {45};
  no.findings = 2;
  no.approach = sim::Approach::soaked;
  const Recording test = sim::simulate_northfind(sim::Instrument{}, no).recordings.front();
  const RecordingPrediction batch = model.predict(test);
  const std::vector<double> unguarded = model.predict_dph(test, false);
  std::size_t zero = 0;
  for (std::size_t i = 0; i < test.size(); ++i) {
    ASSERT_GE(batch.weight[i], 0.0);
    ASSERT_LE(batch.weight[i], 1.0);
    if (batch.weight[i] == 0.0) {
      ++zero;
      ASSERT_EQ(batch.drift_dph[i], model.y_scaler.mean[0]) << i;
    }
    if (batch.weight[i] == 1.0) {
      ASSERT_EQ(batch.drift_dph[i], unguarded[i]) << i;
    }
  }
  EXPECT_GT(zero, test.size() / 2) << "the soaked start-up should be novel to this model";
  EXPECT_EQ(batch.weight[0], 0.0) << "novel temperatures count during the warm-up too";

  StreamingCompensator stream(model, 1.0);
  for (std::size_t i = 0; i < test.size(); ++i) {
    ASSERT_EQ(stream
                  .update({test.time_s[i], test.gyro_dph[i], test.temp_fog_degc[i],
                           test.temp_acc1_degc[i], test.temp_acc2_degc[i]})
                  .drift_dph,
              batch.drift_dph[i])
        << i;
    ASSERT_EQ(stream.novelty(), batch.novelty[i]) << i;
    ASSERT_EQ(stream.weight(), batch.weight[i]) << i;
  }
  const std::vector<double> in_c = c_header_stream(model, test);
  ASSERT_EQ(in_c.size(), test.size());
  double worst = 0, scale = 0;
  for (std::size_t i = 0; i < in_c.size(); ++i) {
    worst = std::max(worst, std::abs(in_c[i] - batch.drift_dph[i]));
    scale = std::max(scale, std::abs(batch.drift_dph[i]));
  }
  EXPECT_LE(worst, 1e-12 * scale);
}

// The differentiator's warm-up does not switch a causal model off (docs/field.md, "The guard at
// power-on"): on start-ups like its calibration, at a temperature between two of it, the guard
// keeps the full correction from the first sample, where the first rates come from fits to one,
// two, three samples. Before the warm-up rule, ν reached 10-50 there and the latched weight was
// 0 for the whole start-up.
TEST(StreamingCompensator, WarmUpDoesNotSwitchACausalModelOff) {
  const CompensationModel model = causal_model({0, 20, 40}, 2, Method::svr);

  sim::NorthfindOptions no;
  no.temps_degc = {10, 30};
  no.findings = 2;
  for (const Recording& test : sim::simulate_northfind(sim::Instrument{}, no).recordings) {
    StreamingCompensator stream(model, 1.0);
    double warm_max = 0;
    for (std::size_t i = 0; i < test.size(); ++i) {
      stream.update({test.time_s[i], test.gyro_dph[i], test.temp_fog_degc[i],
                     test.temp_acc1_degc[i], test.temp_acc2_degc[i]});
      if (i < 120) warm_max = std::max(warm_max, stream.novelty());
      ASSERT_EQ(stream.weight(), 1.0) << test.source << " sample " << i;
    }
    EXPECT_LT(warm_max, model.guard.settings.full_at) << test.source;
    // The batch path and the C header keep the correction too, sample for sample.
    const RecordingPrediction batch = model.predict(test);
    EXPECT_EQ(batch.novelty.back(), stream.novelty());
    const std::vector<double> in_c = c_header_stream(model, test);
    ASSERT_EQ(in_c.size(), test.size());
    for (std::size_t i = 0; i < test.size(); ++i) {
      ASSERT_EQ(batch.weight[i], 1.0) << i;
      ASSERT_NEAR(in_c[i], batch.drift_dph[i], 1e-12 * std::abs(batch.drift_dph[i]) + 1e-15) << i;
    }
  }
}

}  // namespace
}  // namespace fogdrift
