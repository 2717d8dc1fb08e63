// Which novelty says better where a model is wrong: the prototype guard's ν (guard.hpp,
// docs/field.md) or a Gaussian process's own predictive standard deviation (gp.hpp, eq. 3)?
// The measurement behind docs/gp.md, "Novelty".
//
//   build/bench/gp_novelty [--seeds N] [--cal-approaches calibration,...] [--population P]
//                          [--iterations I] [--gp-points N] [--threads T]
//
// For each seed: simulate the calibration campaign under the given approaches (the paper's
// protocol by default), train a GP with `train`'s defaults on its training repetitions, and
// simulate north-finding start-ups of every approach at the paper's seven temperatures. At every
// sample of every start-up, with the features the model computes at the recording's rate:
//   e  = |f(x) − true drift|, the model's error (°/h, the simulator's drift_true_dph), unguarded;
//   ν  = the guard's novelty of x;
//   sd = √V[f(x)] / s, the GP's posterior standard deviation as a share of its prior's.
// Printed per approach, pooled over seeds: Spearman's rank correlation of ν and of sd with e, and
// the area under the ROC curve of each as a detector of the samples whose error is in the top
// tenth of that approach's errors (0.5: no better than chance).

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/regress/gp.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/train.hpp"

namespace {

using namespace fogdrift;

// Ranks 1 … n, ties given their mean rank.
std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = 0.5 * static_cast<double>(i + j) + 1;
    i = j + 1;
  }
  return r;
}

double spearman(const std::vector<double>& a, const std::vector<double>& b) {
  const std::vector<double> ra = ranks(a), rb = ranks(b);
  const double n = static_cast<double>(a.size()), mean = (n + 1) / 2;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (ra[i] - mean) * (rb[i] - mean);
    saa += (ra[i] - mean) * (ra[i] - mean);
    sbb += (rb[i] - mean) * (rb[i] - mean);
  }
  return sab / std::sqrt(saa * sbb);
}

// AUC of `score` for the positives (Mann–Whitney U / (n⁺ n⁻)).
double auc(const std::vector<double>& score, const std::vector<bool>& positive) {
  const std::vector<double> r = ranks(score);
  double sum = 0, np = 0;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (positive[i]) sum += r[i], np += 1;
  const double nn = static_cast<double>(r.size()) - np;
  return (sum - np * (np + 1) / 2) / (np * nn);
}

}  // namespace

int main(int argc, char** argv) try {
  std::size_t seeds = 2, population = 10, iterations = 20, threads = 0, points = 800;
  std::string cal_approaches = "calibration";
  const std::map<std::string, std::size_t*> counts = {{"--seeds", &seeds},
                                                      {"--population", &population},
                                                      {"--iterations", &iterations},
                                                      {"--gp-points", &points},
                                                      {"--threads", &threads}};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i], value = argv[i + 1];
    if (flag == "--cal-approaches")
      cal_approaches = value;
    else if (counts.contains(flag))
      *counts.at(flag) = std::stoul(value);
    else
      throw OptionError(flag, "is not an option of gp_novelty");
  }
  ThreadPool pool(static_cast<unsigned>(threads));
  const sim::Instrument instrument;
  sim::CalibrationOptions co;
  co.approaches = sim::approaches_from_string(cal_approaches, "--cal-approaches");
  co.repetitions = std::max(2, static_cast<int>(co.approaches.size()) + 1);
  if (co.approaches.size() == 1) co.repetitions = 4;  // the paper's protocol
  const DatasetOptions dataset;
  const std::vector<sim::Approach> field = {sim::Approach::calibration, sim::Approach::soaked,
                                            sim::Approach::warm, sim::Approach::ramping};
  // [approach] pooled over seeds
  std::vector<std::vector<double>> error(field.size()), nu(field.size()), sd(field.size());
  for (std::size_t seed = 1; seed <= seeds; ++seed) {
    co.seed = seed;
    const sim::SimulatedCampaign cal = sim::simulate_calibration(instrument, co);
    const Dataset train =
        build_dataset(recording_inputs(cal.campaign, cal.recordings, Role::train), dataset);
    TrainOptions to;
    to.method = parse_method("gp");
    to.trainers.get<GpOptions>().max_points = points;
    to.tune.optimizer.run.population = population;
    to.tune.optimizer.run.iterations = iterations;
    to.tune.optimizer.run.seed = seed;
    to.tune.pool = &pool;
    to.held_out = false;
    const CompensationModel model = fogdrift::train(train, dataset, to).model;
    const GpPosterior posterior = factor(model.regressor.get<Gp>());
    const double prior_sd = std::sqrt(posterior.gp.hyper.signal_variance);
    for (std::size_t a = 0; a < field.size(); ++a) {
      sim::NorthfindOptions no;
      no.approach = field[a];
      no.seed = seed;
      const sim::SimulatedCampaign nf = sim::simulate_northfind(instrument, no);
      for (const Recording& rec : nf.recordings) {
        const RecordingPrediction p = model.predict(rec, false);
        FeatureOptions fo = model.dataset.preprocessing;
        fo.block.block_s = sample_interval_s(rec);
        const FeatureTable t = compute_features(rec, model.dataset.features, fo);
        const std::vector<double> truth = rec.numeric_column("drift_true_dph");
        const std::size_t d = model.inputs();
        std::vector<double> z(d);
        // Every 10th sample: neighbours are nearly the same, and the variance costs n² each.
        for (std::size_t i = 0; i < t.rows; i += 10) {
          for (std::size_t k = 0; k < d; ++k)
            z[k] = (t.x[i * d + k] - model.x_scaler.mean[k]) / model.x_scaler.scale[k];
          error[a].push_back(std::abs(p.model_drift_dph[i] - truth[i]));
          nu[a].push_back(p.novelty[i]);
          sd[a].push_back(std::sqrt(posterior.variance(z.data())) / prior_sd);
        }
      }
    }
    std::fprintf(stderr, "seed %zu done\n", seed);
  }
  std::printf("| start-ups | samples | Spearman ν | Spearman sd | AUC ν | AUC sd |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (std::size_t a = 0; a < field.size(); ++a) {
    std::vector<double> sorted = error[a];
    std::sort(sorted.begin(), sorted.end());
    const double cut = sorted[sorted.size() * 9 / 10];
    std::vector<bool> worst(error[a].size());
    for (std::size_t i = 0; i < worst.size(); ++i) worst[i] = error[a][i] > cut;
    std::printf("| %s | %zu | %.2f | %.2f | %.2f | %.2f |\n",
                std::string(sim::to_string(field[a])).c_str(), error[a].size(),
                spearman(nu[a], error[a]), spearman(sd[a], error[a]), auc(nu[a], worst),
                auc(sd[a], worst));
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "gp_novelty: %s\n", e.what());
  return 1;
}
