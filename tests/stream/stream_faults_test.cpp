// The streaming compensator under sensor faults (stream_faults.hpp, docs/compensation.md):
// each rule of the policy on a hand-made fault, random faults injected into long simulated
// streams (finite output, every faulty sample flagged, recovery to the fault-free output bit for
// bit), and the C header of export-c running the same policy.
#include "fogdrift/stream/stream_faults.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/train/train.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

const double kNan = std::nan("");

TEST(FaultPolicy, ValidateNamesTheField) {
  EXPECT_NO_THROW(validate(FaultPolicy{}));
  auto field_of = [](const FaultPolicy& p) {
    try {
      validate(p);
    } catch (const OptionError& e) {
      return e.option();
    }
    return std::string("(none)");
  };
  FaultPolicy p;
  p.temp_min_degc = 200;
  EXPECT_EQ(field_of(p), "faults.temp_max_degc");
  p = {};
  p.gyro_limit_dph = 0;
  EXPECT_EQ(field_of(p), "faults.gyro_limit_dph");
  p = {};
  p.bridge_s = -1;
  EXPECT_EQ(field_of(p), "faults.bridge_s");
  p = {};
  p.hold_s = 2;  // below bridge_s
  EXPECT_EQ(field_of(p), "faults.hold_s");
  p = {};
  p.stuck_s = kNan;
  EXPECT_EQ(field_of(p), "faults.stuck_s");
  p = {};
  p.stuck_delta_degc = 0;
  EXPECT_EQ(field_of(p), "faults.stuck_delta_degc");
  p = {};
  p.temp_jump_degc = -1;
  EXPECT_EQ(field_of(p), "faults.temp_jump_degc");
  p.temp_jump_degc = kNan;
  EXPECT_EQ(field_of(p), "faults.temp_jump_degc");
  p.temp_jump_degc = 0;  // the check switched off
  EXPECT_EQ(field_of(p), "(none)");
}

TEST(FaultPolicy, DescribesFlagsByName) {
  EXPECT_EQ(fault::describe(0), "");
  EXPECT_EQ(fault::describe(fault::temp_bad | fault::bridged), "temp_bad|bridged");
  EXPECT_EQ(fault::describe(fault::stopped), "stopped");
  for (std::size_t k = 0; k < fault::count; ++k) EXPECT_FALSE(fault::names()[k].empty());
}

// A model trained on causal features of a simulated calibration, and a long test start-up.
struct Fixture {
  CompensationModel model;
  Recording test;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    sim::CalibrationOptions co;
    co.temps_degc = {-20, 30};
    co.repetitions = 3;
    co.powered_s = 1800;
    const sim::SimulatedCampaign sc = sim::simulate_calibration(sim::Instrument{}, co);
    const std::vector<RecordingInput> inputs =
        recording_inputs(sc.campaign, sc.recordings, Role::train);
    DatasetOptions dataset;
    dataset.preprocessing.rates.causality = signal::Causality::causal;
    const Dataset data = build_dataset(inputs, dataset);
    TrainOptions o;
    o.method = Method::svr;
    return Fixture{train(data, dataset, o).model, sc.recordings.back()};
  }();
  return f;
}

Sample sample_of(const Recording& r, std::size_t i) {
  return {r.time_s[i], r.gyro_dph[i], r.temp_fog_degc[i], r.temp_acc1_degc[i], r.temp_acc2_degc[i]};
}

std::vector<StreamOutput> run(const std::vector<Sample>& samples, const StreamOptions& o = {}) {
  StreamingCompensator c(fixture().model, 1.0, o);
  std::vector<StreamOutput> out;
  for (const Sample& s : samples) out.push_back(c.update(s));
  return out;
}

std::vector<Sample> clean_samples() {
  const Recording& r = fixture().test;
  std::vector<Sample> s;
  for (std::size_t i = 0; i < r.size(); ++i) s.push_back(sample_of(r, i));
  return s;
}

