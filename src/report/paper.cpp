#include "fogdrift/report/paper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "fogdrift/dataset.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/eval/field.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/features.hpp"
#include "fogdrift/train.hpp"

namespace fogdrift::report {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

std::vector<RecordingInput> inputs_of(const sim::SimulatedCampaign& c, std::optional<Role> role) {
  std::vector<RecordingInput> inputs;
  for (std::size_t i = 0; i < c.recordings.size(); ++i) {
    const CampaignEntry& e = c.campaign.recordings[i];
    if (role && e.role != *role) continue;
    inputs.push_back(recording_input(c.campaign, e, c.recordings[i]));
  }
  return inputs;
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
    Recording rec = nf.recordings[i];
    if (drift) {
      const std::vector<double> d = drift(rec);
      for (std::size_t k = 0; k < d.size(); ++k) rec.gyro_dph[k] -= d[k];
    }
    out.push_back(eval::rms(eval::northfind_errors_deg(rec, nf.campaign.latitude_deg.value(),
                                                       e.true_azimuth_deg.value())));
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
  to.tune.pool = o.pool;
  to.tune.space.epsilon = o.epsilon;
  to.tune.space.search_epsilon = o.search_epsilon;
  to.mlp = o.mlp;
  return to;
}

std::string temp_label(double t) {
  return fmt::format("{}{} °C", t < 0 ? "−" : "", std::abs(t));
}

// Decimated (every `step` samples) centred moving average of a column.
std::vector<double> smoothed(const std::vector<double>& v, std::size_t window, std::size_t step) {
  const std::vector<double> s = eval::moving_average(v, window);
  std::vector<double> out;
  for (std::size_t i = 0; i < s.size(); i += step) out.push_back(s[i]);
  return out;
}

// What the first seed keeps for the studies and the figures.
struct FirstSeed {
  sim::SimulatedCampaign cal, nf;
  Dataset train, test;
  DatasetOptions dataset;
  std::map<std::string, CompensationModel> models;
};

struct Stages {
  const PaperOptions& o;
  double done = 0, total = 1;
  void step(const std::string& stage, double weight) {
    if (o.progress) o.progress(stage, std::min(1.0, done / total));
    done += weight;
  }
};

constexpr double kTunedWeight = 6, kOtherWeight = 1, kLotoWeight = 4;

SeedRun run_seed(const PaperOptions& o, std::uint64_t seed, Stages& stages, FirstSeed* keep) {
  const auto start = Clock::now();
  SeedRun run;
  run.seed = seed;
  stages.step(fmt::format("seed {}: simulating the campaigns", seed), kOtherWeight);
  sim::CalibrationOptions co = o.calibration;
  co.seed = seed;
  sim::NorthfindOptions no = o.northfind, so = o.stable;
  no.seed = so.seed = seed;
  sim::SimulatedCampaign cal = sim::simulate_calibration(o.instrument, co);
  sim::SimulatedCampaign nf = sim::simulate_northfind(o.instrument, no);
  const sim::SimulatedCampaign st = sim::simulate_stable(o.instrument, so);

  const DatasetOptions dataset;
  Dataset train = build_dataset(inputs_of(cal, Role::train), dataset);
  Dataset test = build_dataset(inputs_of(cal, Role::test), dataset);
  run.raw_rmse_deg = northfind_rmse(nf, {});
  run.raw_mean_rmse_deg = mean_of(run.raw_rmse_deg);
  if (has_true_drift(nf)) {
    run.oracle_rmse_deg = northfind_rmse(
        nf, [](const Recording& rec) { return rec.numeric_column("drift_true_dph"); });
    run.oracle_mean_rmse_deg = mean_of(run.oracle_rmse_deg);
  }
  run.stable_rmse_deg = mean_of(northfind_rmse(st, {}));
  // The start-up conditions table: the same temperatures under every approach asked for.
  std::vector<sim::SimulatedCampaign> start_ups;
  for (sim::Approach a : o.start_ups) {
    sim::NorthfindOptions ao = no;
    ao.approach = a;
    start_ups.push_back(sim::simulate_northfind(o.instrument, ao));
    const eval::FieldSummary f =
        eval::field_summary(start_ups.back().campaign, start_ups.back().recordings, {});
    run.start_up_raw_rmse_deg.push_back(f.raw_mean_rmse_deg());
    run.start_up_floor_rmse_deg.push_back(f.floor_mean_rmse_deg());
  }
  run.denoised_std_dph =
      eval::pool(eval::metrics_per_recording(test, std::vector<double>(test.rows, 0.0)))
          .std_before_dph;

  for (std::string_view name : kPaperMethods) {
    const Method method = parse_method(std::string(name));
    const bool tuned = method != Method::svr && method != Method::bp;
    stages.step(fmt::format("seed {}: training {}", seed, name),
                tuned ? kTunedWeight : kOtherWeight);
    TrainResult trained =
        fogdrift::train(train, dataset, train_options(o, method, seed, o.fitness));
    MethodRun m;
    m.method = std::string(name);
    m.table2 = table2_of(trained.model, test);
    m.rmse_deg = northfind_rmse(nf, predicted_by(trained.model));
    m.mean_rmse_deg = mean_of(m.rmse_deg);
    for (const sim::SimulatedCampaign& c : start_ups) {
      // One prediction per recording gives both the guarded and the unguarded drift.
      std::vector<RecordingPrediction> predicted;
      for (const Recording& rec : c.recordings) predicted.push_back(trained.model.predict(rec));
      auto of = [&](const Recording& rec) -> const RecordingPrediction& {
        return predicted[static_cast<std::size_t>(&rec - c.recordings.data())];
      };
      const eval::DriftOf guarded = [&](const Recording& rec) { return of(rec).drift_dph; };
      const eval::DriftOf unguarded = [&](const Recording& rec) { return of(rec).model_drift_dph; };
      m.start_up_rmse_deg.push_back(
          eval::field_summary(c.campaign, c.recordings, guarded).comp_mean_rmse_deg());
      m.start_up_unguarded_rmse_deg.push_back(
          eval::field_summary(c.campaign, c.recordings, unguarded).comp_mean_rmse_deg());
    }
    m.hyperparameters = trained.summary.hyperparameters;
    m.fitness_value = trained.summary.fitness_value;
    m.train_seconds = trained.summary.seconds;
    run.methods.push_back(std::move(m));
    if (keep) keep->models.emplace(std::string(name), std::move(trained.model));
  }
  if (keep) {
    keep->cal = std::move(cal);
    keep->nf = std::move(nf);
    keep->train = std::move(train);
    keep->test = std::move(test);
    keep->dataset = dataset;
  }
  run.seconds = seconds_since(start);
  return run;
}

std::vector<LotoRow> loto_study(const PaperOptions& o, const SeedRun& run, const FirstSeed& f) {
  std::vector<double> temps;
  for (const auto& g : f.train.groups) temps.push_back(g.initial_temp_degc);
  std::sort(temps.begin(), temps.end());
  temps.erase(std::unique(temps.begin(), temps.end()), temps.end());
  const std::string methods[] = {"ssa-svr", "bp"};
  std::vector<LotoRow> rows(temps.size() * 2);
  auto job = [&](std::size_t k) {
    const double t = temps[k / 2];
    const std::string& name = methods[k % 2];
    std::vector<std::size_t> keep_groups, test_groups;
    for (std::size_t g = 0; g < f.train.groups.size(); ++g)
      if (f.train.groups[g].initial_temp_degc != t) keep_groups.push_back(g);
    for (std::size_t g = 0; g < f.test.groups.size(); ++g)
      if (f.test.groups[g].initial_temp_degc == t) test_groups.push_back(g);
    const Dataset train = f.train.select_groups(keep_groups);
    const Dataset test = f.test.select_groups(test_groups);
    // The pool is nested inside the study's loop here: it runs serially.
    TrainOptions to =
        train_options(o, name == "bp" ? Method::bp : Method::svr, run.seed, o.fitness);
    // One temperature fewer to deal into temperature folds (they only score the model here).
    if (to.tune.cv.scheme == tune::CvScheme::temperature) {
      if (temps.size() >= 3)
        to.tune.cv.folds = std::min(to.tune.cv.folds, temps.size() - 1);
      else
        to.tune.cv = tune::CvOptions{};
    }
    if (name != "bp") to.svr_params = svr_params_of(run.method(name));
    const TrainResult loto = fogdrift::train(train, f.dataset, to);
    const eval::CompensationMetrics all = table2_of(f.models.at(name), test);
    const eval::CompensationMetrics left = table2_of(loto.model, test);
    rows[k] =
        LotoRow{t,           name,        all.std_before_dph, all.std_after_dph, left.std_after_dph,
                all.mae_dph, left.mae_dph};
  };
  if (o.pool)
    o.pool->parallel_for(rows.size(), job);
  else
    for (std::size_t k = 0; k < rows.size(); ++k) job(k);
  return rows;
}

std::vector<FitnessRow> fitness_study(const PaperOptions& o, const SeedRun& run,
                                      const FirstSeed& f) {
  std::vector<FitnessRow> rows;
  for (tune::Fitness fitness : {tune::Fitness::cv, tune::Fitness::train}) {
    FitnessRow row;
    row.fitness = std::string(tune::to_string(fitness));
    if (fitness == o.fitness) {
      const MethodRun& m = run.method("ssa-svr");
      row.c = m.hyperparameter("C");
      row.sigma = m.hyperparameter("sigma");
      row.fitness_value = m.fitness_value;
      row.std_dph = m.table2.std_after_dph;
      row.mae_dph = m.table2.mae_dph;
      row.mean_rmse_deg = m.mean_rmse_deg;
    } else {
      const TrainResult t =
          train(f.train, f.dataset, train_options(o, Method::ssa_svr, run.seed, fitness));
      row.c = t.summary.tuning.best.c;
      row.sigma = t.summary.tuning.best.kernel.sigma();
      row.fitness_value = t.summary.fitness_value;
      const eval::CompensationMetrics m = table2_of(t.model, f.test);
      row.std_dph = m.std_after_dph;
      row.mae_dph = m.mae_dph;
      row.mean_rmse_deg = mean_of(northfind_rmse(f.nf, predicted_by(t.model)));
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<Figure> figures_of(const PaperResult& r, const FirstSeed& f) {
  std::vector<Figure> out;
  const std::size_t window = 61, step = 10;
  // Fig. 1 and 2: the test repetition's start-ups.
  Figure fig1{"fig1_startup", "Fig. 1 — start-up output at every initial temperature", {}};
  Figure fig2{"fig2_output_vs_temperature", "Fig. 2 — output against the FOG temperature", {}};
  Panel p1{"calibration test repetition, 60 s moving average",
           "time since power-on (min)",
           "gyro output (°/h)",
           {}};
  Panel p2{"calibration test repetition, 60 s moving average",
           "FOG thermometer (°C)",
           "gyro output (°/h)",
           {}};
  for (std::size_t i = 0; i < f.cal.recordings.size(); ++i) {
    const CampaignEntry& e = f.cal.campaign.recordings[i];
    if (e.role != Role::test) continue;
    const Recording& rec = f.cal.recordings[i];
    std::vector<double> minutes;
    for (std::size_t k = 0; k < rec.time_s.size(); k += step) minutes.push_back(rec.time_s[k] / 60);
    const std::vector<double> gyro = smoothed(rec.gyro_dph, window, step);
    p1.series.push_back({temp_label(e.initial_temp_degc), minutes, gyro});
    p2.series.push_back({temp_label(e.initial_temp_degc),
                         smoothed(rec.numeric_column("temp_fog_degc"), window, step), gyro});
  }
  fig1.panels.push_back(std::move(p1));
  fig2.panels.push_back(std::move(p2));
  out.push_back(std::move(fig1));
  out.push_back(std::move(fig2));

  // Fig. 3: a calibration-like start-up at 25 °C (cycles at 5 and 15 °C before it).
  {
    sim::CalibrationOptions co = r.options.calibration;
    co.seed = r.seeds.front().seed;
    co.temps_degc = {5, 15, 25};
    co.repetitions = 1;
    co.test_repetitions = 0;
    const auto c = sim::simulate_calibration(r.options.instrument, co);
    const FeatureTable table =
        compute_features(c.recordings.back(), f.dataset.features, f.dataset.preprocessing);
    Figure fig3{"fig3_features_25C",
                "Fig. 3 — temperatures, rates and gradients after power-on at 25 °C",
                {{"temperatures", "time since power-on (min)", "°C", {}},
                 {"rates", "time since power-on (min)", "°C/s", {}},
                 {"gradients", "time since power-on (min)", "°C", {}}}};
    std::vector<double> minutes;
    for (double t : table.time_s) minutes.push_back(t / 60);
    for (std::size_t c2 = 0; c2 < table.names.size(); ++c2) {
      const std::string& name = table.names[c2];
      const std::size_t panel = name.starts_with("dT") ? 1 : (name.starts_with("grad") ? 2 : 0);
      Series s{name, minutes, {}};
      for (std::size_t k = 0; k < table.rows; ++k)
        s.y.push_back(table.x[k * table.names.size() + c2]);
      fig3.panels[panel].series.push_back(std::move(s));
    }
    out.push_back(std::move(fig3));
  }

  // Fig. 8: the test repetition before and after compensation, recordings end to end.
  {
    Figure fig8{"fig8_compensation",
                "Fig. 8 — test repetition before and after compensation (each recording's mean "
                "removed)",
                {}};
    Panel p{"recordings −40 … 60 °C end to end, 10 s blocks",
            "hours of powered time",
            "drift (°/h)",
            {}};
    Series denoised{"denoised", {}, {}};
    std::vector<Series> comp;
    std::vector<std::vector<double>> predicted;
    for (const char* name : {"bp", "ssa-svr"}) {
      comp.push_back({fmt::format("compensated, {}", name), {}, {}});
      predicted.push_back(f.models.at(name).predict_dph(f.test));
    }
    double offset_h = 0;
    for (std::size_t g = 0; g < f.test.groups.size(); ++g) {
      std::vector<std::size_t> rows;
      for (std::size_t i = 0; i < f.test.rows; ++i)
        if (f.test.group[i] == g) rows.push_back(i);
      if (rows.empty()) continue;
      double my = 0;
      std::vector<double> mc(comp.size(), 0.0);
      for (std::size_t i : rows) {
        my += f.test.y[i];
        for (std::size_t m = 0; m < comp.size(); ++m) mc[m] += f.test.y[i] - predicted[m][i];
      }
      my /= static_cast<double>(rows.size());
      for (double& v : mc) v /= static_cast<double>(rows.size());
      for (std::size_t i : rows) {
        const double h = offset_h + f.test.time_s[i] / 3600;
        denoised.x.push_back(h);
        denoised.y.push_back(f.test.y[i] - my);
        for (std::size_t m = 0; m < comp.size(); ++m) {
          comp[m].x.push_back(h);
          comp[m].y.push_back(f.test.y[i] - predicted[m][i] - mc[m]);
        }
      }
      offset_h = denoised.x.back() + 10.0 / 3600;
    }
    p.series.push_back(std::move(denoised));
    for (auto& s : comp) p.series.push_back(std::move(s));
    fig8.panels.push_back(std::move(p));
    out.push_back(std::move(fig8));
  }

  // North-finding RMSE per initial temperature, means over the seeds.
  {
    Figure fig{"fig_northfind",
               fmt::format("North-finding RMSE per initial temperature (mean of {} seed{})",
                           r.seeds.size(), r.seeds.size() == 1 ? "" : "s"),
               {{"five findings during the start-up at each temperature",
                 "initial temperature (°C)",
                 "RMSE (°)",
                 {}}}};
    auto& series = fig.panels[0].series;
    const std::size_t n = r.northfind_temps_degc.size();
    auto mean_over_seeds = [&](auto get) {
      std::vector<double> y(n, 0.0);
      for (const SeedRun& s : r.seeds) {
        const std::vector<double>& v = get(s);
        for (std::size_t k = 0; k < n; ++k) y[k] += v[k] / static_cast<double>(r.seeds.size());
      }
      return y;
    };
    series.push_back({"raw", r.northfind_temps_degc,
                      mean_over_seeds([](const SeedRun& s) -> const std::vector<double>& {
                        return s.raw_rmse_deg;
                      }),
                      true});
    for (std::string_view name : kPaperMethods) {
      series.push_back({std::string(name), r.northfind_temps_degc,
                        mean_over_seeds([name](const SeedRun& s) -> const std::vector<double>& {
                          return s.method(name).rmse_deg;
                        }),
                        true});
    }
    if (!r.seeds.front().oracle_rmse_deg.empty()) {
      series.push_back({"true drift subtracted", r.northfind_temps_degc,
                        mean_over_seeds([](const SeedRun& s) -> const std::vector<double>& {
                          return s.oracle_rmse_deg;
                        }),
                        true});
    }
    std::vector<double> stable;
    for (const SeedRun& s : r.seeds) stable.push_back(s.stable_rmse_deg);
    const double st = mean_of(stable);
    series.push_back({"stable stage",
                      {r.northfind_temps_degc.front(), r.northfind_temps_degc.back()},
                      {st, st},
                      false,
                      true});
    out.push_back(std::move(fig));
  }
  return out;
}

}  // namespace

double MethodRun::hyperparameter(std::string_view name) const {
  for (const auto& [n, v] : hyperparameters)
    if (n == name) return v;
  return std::nan("");
}

const MethodRun& SeedRun::method(std::string_view name) const {
  for (const auto& m : methods)
    if (m.method == name) return m;
  throw std::out_of_range(fmt::format("no method {} in this run", name));
}

void validate(const PaperOptions& o) {
  if (o.seeds < 1 || o.seeds > 1000)
    throw OptionError("seeds", fmt::format("{} is outside [1, 1000]", o.seeds));
  if (o.population < 5 || o.population > 10000)
    throw OptionError("population",
                      fmt::format("{} is outside [5, 10000] (SSA needs 5 sparrows)", o.population));
  if (!std::isfinite(o.epsilon) || o.epsilon < 0 || o.epsilon > 10)
    throw OptionError("epsilon", fmt::format("{} is outside [0, 10]", o.epsilon));
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
  if (o.cv.scheme == tune::CvScheme::temperature && (o.cv.folds < 2 || o.cv.folds > temps))
    throw OptionError("cv.folds", fmt::format("{} folds of whole temperatures need 2 to {} (the "
                                              "calibration temperatures); set --folds, or --cv "
                                              "repetition to leave one repetition out",
                                              o.cv.folds, temps));
  if (o.cv.scheme == tune::CvScheme::recording &&
      (o.cv.folds < 2 || o.cv.folds > temps * train_reps))
    throw OptionError("cv.folds", fmt::format("{} folds of whole recordings need 2 to {} (the "
                                              "training recordings)",
                                              o.cv.folds, temps * train_reps));
  if (o.cv.scheme == tune::CvScheme::repetition && train_reps < 2)
    throw OptionError("cv.scheme",
                      "leave one repetition out needs two or more training repetitions");
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
  const double per_seed = 3 * kTunedWeight + 3 * kOtherWeight;
  stages.total = per_seed * static_cast<double>(options.seeds) +
                 (options.studies ? kLotoWeight + kTunedWeight : 0.0) + 1;
  FirstSeed first;
  for (std::size_t k = 0; k < options.seeds; ++k) {
    const std::uint64_t seed = options.first_seed + k;
    r.seeds.push_back(run_seed(options, seed, stages, k == 0 ? &first : nullptr));
  }
  if (options.studies) {
    stages.step("study: leave one temperature out", kLotoWeight);
    r.loto = loto_study(options, r.seeds.front(), first);
    stages.step("study: training-loss against cross-validation fitness", kTunedWeight);
    r.fitness = fitness_study(options, r.seeds.front(), first);
  }
  stages.step("figures", 1);
  r.figures = figures_of(r, first);
  r.seconds = seconds_since(start);
  if (options.progress) options.progress("done", 1.0);
  return r;
}

}  // namespace fogdrift::report
