// What the streaming compensator costs per sample, with and without the novelty guard, against
// the model's size: the firmware's budget (docs/field.md, bench/RESULTS.md).
//
//   build/bench/stream_speed [--runs N]
//
// Models: BP, a cubic polynomial and untuned SVRs trained (causal rates) on simulated calibration
// campaigns of 3, 6 and 11 temperatures (more support vectors with more rows). Each is run over
// the 30-minute test start-ups at 1 Hz, one thread; the median over N runs (default 5) of the
// time per sample is printed, with samples per second per core.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/model/dataset.hpp"
#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/regress/poly.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/svr/svr.hpp"
#include "fogdrift/train/train.hpp"

namespace {

using namespace fogdrift;
using Clock = std::chrono::steady_clock;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Seconds per sample of one pass of the compensator over every test recording.
double seconds_per_sample(const CompensationModel& model, const std::vector<Recording>& tests,
                          double& sink) {
  StreamingCompensator stream(model, 1.0);
  std::size_t samples = 0;
  const auto start = Clock::now();
  for (const Recording& r : tests) {
    stream.reset();
    for (std::size_t i = 0; i < r.size(); ++i)
      sink += stream
                  .update({r.time_s[i], r.gyro_dph[i], r.temp_fog_degc[i], r.temp_acc1_degc[i],
                           r.temp_acc2_degc[i]})
                  .drift_dph;
    samples += r.size();
  }
  return std::chrono::duration<double>(Clock::now() - start).count() / static_cast<double>(samples);
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--runs") == 0) runs = std::max(1, std::atoi(argv[i + 1]));
  struct Case {
    std::string name;
    Method method;
    std::vector<double> temps;
    std::string features = "T,dT,grad";  // the paper's; train's default adds dT@300
  };
  const std::vector<double> eleven = {-40, -30, -20, -10, 0, 10, 20, 30, 40, 50, 60};
  const std::vector<double> six = {-40, -20, 0, 20, 40, 60};
  const std::vector<Case> cases = {
      {"bp", Method::bp, eleven},
      {"bp, T,dT,grad,dT@300", Method::bp, eleven, "T,dT,grad,dT@300"},
      {"poly", Method::poly, eleven},
      {"svr, 3 temperatures", Method::svr, {-40, 10, 60}},
      {"svr, 6 temperatures", Method::svr, six},
      {"svr, 6 temperatures, T,dT,grad,dT@300", Method::svr, six, "T,dT,grad,dT@300"},
      {"svr, 11 temperatures", Method::svr, eleven}};
  std::printf(
      "| model | size | guard prototypes | µs/sample, guard off | µs/sample, guard on "
      "| samples/s/core, guard on | guard's share |\n|---|---|---|---|---|---|---|\n");
  double sink = 0;
  for (const Case& c : cases) {
    sim::CalibrationOptions co;
    co.temps_degc = c.temps;
    const sim::SimulatedCampaign cal = sim::simulate_calibration(sim::Instrument{}, co);
    std::vector<RecordingInput> train_inputs;
    std::vector<Recording> tests;
    for (std::size_t i = 0; i < cal.recordings.size(); ++i) {
      const CampaignEntry& e = cal.campaign.recordings[i];
      if (e.role == Role::train)
        train_inputs.push_back(recording_input(cal.campaign, e, cal.recordings[i]));
      else
        tests.push_back(cal.recordings[i]);
    }
    DatasetOptions dataset;
    dataset.features = FeatureSpec::parse(c.features);
    dataset.preprocessing.rates.causality = signal::Causality::causal;
    TrainOptions to;
    to.method = c.method;
    const CompensationModel model = train(build_dataset(train_inputs, dataset), dataset, to).model;
    std::string size;
    if (const auto* m = model.regressor.get_if<svr::Model>())
      size = std::to_string(m->size()) + " support vectors";
    else if (const auto* m = model.regressor.get_if<Mlp>())
      size = std::to_string(m->hidden) + " hidden units";
    else
      size = std::to_string(model.regressor.get<Poly>().terms()) + " terms";
    // Without the guard: the same model with its guard removed (a version 1 model), so that
    // neither the novelty nor the weight is computed.
    CompensationModel unguarded = model;
    unguarded.guard = {};
    std::vector<double> off, on;
    for (int r = 0; r < runs; ++r) {  // alternate, so that the machine's noise hits both alike
      off.push_back(seconds_per_sample(unguarded, tests, sink));
      on.push_back(seconds_per_sample(model, tests, sink));
    }
    const double t_off = median(off), t_on = median(on);
    std::printf("| %s | %s | %zu | %.2f | %.2f | %.0f | %.0f %% |\n", c.name.c_str(), size.c_str(),
                model.guard.size(), 1e6 * t_off, 1e6 * t_on, 1.0 / t_on,
                100.0 * (t_on - t_off) / t_on);
  }
  std::fprintf(stderr, "(checksum %g)\n", sink);
  return 0;
}