std::size_t window() {
  return signal::window_samples(fixture().model.dataset.preprocessing.rates, 1.0);
}

TEST(StreamFaults, WithoutFaultsNothingIsFlaggedAndTheBatchPathHolds) {
  const std::vector<StreamOutput> out = run(clean_samples());
  const std::vector<double> batch = fixture().model.predict_dph(fixture().test);
  ASSERT_EQ(out.size(), batch.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    ASSERT_EQ(out[i].flags, 0u) << i;
    ASSERT_EQ(out[i].drift_dph, batch[i]) << i;
    ASSERT_EQ(out[i].gyro_comp_dph, fixture().test.gyro_dph[i] - batch[i]) << i;
  }
}

TEST(StreamFaults, ABadReadingIsBridgedAlongItsRate) {
  std::vector<Sample> s = clean_samples();
  s[600].temp_fog_degc = kNan;
  s[601].temp_acc1_degc = 900;  // out of range
  const std::vector<StreamOutput> out = run(s), clean = run(clean_samples());
  EXPECT_EQ(out[600].flags, fault::temp_bad | fault::bridged);
  EXPECT_EQ(out[601].flags, fault::temp_bad | fault::bridged);
  EXPECT_EQ(out[602].flags, 0u);
  // The stand-in continues the thermometer along its rate: the drift barely moves.
  EXPECT_NEAR(out[600].drift_dph, clean[600].drift_dph, 1e-3);
  EXPECT_EQ(out[602 + window()].drift_dph, clean[602 + window()].drift_dph);
}

TEST(StreamFaults, ALongOutageHoldsThenStopsThenRecovers) {
  FaultPolicy p;
  p.bridge_s = 5;
  p.hold_s = 60;
  std::vector<Sample> s = clean_samples();
  for (std::size_t i = 500; i < 600; ++i) s[i].temp_acc2_degc = kNan;  // 100 s
  const std::vector<StreamOutput> out = run(s, {true, p});
  const double held = out[504].drift_dph;
  for (std::size_t i = 500; i <= 504; ++i)
    EXPECT_EQ(out[i].flags, fault::temp_bad | fault::bridged);
  // Beyond 5 s the thermometer is out: the last good drift is held for 60 s, then the correction
  // stops (the model's mean drift).
  for (std::size_t i = 505; i <= 564; ++i) {
    EXPECT_EQ(out[i].flags, fault::temp_bad | fault::held) << i;
    EXPECT_EQ(out[i].drift_dph, held) << i;
  }
  for (std::size_t i = 565; i < 600; ++i) {
    EXPECT_EQ(out[i].flags, fault::temp_bad | fault::stopped) << i;
    EXPECT_EQ(out[i].drift_dph, fixture().model.y_scaler.mean[0]) << i;
  }
  // Back: the rate filters start again; until their window is full the drift is not the model's
  // (held is over, so stopped), then it is the fault-free drift, bit for bit.
  const std::size_t w = window();
  for (std::size_t i = 600; i < 600 + w - 1; ++i) EXPECT_EQ(out[i].flags, fault::stopped) << i;
  const std::vector<StreamOutput> clean = run(clean_samples());
  for (std::size_t i = 600 + w - 1; i < out.size(); ++i) {
    ASSERT_EQ(out[i].flags, 0u) << i;
    ASSERT_EQ(out[i].drift_dph, clean[i].drift_dph) << i;
  }
}

TEST(StreamFaults, GapsAreBridgedOrRestartTheRates) {
  std::vector<Sample> s = clean_samples();
  s.erase(s.begin() + 300, s.begin() + 303);  // 3 samples lost: bridged
  s.erase(s.begin() + 900, s.begin() + 930);  // 30 s lost: too long to bridge
  const std::vector<StreamOutput> out = run(s);
  EXPECT_EQ(out[299].flags, 0u);
  EXPECT_EQ(out[300].flags, fault::gap);
  EXPECT_EQ(out[301].flags, 0u);
  // Held at the drift before the gap for hold_s (300 s) after it, longer than the refill.
  EXPECT_EQ(out[900].flags, fault::gap | fault::held);
  for (std::size_t i = 901; i < 900 + window() - 1; ++i) EXPECT_EQ(out[i].flags, fault::held) << i;
  EXPECT_EQ(out[900 + window() - 1].flags, 0u);
  EXPECT_EQ(out[900].drift_dph, out[899].drift_dph);
}

