// Does a compensation model transfer to start-ups unlike its calibration? The measurement
// behind docs/field.md: for each seed, simulate a calibration campaign under the given start-up
// approaches, train the given methods on its training repetitions, and find north on start-ups
// of every approach at the paper's seven temperatures.
//
//   build/bench/transfer_study [--seeds N] [--cal-approaches calibration,soaked,...]
//                              [--repetitions R] [--features SPEC] [--methods bp,ssa-svr]
//                              [--epsilon E] [--population P] [--iterations I]
//                              [--cv temperature|repetition] [--guard on|off] [--threads T]
//                              [--guard-full-at NU] [--guard-zero-at NU] [--guard-prototypes K]
//                              [--guard-recover-s S]
//
// Printed per method and start-up approach, as means over temperatures and seeds: the raw RMSE,
// the floor (the simulator's true drift subtracted), the compensated RMSE and the share of the
// removable error removed, (raw² − comp²) / (raw² − floor²) (docs/field.md).
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/eval/field.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/train.hpp"

namespace {

using namespace fogdrift;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from <= s.size()) {
    const std::size_t comma = std::min(s.find(',', from), s.size());
    out.push_back(s.substr(from, comma - from));
    from = comma + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) try {
  std::size_t seeds = 2, population = 10, iterations = 20, threads = 0;
  int repetitions = 0;
  std::string cal_approaches = "calibration", features = default_feature_spec().to_string();
  std::string methods = "bp,ssa-svr", cv = "temperature", guard = "on";
  double epsilon = 0.05;
  GuardSettings guard_settings;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--seeds")
      seeds = std::stoul(value);
    else if (flag == "--cal-approaches")
      cal_approaches = value;
    else if (flag == "--repetitions")
      repetitions = std::stoi(value);
    else if (flag == "--features")
      features = value;
    else if (flag == "--methods")
      methods = value;
    else if (flag == "--epsilon")
      epsilon = std::stod(value);
    else if (flag == "--population")
      population = std::stoul(value);
    else if (flag == "--iterations")
      iterations = std::stoul(value);
    else if (flag == "--cv")
      cv = value;
    else if (flag == "--guard")
      guard = value;
    else if (flag == "--threads")
      threads = std::stoul(value);
    else if (flag == "--guard-full-at")
      guard_settings.full_at = std::stod(value);
    else if (flag == "--guard-zero-at")
      guard_settings.zero_at = std::stod(value);
    else if (flag == "--guard-prototypes")
      guard_settings.prototypes = std::stoul(value);
    else if (flag == "--guard-recover-s")
      guard_settings.recover_s = std::stod(value);
    else
      throw OptionError(flag, "is not an option of transfer_study");
  }
  ThreadPool pool(static_cast<unsigned>(threads));
  const sim::Instrument instrument;
  sim::CalibrationOptions co;
  co.approaches = sim::approaches_from_string(cal_approaches, "--cal-approaches");
  // By default one training repetition per approach, plus the test repetition.
  co.repetitions = repetitions > 0 ? repetitions : static_cast<int>(co.approaches.size()) + 1;
  if (co.repetitions < 2) co.repetitions = 2;
  DatasetOptions dataset;
  dataset.features = FeatureSpec::parse(features);

  const std::vector<sim::Approach> field = {sim::Approach::calibration, sim::Approach::soaked,
                                            sim::Approach::warm, sim::Approach::ramping};
  const std::vector<std::string> names = split(methods);
  // [method][approach] accumulated over seeds
  std::vector<std::vector<eval::FieldSummary>> sum(names.size(),
                                                   std::vector<eval::FieldSummary>(field.size()));
  // Samples outside the training region, with a reduced correction, and in all.
  std::vector<std::vector<double>> outside(names.size(), std::vector<double>(field.size())),
      reduced = outside, samples = outside;
  for (std::size_t seed = 1; seed <= seeds; ++seed) {
    co.seed = seed;
    const sim::SimulatedCampaign cal = sim::simulate_calibration(instrument, co);
    const Dataset train =
        build_dataset(recording_inputs(cal.campaign, cal.recordings, Role::train), dataset);
    std::vector<sim::SimulatedCampaign> nf;
    for (sim::Approach a : field) {
      sim::NorthfindOptions no;
      no.approach = a;
      no.seed = seed;
      nf.push_back(sim::simulate_northfind(instrument, no));
    }
    for (std::size_t m = 0; m < names.size(); ++m) {
      TrainOptions to;
      to.method = parse_method(names[m], "--methods");
      to.tune.cv.scheme = tune::parse_cv_scheme(cv, "--cv");
      to.tune.space.epsilon = epsilon;
      to.tune.optimizer.run.population = population;
      to.tune.optimizer.run.iterations = iterations;
      to.tune.optimizer.run.seed = seed;
      to.tune.pool = &pool;
      to.guard = guard_settings;
      const TrainResult r = fogdrift::train(train, dataset, to);
      for (std::size_t a = 0; a < field.size(); ++a) {
        const eval::DriftOf drift = [&, a](const Recording& rec) {
          RecordingPrediction p = r.model.predict(rec, guard == "on");
          for (std::size_t i = 0; i < p.novelty.size(); ++i) {
            reduced[m][a] += p.weight[i] < 1.0;
            outside[m][a] += p.novelty[i] > 1.0;
            samples[m][a] += 1;
          }
          return p.drift_dph;
        };
        const eval::FieldSummary s = eval::field_summary(nf[a].campaign, nf[a].recordings, drift);
        sum[m][a].accumulate(s);
      }
      std::fprintf(stderr, "seed %zu %s done (%.0f s)\n", seed, names[m].c_str(),
                   r.summary.seconds);
    }
  }
  std::printf(
      "| method | start-up | raw ° | floor ° | compensated ° | removed | worse than raw "
      "| novel | reduced |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t m = 0; m < names.size(); ++m)
    for (std::size_t a = 0; a < field.size(); ++a) {
      const eval::FieldSummary& s = sum[m][a];
      std::printf("| %s | %s | %.4f | %.4f | %.4f | %.0f %% | %zu of %zu | %.0f %% | %.0f %% |\n",
                  names[m].c_str(), std::string(sim::to_string(field[a])).c_str(),
                  s.raw_mean_rmse_deg(), s.floor_mean_rmse_deg(), s.comp_mean_rmse_deg(),
                  100 * s.share_removed(), s.worse_than_raw, s.recordings.size(),
                  100 * outside[m][a] / samples[m][a], 100 * reduced[m][a] / samples[m][a]);
    }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "transfer_study: %s\n", e.what());
  return 1;
}
