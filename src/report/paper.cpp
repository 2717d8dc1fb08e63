#include "fogdrift/report/paper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <optional>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/eval/field.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/train/bp_trainer.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/train.hpp"
#include "report/paper_figures.hpp"

namespace fogdrift::report {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The methods whose hyperparameters a search chooses (PSO-, GWO- and SSA-SVR, the GP), as
// their trainers resolve them with default options.
bool is_searched(Method method) {
  TrainOptions to;
  to.method = method;
  return is_optimizer(resolved(to).method.search);
}

// Table 2 of a model on test rows: per recording, pooled (eval/metrics.hpp).
eval::CompensationMetrics table2_of(const CompensationModel& model, const Dataset& test) {
  return eval::pool(eval::metrics_per_recording(test, model.predict_dph(test)));
}

// North-finding RMSE of every recording of a north-finding campaign after subtracting
// `drift(recording)` from the gyro; raw when `drift` is empty.
using DriftOf = std::function<std::vector<double>(const Recording&)>;
std::vector<double> northfind_rmse(const sim::SimulatedCampaign& nf, const DriftOf& drift) {
  std::vector<double> out;
  for (std::size_t i = 0; i < nf.recordings.size(); ++i) {
    const CampaignEntry& e = nf.campaign.recordings[i];
    const Recording& rec = nf.recordings[i];
    const double latitude = nf.campaign.latitude_deg.value(), truth = e.true_azimuth_deg.value();
    out.push_back(eval::rms(drift ? eval::northfind_errors_deg(rec, drift(rec), latitude, truth)
                                  : eval::northfind_errors_deg(rec, latitude, truth)));
  }
  return out;
}

DriftOf predicted_by(const CompensationModel& model) {
  return [&model](const Recording& rec) { return model.predict_dph(rec); };
}

// The simulator's ground truth, when every recording carries it.
bool has_true_drift(const sim::SimulatedCampaign& nf) {
  for (const Recording& rec : nf.recordings)
    if (!rec.has_column("drift_true_dph")) return false;
  return !nf.recordings.empty();
}

svr::Params svr_params_of(const MethodRun& run) {
  svr::Params p;
  p.c = run.hyperparameter("C");
  p.kernel = svr::Kernel::rbf_sigma(run.hyperparameter("sigma"));
  p.epsilon = run.hyperparameter("epsilon");
  return p;
}

// How every model of the experiment is trained: the run's budget, fitness, ε and BP settings.
TrainOptions train_options(const PaperOptions& o, Method method, std::uint64_t seed,
                           tune::Fitness fitness) {
  TrainOptions to;
  to.method = method;
  to.tune.fitness = fitness;
  to.tune.cv = o.cv;
  to.tune.optimizer.run.population = o.population;
  to.tune.optimizer.run.iterations = o.iterations;
  to.tune.optimizer.run.seed = seed;
  to.tune.optimizer.run.stall_iterations = 0;  // the paper's fixed budget, every iteration
  to.tune.search_rows = 0;                     // on every row
  to.tune.smo_iterations_per_row = 0;          // every fit to the end
  to.tune.candidate_resolution = 0;            // every distinct candidate fitted
  to.tune.pool = o.pool;
  to.tune.space.epsilon = o.epsilon;
  to.tune.space.search_epsilon = o.search_epsilon;
  to.trainers.get<BpTrainer::Options>() = o.mlp;
  to.held_out = false;  // the paper scores its models on its own test data
  return to;
}

// A campaign's start-ups with the model's drift subtracted: the mean north-finding RMSE guarded
// and not, and the drift's own error removed finding by finding, guarded (field.hpp). One
// prediction per recording gives all three.
struct StartUpScore {
  double guarded_deg = 0, unguarded_deg = 0, guarded_drift_error_removed = 0;
};
StartUpScore start_up_score(const CompensationModel& model, const sim::SimulatedCampaign& c) {
  std::vector<RecordingPrediction> predicted;
  for (const Recording& rec : c.recordings) predicted.push_back(model.predict(rec));
  auto of = [&](const Recording& rec) -> const RecordingPrediction& {
    return predicted[static_cast<std::size_t>(&rec - c.recordings.data())];
  };
  const eval::DriftOf guarded = [&](const Recording& rec) { return of(rec).drift_dph; };
  const eval::DriftOf unguarded = [&](const Recording& rec) { return of(rec).model_drift_dph; };
  const eval::FieldSummary on = eval::field_summary(c.campaign, c.recordings, guarded);
  return {on.comp_mean_rmse_deg(),
          eval::field_summary(c.campaign, c.recordings, unguarded).comp_mean_rmse_deg(),
          on.drift_error_removed()};
}

// The progress line: stages are reported from the pool's threads, in the order they start.
struct Stages {
  explicit Stages(const PaperOptions& options) : o(options) {}
  const PaperOptions& o;
  double done = 0, total = 1;
  std::mutex mutex;
  void step(const std::string& stage, double weight) {
    const std::lock_guard<std::mutex> lock(mutex);
    if (o.progress) o.progress(stage, std::min(1.0, done / total));
    done += weight;
  }
};

constexpr double kTunedWeight = 6, kOtherWeight = 1, kLotoWeight = 4;

// One seed's campaigns and datasets, and its run as the method tasks fill it in.
struct SeedCase {
  sim::SimulatedCampaign cal, nf;
  std::vector<sim::SimulatedCampaign> start_ups;  // one per PaperOptions::start_ups
  Dataset train, test;
  SeedRun run;
  std::vector<std::optional<CompensationModel>> models;  // o.methods order, first seed only
};

// Simulates a seed's campaigns and measures what needs no model: raw, floor, stable.
void prepare_seed(const PaperOptions& o, std::uint64_t seed, Stages& stages, SeedCase& c) {
  const auto start = Clock::now();
  SeedRun& run = c.run;
  run.seed = seed;
  stages.step(fmt::format("seed {}: simulating the campaigns", seed), kOtherWeight);
  sim::CalibrationOptions co = o.calibration;
  co.seed = seed;
  sim::NorthfindOptions no = o.northfind, so = o.stable;
  no.seed = so.seed = seed;
  c.cal = sim::simulate_calibration(o.instrument, co);
  c.nf = sim::simulate_northfind(o.instrument, no);
  const sim::SimulatedCampaign st = sim::simulate_stable(o.instrument, so);

  const DatasetOptions dataset;
  c.train = build_dataset(recording_inputs(c.cal.campaign, c.cal.recordings, Role::train), dataset);
  c.test = build_dataset(recording_inputs(c.cal.campaign, c.cal.recordings, Role::test), dataset);
  run.raw_rmse_deg = northfind_rmse(c.nf, {});
  run.raw_mean_rmse_deg = mean_of(run.raw_rmse_deg);
  if (has_true_drift(c.nf)) {
    run.oracle_rmse_deg = northfind_rmse(
        c.nf, [](const Recording& rec) { return rec.numeric_column("drift_true_dph"); });
    run.oracle_mean_rmse_deg = mean_of(run.oracle_rmse_deg);
  }
  run.stable_rmse_deg = mean_of(northfind_rmse(st, {}));
  // The start-up conditions table: the same temperatures under every approach asked for.
  for (sim::Approach a : o.start_ups) {
    sim::NorthfindOptions ao = no;
    ao.approach = a;
    c.start_ups.push_back(sim::simulate_northfind(o.instrument, ao));
    const eval::FieldSummary f =
        eval::field_summary(c.start_ups.back().campaign, c.start_ups.back().recordings, {});
    run.start_up_raw_rmse_deg.push_back(f.raw_mean_rmse_deg());
    run.start_up_floor_rmse_deg.push_back(f.floor_mean_rmse_deg());
  }
  run.denoised_std_dph =
      eval::pool(eval::metrics_per_recording(c.test, std::vector<double>(c.test.rows, 0.0)))
          .std_before_dph;
  run.methods.resize(o.methods.size());
  c.models.resize(o.methods.size());
  run.seconds = seconds_since(start);
}

// Trains one method on a seed's campaign and scores it: Table 2, Table 3 and the start-up
// conditions; for SSA-SVR also the causal refit. Writes only its own entries of the seed's run,
// so the tasks of one seed may run side by side. Returns the task's own time.
double run_method(const PaperOptions& o, std::size_t method_index, Stages& stages, SeedCase& c,
                  bool keep_model) {
  const auto start = Clock::now();
  const Method method = o.methods[method_index];
  SeedRun& run = c.run;
  const std::uint64_t seed = run.seed;
  const std::string name = to_string(method);
  stages.step(fmt::format("seed {}: training {}", seed, name),
              is_searched(method) ? kTunedWeight : kOtherWeight);
  const DatasetOptions dataset;
  TrainResult trained =
      fogdrift::train(c.train, dataset, train_options(o, method, seed, o.fitness));
  MethodRun& m = run.methods[method_index];
  m.method = method;
  m.table2 = table2_of(trained.model, c.test);
  m.rmse_deg = northfind_rmse(c.nf, predicted_by(trained.model));
  m.mean_rmse_deg = mean_of(m.rmse_deg);
  for (const sim::SimulatedCampaign& sc : c.start_ups) {
    const StartUpScore score = start_up_score(trained.model, sc);
    m.start_up_rmse_deg.push_back(score.guarded_deg);
    m.start_up_unguarded_rmse_deg.push_back(score.unguarded_deg);
    m.start_up_drift_error_removed.push_back(score.guarded_drift_error_removed);
  }
  m.hyperparameters = trained.summary.hyperparameters;
  if (method == Method::ssa_svr && o.causal && !c.start_ups.empty()) {
    // What firmware runs: the same C, σ and ε on causal rates, over the causal window and
    // degree `train` uses. Its batch prediction equals the streaming compensator's sample
    // for sample (compensator.hpp).
    DatasetOptions causal = dataset;
    causal.preprocessing.rates = signal::recommended_rates(signal::Causality::causal);
    TrainOptions to = train_options(o, Method::svr, seed, o.fitness);
    to.trainers.get<SvrTrainer::Options>().params = svr_params_of(m);
    const CompensationModel streamed =
        fogdrift::train(
            build_dataset(recording_inputs(c.cal.campaign, c.cal.recordings, Role::train), causal),
            causal, to)
            .model;
    for (const sim::SimulatedCampaign& sc : c.start_ups) {
      const StartUpScore score = start_up_score(streamed, sc);
      run.causal_start_up_rmse_deg.push_back(score.guarded_deg);
      run.causal_start_up_unguarded_rmse_deg.push_back(score.unguarded_deg);
      run.causal_start_up_drift_error_removed.push_back(score.guarded_drift_error_removed);
    }
  }
  m.fitness_value = trained.summary.fitness_value;
  m.train_seconds = trained.summary.seconds;
  if (keep_model) c.models[method_index] = std::move(trained.model);
  return seconds_since(start);
}

// fn(0) … fn(n − 1) on the pool, longest first as the caller orders them; serially without one.
void for_each_task(ThreadPool* pool, std::size_t n, const std::function<void(std::size_t)>& fn) {
  if (pool)
    pool->parallel_for(n, fn);
  else
    for (std::size_t k = 0; k < n; ++k) fn(k);
}

// The calibration temperatures of a dataset, ascending.
std::vector<double> temperatures_of(const Dataset& data) {
  std::vector<double> temps;
  for (const auto& g : data.groups) temps.push_back(g.initial_temp_degc);
  std::sort(temps.begin(), temps.end());
  temps.erase(std::unique(temps.begin(), temps.end()), temps.end());
  return temps;
}

// Row k of the leave-one-temperature-out study: temperature temps[k / 2], SSA-SVR (its tuned
// C, σ and ε refitted) for even k, BP for odd k.
LotoRow loto_row(const PaperOptions& o, const SeedRun& run, const FirstSeed& f,
                 const std::vector<double>& temps, std::size_t k) {
  const double t = temps[k / 2];
  const Method method = k % 2 ? Method::bp : Method::ssa_svr;
  std::vector<std::size_t> keep_groups, test_groups;
  for (std::size_t g = 0; g < f.train.groups.size(); ++g)
    if (f.train.groups[g].initial_temp_degc != t) keep_groups.push_back(g);
  for (std::size_t g = 0; g < f.test.groups.size(); ++g)
    if (f.test.groups[g].initial_temp_degc == t) test_groups.push_back(g);
  const Dataset train = f.train.select_groups(keep_groups);
  const Dataset test = f.test.select_groups(test_groups);
  // Run as a task of the pool: its own pool loops run serially.
  TrainOptions to =
      train_options(o, method == Method::bp ? Method::bp : Method::svr, run.seed, o.fitness);
  // One temperature fewer to deal into temperature folds (they only score the model here).
  if (to.tune.cv.scheme == tune::CvScheme::temperature) {
    if (temps.size() >= 3)
      to.tune.cv.folds = std::min(to.tune.cv.folds, temps.size() - 1);
    else
      to.tune.cv = tune::CvOptions{};
  }
  if (method != Method::bp)
    to.trainers.get<SvrTrainer::Options>().params = svr_params_of(run.method(method));
  const TrainResult loto = fogdrift::train(train, f.dataset, to);
  const eval::CompensationMetrics all = table2_of(f.models.at(method), test);
  const eval::CompensationMetrics left = table2_of(loto.model, test);
  return LotoRow{
      t,           method,      all.std_before_dph, all.std_after_dph, left.std_after_dph,
      all.mae_dph, left.mae_dph};
}

// The fitness study's row for the fitness `train` was not run with: SSA-SVR searched again with
// it on the first seed's campaign. It reads only what prepare_seed wrote, so it runs beside that
// seed's method tasks, from the start: it is the experiment's longest job.
FitnessRow searched_fitness_row(const PaperOptions& o, tune::Fitness fitness, const SeedCase& c) {
  FitnessRow row;
  row.fitness = fitness;
  const DatasetOptions dataset;
  const TrainResult t =
      train(c.train, dataset, train_options(o, Method::ssa_svr, c.run.seed, fitness));
  const tune::TuneSummary& search = t.summary.record.get<SvrTrainer::Record>()->tuning;
  row.c = search.best.c;
  row.sigma = search.best.kernel.sigma();
  row.fitness_value = t.summary.fitness_value;
  const eval::CompensationMetrics m = table2_of(t.model, c.test);
  row.std_dph = m.std_after_dph;
  row.mae_dph = m.mae_dph;
  row.mean_rmse_deg = mean_of(northfind_rmse(c.nf, predicted_by(t.model)));
  return row;
}

// The fitness study: cv first, then train; the options' own fitness is the first seed's
// SSA-SVR, the other `searched`.
std::vector<FitnessRow> fitness_study(const PaperOptions& o, const SeedRun& run,
                                      const FitnessRow& searched) {
  std::vector<FitnessRow> rows;
  for (tune::Fitness fitness : {tune::Fitness::cv, tune::Fitness::train}) {
    if (fitness != o.fitness) {
      rows.push_back(searched);
      continue;
    }
    FitnessRow row;
    row.fitness = fitness;
    const MethodRun& m = run.method(Method::ssa_svr);
    row.c = m.hyperparameter("C");
    row.sigma = m.hyperparameter("sigma");
    row.fitness_value = m.fitness_value;
    row.std_dph = m.table2.std_after_dph;
    row.mae_dph = m.table2.mae_dph;
    row.mean_rmse_deg = m.mean_rmse_deg;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

double MethodRun::hyperparameter(std::string_view name) const {
  for (const auto& [n, v] : hyperparameters)
    if (n == name) return v;
  return std::nan("");
}

const MethodRun& SeedRun::method(Method method) const {
  for (const auto& m : methods)
    if (m.method == method) return m;
  throw std::out_of_range(fmt::format("no method {} in this run", to_string(method)));
}

void validate(const PaperOptions& o) {
  if (o.seeds < 1 || o.seeds > 1000)
    throw OptionError("seeds", fmt::format("{} is outside [1, 1000]", o.seeds));
  if (o.population < 5 || o.population > 10000)
    throw OptionError("population",
                      fmt::format("{} is outside [5, 10000] (SSA needs 5 sparrows)", o.population));
  tune::check_epsilon(o.epsilon);
  if (o.iterations < 1 || o.iterations > 100000)
    throw OptionError("iterations", fmt::format("{} is outside [1, 100000]", o.iterations));
  const std::size_t temps = o.calibration.temps_degc.size();
  const std::size_t train_reps =
      o.calibration.repetitions > o.calibration.test_repetitions
          ? static_cast<std::size_t>(o.calibration.repetitions - o.calibration.test_repetitions)
          : 0;
  sim::validate(o.instrument);
  sim::validate(o.calibration);
  sim::validate(o.northfind, "northfind");
  sim::validate(o.stable, "stable");
  // k folds of n whole units (temperatures, recordings) need 2 <= k <= n.
  auto folds_of = [&](std::size_t n, const char* units, const char* advice) {
    if (o.cv.folds >= 2 && o.cv.folds <= n) return;
    const std::string ask = n < 2    ? std::string("there are too few for folds")
                            : n == 2 ? std::string("ask for 2 folds")
                                     : fmt::format("ask for 2 to {} folds", n);
    throw OptionError("cv.folds",
                      fmt::format("{} folds of whole {} need {} {}, and there are "
                                  "{}; {}{}",
                                  o.cv.folds, units, std::max<std::size_t>(o.cv.folds, 2), units, n,
                                  ask, advice));
  };
  if (o.cv.scheme == tune::CvScheme::temperature)
    folds_of(static_cast<std::size_t>(temps), "calibration temperatures",
             ", or {cv} repetition to leave one repetition out");
  if (o.cv.scheme == tune::CvScheme::recording)
    folds_of(static_cast<std::size_t>(temps * train_reps), "training recordings", "");
  if (o.cv.scheme == tune::CvScheme::repetition && train_reps < 2)
    throw OptionError("cv.scheme",
                      "leave one repetition out needs two or more training repetitions");
  for (std::size_t j = 0; j < o.methods.size(); ++j)
    if (std::find(o.methods.begin(), o.methods.begin() + static_cast<std::ptrdiff_t>(j),
                  o.methods[j]) != o.methods.begin() + static_cast<std::ptrdiff_t>(j))
      throw OptionError("methods", fmt::format("{} is listed twice", to_string(o.methods[j])));
  for (const Method needed : {Method::bp, Method::ssa_svr})
    if (std::find(o.methods.begin(), o.methods.end(), needed) == o.methods.end())
      throw OptionError("methods", fmt::format("must include {}: the report and the studies "
                                               "compare it",
                                               to_string(needed)));
  if (o.calibration.test_repetitions < 1 ||
      o.calibration.test_repetitions >= o.calibration.repetitions)
    throw OptionError("calibration.repetitions",
                      "the experiment needs at least one training and one test repetition");
}

PaperResult run_paper(const PaperOptions& options) {
  validate(options);
  const auto start = Clock::now();
  PaperResult r;
  r.options = options;
  r.options.progress = nullptr;
  r.options.pool = nullptr;
  r.northfind_temps_degc = options.northfind.temps_degc;

  Stages stages{options};
  double per_seed = kOtherWeight;  // simulating the campaigns
  for (const Method m : options.methods) per_seed += is_searched(m) ? kTunedWeight : kOtherWeight;
  stages.total = per_seed * static_cast<double>(options.seeds) +
                 (options.studies ? kLotoWeight + kTunedWeight : 0.0) + 1;
  // Every seed's campaigns first, then every (seed, method) pair as one task, the tuned SVRs
  // first: each search then runs serially inside its task, and both cores stay busy to the end
  // instead of waiting at the end of each of a search's batches. Results do not depend on it.
  std::vector<SeedCase> cases(options.seeds);
  for_each_task(options.pool, cases.size(), [&](std::size_t k) {
    prepare_seed(options, options.first_seed + k, stages, cases[k]);
  });
  // (seed, method index); the index past the methods is the fitness study's search, on the
  // first seed, put first as the longest job.
  const std::size_t study_search = options.methods.size();
  const tune::Fitness other_fitness =
      options.fitness == tune::Fitness::cv ? tune::Fitness::train : tune::Fitness::cv;
  FitnessRow searched;
  std::vector<std::pair<std::size_t, std::size_t>> tasks;
  if (options.studies) tasks.emplace_back(0, study_search);
  for (const bool tuned : {true, false})
    for (std::size_t j = 0; j < options.methods.size(); ++j)
      if (tuned == is_searched(options.methods[j]))
        for (std::size_t k = 0; k < cases.size(); ++k) tasks.emplace_back(k, j);
  std::vector<double> task_seconds(tasks.size());  // a seed's own time; the study's is not
  for_each_task(options.pool, tasks.size(), [&](std::size_t t) {
    const auto [k, j] = tasks[t];
    if (j == study_search) {
      stages.step(fmt::format("study: SSA-SVR searched with the {} fitness",
                              tune::to_string(other_fitness)),
                  kTunedWeight);
      searched = searched_fitness_row(options, other_fitness, cases[k]);
      return;
    }
    task_seconds[t] = run_method(options, j, stages, cases[k], k == 0);
  });
  for (std::size_t t = 0; t < tasks.size(); ++t)
    cases[tasks[t].first].run.seconds += task_seconds[t];
  FirstSeed first;
  for (std::size_t j = 0; j < options.methods.size(); ++j)
    first.models.emplace(options.methods[j], std::move(*cases.front().models[j]));
  first.cal = std::move(cases.front().cal);
  first.nf = std::move(cases.front().nf);
  first.train = std::move(cases.front().train);
  first.test = std::move(cases.front().test);
  for (SeedCase& c : cases) r.seeds.push_back(std::move(c.run));
  if (options.studies) {
    // The leave-one-temperature-out fits need the first seed's SSA-SVR and BP; the fitness
    // study's search ran beside the method tasks.
    stages.step("study: leave one temperature out", kLotoWeight);
    const std::vector<double> temps = temperatures_of(first.train);
    r.loto.resize(2 * temps.size());
    for_each_task(options.pool, r.loto.size(), [&](std::size_t k) {
      r.loto[k] = loto_row(options, r.seeds.front(), first, temps, k);
    });
    r.fitness = fitness_study(options, r.seeds.front(), searched);
  }
  stages.step("figures", 1);
  r.figures = paper_figures(r, first);
  r.seconds = seconds_since(start);
  if (options.progress) options.progress("done", 1.0);
  return r;
}

}  // namespace fogdrift::report