// Found by an attack (issue 57): 2 Hz data streamed as 1 Hz had no flag on any line. A step
// within ±10 % of the interval is one; outside it (and neither out of order nor a gap) it is
// flagged off_interval, at the model's interval and, for a faster logger, at the data's.
TEST(StreamFaults, AStepOffTheIntervalIsFlagged) {
  std::vector<Sample> s = clean_samples();
  s.resize(200);
  for (std::size_t i = 0; i < s.size(); ++i) s[i].time_s = 0.5 * static_cast<double>(i);
  const std::vector<StreamOutput> twice = run(s);
  EXPECT_EQ(twice[0].flags, 0u);
  for (std::size_t i = 1; i < twice.size(); ++i)
    ASSERT_EQ(twice[i].flags & fault::off_interval, fault::off_interval) << i;
  for (std::size_t i = 0; i < s.size(); ++i)
    s[i].time_s = static_cast<double>(i) + (i % 2 ? 0.09 : 0.0);  // steps of 1.09 and 0.91 s
  for (const StreamOutput& o : run(s)) ASSERT_EQ(o.flags & fault::off_interval, 0u);
  for (std::size_t i = 0; i < s.size(); ++i) s[i].time_s = 1.2 * static_cast<double>(i);
  const std::vector<StreamOutput> slow = run(s);
  for (std::size_t i = 1; i < slow.size(); ++i)
    ASSERT_EQ(slow[i].flags & fault::off_interval, fault::off_interval) << i;
  // A 10 Hz logger: its steps are checked at 0.1 s.
  CompensationModel model = fixture().model;
  model.dataset.preprocessing.sample_interval_s = 1.0;  // as train_campaign records it
  StreamingCompensator fast(model, 0.1);
  Sample x = clean_samples()[0];
  std::uint32_t flags = 0;
  for (int i = 0; i < 40; ++i) {
    x.time_s = 0.05 * i;  // 20 Hz data as 10 Hz
    flags |= i > 0 ? fast.update(x).flags : 0u;
  }
  EXPECT_EQ(flags & fault::off_interval, fault::off_interval);
  EXPECT_EQ(kIntervalTolerance, 0.10);
}

// A rate given with four digits runs on the model's own interval (decimate.hpp,
// streaming_interval_s): the drifts are those of the exact rate, bit for bit.
TEST(StreamFaults, ARateRoundedToFourDigitsRunsAsTheModelsOwn) {
  const std::vector<Sample> s = clean_samples();
  CompensationModel model = fixture().model;
  model.dataset.preprocessing.sample_interval_s = 1.0;  // as train_campaign records it
  StreamingCompensator exact(model, 1.0), rounded(model, 1.0 / 1.0004);
  for (std::size_t i = 0; i < 300; ++i)
    ASSERT_EQ(exact.update(s[i]).drift_dph, rounded.update(s[i]).drift_dph) << i;
}

TEST(StreamFaults, TimeThatDoesNotAdvanceIsSkippedAndGoingBackRestarts) {
  std::vector<Sample> s = clean_samples();
  Sample repeat = s[200];
  repeat.temp_fog_degc += 5;  // a replayed sample must not disturb anything
  s.insert(s.begin() + 201, repeat);
  s[400].time_s = kNan;
  std::vector<Sample> restarted(s.begin(), s.begin() + 700);
  restarted.insert(restarted.end(), s.begin() + 1, s.end());  // power cycle: time from 1 s again
  const std::vector<StreamOutput> out = run(restarted);
  const std::vector<StreamOutput> clean = run(clean_samples());
  EXPECT_EQ(out[201].flags, fault::out_of_order);
  EXPECT_EQ(out[201].drift_dph, out[200].drift_dph);
  EXPECT_EQ(out[202].flags, 0u);
  EXPECT_EQ(out[202].drift_dph, clean[201].drift_dph);
  EXPECT_EQ(out[400].flags, fault::time_bad);  // taken as one step on: it was
  EXPECT_EQ(out[400].drift_dph, clean[399].drift_dph);
  EXPECT_EQ(out[700].flags, fault::restart);
  StreamingCompensator fresh(fixture().model, 1.0);
  EXPECT_EQ(out[700].drift_dph, fresh.update(clean_samples()[1]).drift_dph);
}

// Found by an attack (issue 36): a time stamp of 1e300 was said to freeze the correction for the
// rest of the input. At the model's rate and at a logger ten times faster (blocks of ten), the
// sample is flagged, the stream starts again as at power-on when time comes back, and after one
// rate window the drift follows the temperatures again.
TEST(StreamFaults, ATimeJumpToTheFarFutureDoesNotFreezeTheCorrection) {
  const Recording& r = fixture().test;
  for (const std::size_t per_second : {std::size_t{1}, std::size_t{10}}) {
    const double dt = 1.0 / static_cast<double>(per_second);
    std::vector<Sample> s;
    for (std::size_t i = 0; i + 1 < r.size(); ++i)
      for (std::size_t k = 0; k < per_second; ++k) {
        Sample x = sample_of(r, i);
        x.time_s = static_cast<double>(i) + static_cast<double>(k) * dt;
        s.push_back(x);
      }
    const std::size_t jump = 600 * per_second;
    s[jump].time_s = 1e300;
    CompensationModel at_1_hz = fixture().model;  // its interval recorded, as train records it
    at_1_hz.dataset.preprocessing.sample_interval_s = 1.0;
    StreamingCompensator c(at_1_hz, dt);
    std::vector<StreamOutput> out;
    for (const Sample& x : s) out.push_back(c.update(x));
    EXPECT_NE(out[jump].flags & fault::gap, 0u) << per_second;
    EXPECT_NE(out[jump + 1].flags & fault::restart, 0u) << per_second;
    const std::size_t settled = jump + (window() + 2) * per_second;
    std::size_t changes = 0;
    for (std::size_t i = settled; i < out.size(); ++i) {
      ASSERT_TRUE(std::isfinite(out[i].drift_dph)) << per_second << " " << i;
      ASSERT_EQ(out[i].flags, 0u) << per_second << " " << i;
      changes += out[i].drift_dph != out[i - 1].drift_dph;
    }
    // The correction moves with the start-up: once a block (per model sample) at least.
    EXPECT_GE(changes, (out.size() - settled) / per_second / 2) << per_second;
  }
}

// Found by an attack (issue 36): a one-sample +100 °C glitch inside the range limits moved the
// drift by 0.38 °/h for a rate window. It is a jump now, bridged like a bad reading; a step that
// lasts beyond bridge_s is real, and the thermometer is taken again.
TEST(StreamFaults, AOneSampleJumpIsBridgedAndALastingStepIsTakenAgain) {
  std::vector<Sample> s = clean_samples();
  s[600].temp_fog_degc += 100;  // inside [-60, 125] °C
  const std::vector<StreamOutput> out = run(s), clean = run(clean_samples());
  EXPECT_EQ(out[600].flags, fault::temp_jump | fault::bridged);
  EXPECT_EQ(out[601].flags, 0u);
  EXPECT_NEAR(out[600].drift_dph, clean[600].drift_dph, 1e-3);
  for (std::size_t i = 601 + window(); i < out.size(); ++i)
    ASSERT_EQ(out[i].drift_dph, clean[i].drift_dph) << i;
  // Without the check the glitch reaches the rates, as before.
  FaultPolicy off;
  off.temp_jump_degc = 0;
  const std::vector<StreamOutput> unchecked = run(s, {true, off});
  EXPECT_EQ(unchecked[600].flags, 0u);
  EXPECT_GT(std::abs(unchecked[605].drift_dph - clean[605].drift_dph), 1e-2);

  // A step of +30 °C that lasts: bridged for bridge_s (5 s), then the reading is taken again
  // and the rates start anew; the output stays finite throughout.
  std::vector<Sample> step = clean_samples();
  for (std::size_t i = 700; i < step.size(); ++i) step[i].temp_acc1_degc += 30;
  const std::vector<StreamOutput> stepped = run(step);
  for (std::size_t i = 700; i <= 704; ++i)  // 1 to 5 s after the last good reading
    EXPECT_NE(stepped[i].flags & fault::temp_jump, 0u) << i;
  for (std::size_t i = 705; i < stepped.size(); ++i) {
    ASSERT_EQ(stepped[i].flags & (fault::temp_jump | fault::temp_bad), 0u) << i;
    ASSERT_TRUE(std::isfinite(stepped[i].drift_dph)) << i;
  }
  EXPECT_EQ(stepped[705 + window()].flags, 0u);
}

TEST(StreamFaults, ABadGyroKeepsTheLastCompensatedValue) {
  std::vector<Sample> s = clean_samples();
  s[50].gyro_dph = kNan;
  s[51].gyro_dph = 1e9;
  const std::vector<StreamOutput> out = run(s);
  EXPECT_EQ(out[50].flags, fault::gyro_bad);
  EXPECT_EQ(out[50].gyro_comp_dph, out[49].gyro_comp_dph);
  EXPECT_EQ(out[51].gyro_comp_dph, out[49].gyro_comp_dph);
  EXPECT_EQ(out[52].flags, 0u);
  EXPECT_TRUE(std::isfinite(out[50].drift_dph));
}

TEST(StreamFaults, AStuckThermometerIsCaughtWhenAnotherMoves) {
  std::vector<Sample> s = clean_samples();
  // The start-up warms every thermometer by several degrees: a frozen FOG thermometer is stuck.
  for (std::size_t i = 100; i < s.size(); ++i) s[i].temp_fog_degc = s[100].temp_fog_degc;
  ASSERT_GT(std::abs(s[700].temp_acc1_degc - s[100].temp_acc1_degc), 2.0);
  const std::vector<StreamOutput> out = run(s);
  std::size_t first = 0;
  for (std::size_t i = 0; i < out.size() && first == 0; ++i)
    if (out[i].flags & fault::temp_stuck) first = i;
  ASSERT_GT(first, 0u) << "never caught";
  EXPECT_GE(first, 400u);  // not before stuck_s = 300 s unchanged
  for (std::size_t i = first; i < out.size(); ++i) ASSERT_NE(out[i].flags & fault::temp_stuck, 0u);
  // A steady instrument whose thermometers all read the same value is not stuck.
  std::vector<Sample> steady = clean_samples();
  for (Sample& x : steady) x.temp_fog_degc = 20, x.temp_acc1_degc = 21, x.temp_acc2_degc = 22;
  for (const StreamOutput& o : run(steady)) ASSERT_EQ(o.flags & fault::temp_stuck, 0u);
}

// Random faults in long streams: every output finite, every faulty sample flagged, and a window
// after each episode the output is the fault-free one, bit for bit (without the guard, whose
// latch may remember a fault; with it, the first two promises).
TEST(StreamFaults, RandomFaultsNeverYieldNonFiniteOutputAndRecover) {
  const std::vector<Sample> clean = clean_samples();
  const std::size_t w = window();
  for (bool guarded : {false, true}) {
    const std::vector<StreamOutput> reference = run(clean, {guarded, {}});
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
      Rng rng(seed);
      std::vector<Sample> s;
      std::vector<std::size_t> origin;  // the clean sample each streamed one is, or npos
      std::vector<bool> faulty;         // a fault was injected into this streamed sample
      constexpr std::size_t npos = static_cast<std::size_t>(-1);
      std::size_t quiet_from = 0;  // no new episode before this sample
      std::size_t episodes = 0;
      for (std::size_t i = 0; i < clean.size(); ++i) {
        Sample x = clean[i];
        bool bad = false;
        // An episode starts on a sample at random, at least 2 windows after the last one ended.
        if (i >= quiet_from + w && i + 60 < clean.size() && rng.uniform() < 0.01) {
          const int kind = static_cast<int>(rng.uniform(0, 6));
          const auto length = static_cast<std::size_t>(rng.uniform(1, 40));
          std::size_t end = i + length;
          for (std::size_t k = i; k < end; ++k) {
            Sample y = clean[k];
            switch (kind) {
              case 0:
                y.temp_fog_degc = kNan;
                break;
              case 1:
                y.temp_acc1_degc = rng.uniform() < 0.5 ? -300.0 : 1e6;
                break;
              case 2:
                y.gyro_dph = kNan;
                break;
              case 3:
                y.time_s = kNan;
                break;
              case 4:
                continue;  // dropped samples
              default:     // a replayed sample before each
                s.push_back(clean[k - 1]);
                origin.push_back(npos);
                faulty.push_back(true);
            }
            s.push_back(y);
            origin.push_back(k);
            faulty.push_back(kind != 5);  // after a replayed sample, the real one is good
          }
          if (kind == 4) {  // the sample after a gap is flagged
            s.push_back(clean[end]);
            origin.push_back(end);
            faulty.push_back(true);
            ++end;
          }
          i = end - 1;
          quiet_from = end + w;
          ++episodes;
          bad = true;
        }
        if (bad) continue;
        s.push_back(x);
        origin.push_back(i);
        faulty.push_back(false);
      }
      const std::vector<StreamOutput> out = run(s, {guarded, {}});
      std::size_t matched = 0;
      for (std::size_t j = 0; j < s.size(); ++j) {
        ASSERT_TRUE(std::isfinite(out[j].drift_dph)) << seed << " " << j;
        ASSERT_TRUE(std::isfinite(out[j].gyro_comp_dph)) << seed << " " << j;
        if (faulty[j]) {
          ASSERT_NE(out[j].flags, 0u) << "seed " << seed << " sample " << j;
        }
      }
      // Recovery: a clean sample at least a window after the last episode matches.
      std::size_t last_fault = 0;
      for (std::size_t j = 0; j < s.size(); ++j) {
        if (faulty[j]) last_fault = j;
        if (faulty[j] || j < last_fault + w + 1 || origin[j] == npos) continue;
        ASSERT_EQ(out[j].flags, 0u) << "seed " << seed << " sample " << j;
        if (guarded) continue;
        ASSERT_EQ(out[j].drift_dph, reference[origin[j]].drift_dph)
            << "seed " << seed << " sample " << j;
        ++matched;
      }
      // Neither check is empty: faults were injected, and much of the stream was compared.
      EXPECT_GE(episodes, 4u) << seed;
      if (!guarded) {
        EXPECT_GT(matched, clean.size() / 4) << seed;
      }
    }
  }
}

// The C header's streaming part runs the same policy: the same flags and the same drift (to
// rounding of the compiled arithmetic) on a stream with every kind of fault.
TEST(StreamFaults, TheCHeaderRunsTheSamePolicy) {
  std::vector<Sample> s = clean_samples();
  s[100].temp_fog_degc = kNan;
  for (std::size_t i = 300; i < 420; ++i) s[i].temp_acc1_degc = 999;
  s[500].gyro_dph = kNan;
  s[550].temp_acc2_degc += 60;  // a jump
  s[600].time_s = kNan;
  s.erase(s.begin() + 700, s.begin() + 703);
  s.erase(s.begin() + 900, s.begin() + 940);
  s.insert(s.begin() + 1000, s[998]);
  for (std::size_t i = 1200; i < s.size(); ++i) s[i].temp_fog_degc = s[1200].temp_fog_degc;
  for (std::size_t i = 1100; i < 1110; ++i)  // steps of 0.75 s: another rate, off_interval
    s[i].time_s = s[1099].time_s + 0.75 * static_cast<double>(i - 1099);
  std::vector<Sample> restarted(s.begin(), s.begin() + 1500);
  restarted.insert(restarted.end(), s.begin(), s.begin() + 300);
  const std::vector<StreamOutput> lib = run(restarted);

  test::TempDir dir;
  test::write_file(dir / "model.h", to_c_header(fixture().model, "fd", 1.0));
  test::write_file(dir / "driver.c", R"(#include <stdio.h>
#include <stdlib.h>
#include "model.h"
int main(void) {
  fd_state s;
  char line[512];
  fd_reset(&s);
  while (fgets(line, sizeof line, stdin)) {
    char* p = line;
    double v[5];
    int k;
    double drift, comp;
    for (k = 0; k < 5; ++k) v[k] = strtod(p, &p);
    drift = fd_update(&s, v[0], v[2], v[3], v[4]);
    comp = fd_compensated_dph(&s, v[1]);
    printf("%.17g %.17g %u\n", drift, comp, s.flags);
  }
  return 0;
}
)");
  std::ostringstream text;
  text.precision(17);
  for (const Sample& x : restarted)
    text << x.time_s << ' ' << x.gyro_dph << ' ' << x.temp_fog_degc << ' ' << x.temp_acc1_degc
         << ' ' << x.temp_acc2_degc << '\n';
  std::istringstream in(test::compile_and_run_c(dir, text.str()));
  std::size_t j = 0, flagged = 0;
  double drift = 0, comp = 0;
  unsigned flags = 0;
  while (in >> drift >> comp >> flags) {
    ASSERT_LT(j, lib.size());
    ASSERT_EQ(flags, lib[j].flags) << j << ": " << fault::describe(lib[j].flags);
    ASSERT_NEAR(drift, lib[j].drift_dph, 1e-12 * (1 + std::abs(lib[j].drift_dph))) << j;
    ASSERT_NEAR(comp, lib[j].gyro_comp_dph, 1e-12 * (1 + std::abs(lib[j].gyro_comp_dph))) << j;
    flagged += flags != 0;
    ++j;
  }
  EXPECT_EQ(j, lib.size());
  EXPECT_GT(flagged, 200u);
}

// Timings fitted to a model's interval (fault_policy_for): the defaults at 1 Hz; a model of 10 s
// samples bridges two of them; of 305 s samples and a 5-sample rate window (1525 s), bridges
// 610 s, holds two windows and checks for a stuck thermometer over five samples.
TEST(FaultPolicyFor, StretchesTheTimingsForASlowModel) {
  const FaultPolicy defaults;
  const FaultPolicy at_1hz = fault_policy_for(1.0, 121.0);
  EXPECT_EQ(at_1hz.bridge_s, defaults.bridge_s);
  EXPECT_EQ(at_1hz.hold_s, defaults.hold_s);
  EXPECT_EQ(at_1hz.stuck_s, defaults.stuck_s);
  EXPECT_EQ(fault_policy_for(10.0, 130.0).bridge_s, 20.0);
  const FaultPolicy slow = fault_policy_for(305.0, 1525.0);
  EXPECT_EQ(slow.bridge_s, 610.0);
  EXPECT_EQ(slow.hold_s, 3050.0);
  EXPECT_EQ(slow.stuck_s, 1525.0);
  EXPECT_EQ(slow.temp_max_degc, defaults.temp_max_degc);
  EXPECT_NO_THROW(validate(slow));
}

}  // namespace
}  // namespace fogdrift
