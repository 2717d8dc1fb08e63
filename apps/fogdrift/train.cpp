// fogdrift train: fit a compensation model on a campaign's training recordings (docs/method.md §2).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/campaign.hpp"
#include "fogdrift/csv.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/model_set.hpp"
#include "fogdrift/thread_pool.hpp"
#include "fogdrift/train_campaign.hpp"

namespace fogdrift::app {
namespace {

// The flags' defaults are the library's, so that they live in one place.
const TrainOptions kTrain;
const opt::RunOptions kRun;

struct TrainArgs {
  std::string campaign;
  std::string output;
  std::string method = to_string(kTrain.method);
  std::string fitness = tune::to_string(kTrain.tune.fitness);
  std::string features = "auto";
  std::string thermometers = "auto";
  std::string cv = tune::to_string(kTrain.tune.cv.scheme);
  std::string differentiator = std::string(signal::to_string(FeatureOptions{}.rates.causality));
  std::string block_s = "auto";
  std::string rate_window_s = "auto";
  std::string rate_degree = "auto";
  std::size_t folds = kTrain.tune.cv.folds;
  std::size_t population = kRun.population;
  std::size_t iterations = kRun.iterations;
  std::uint64_t seed = kRun.seed;
  unsigned threads = 0;
  double cache_mb = kTrain.tune.cache_mb;
  double c_min = tune::SearchSpace{}.c_min, c_max = tune::SearchSpace{}.c_max,
         sigma_min = tune::SearchSpace{}.sigma_min, sigma_max = tune::SearchSpace{}.sigma_max,
         epsilon = tune::SearchSpace{}.epsilon;
  bool search_epsilon = false;
  bool auto_box = false;
  bool no_racing = false;
  bool no_denoise = false;
  std::size_t hidden = kTrain.mlp.hidden;
  std::size_t max_degree = kTrain.poly_max_degree;
  std::size_t gp_points = kTrain.gp.max_points;
  std::string gp_kernel = kTrain.gp.ard ? "ard" : "rbf";
  std::string gp_fit = std::string(to_string(kTrain.gp.selection));
  std::string targets = "gyro_dph";
  bool json = false;
  bool quiet = false;
};

// The library's field names and the flags that set them.
const FlagTable kTrainFlags = {{"population", "--population"},
                               {"iterations", "--iterations"},
                               {"c_min", "--c-min"},
                               {"c_max", "--c-max"},
                               {"sigma_min", "--sigma-min"},
                               {"sigma_max", "--sigma-max"},
                               {"epsilon", "--epsilon"},
                               {"epsilon_min", "--epsilon"},
                               {"epsilon_max", "--epsilon"},
                               {"cv", "--cv"},
                               {"folds", "--folds"},
                               {"hidden", "--hidden"},
                               {"degree", "--max-degree"},
                               {"gp_points", "--gp-points"},
                               {"gp_kernel", "--gp-kernel"},
                               {"gp_fit", "--gp-fit"},
                               {"features", "--features"},
                               {"thermometers", "--thermometers"},
                               {"block_s", "--block-s"},
                               {"window_s", "--rate-window-s"},
                               {"poly_order", "--rate-degree"},
                               {"denoise", "--no-denoise"},
                               {"cache_mb", "--cache-mb"}};

/// "auto" or a positive number of seconds.
std::optional<double> seconds_or_auto(const std::string& text, const std::string& flag) {
  if (text == "auto") return std::nullopt;
  const auto v = csv::parse_number(text);
  if (!v || !(*v > 0))
    throw OptionError(flag,
                      fmt::format("'{}' is neither auto nor a positive number of seconds", text));
  return v;
}

/// "auto" or a polynomial degree 1..4.
std::optional<int> degree_or_auto(const std::string& text) {
  if (text == "auto") return std::nullopt;
  const auto v = csv::parse_number(text);
  if (!v || *v != std::floor(*v) || *v < 1 || *v > 4)
    throw OptionError("--rate-degree",
                      fmt::format("'{}' is neither auto nor a whole degree 1..4", text));
  return static_cast<int>(*v);
}

/// The choices made for the user, each with the flag that would change it.
std::vector<std::string> notes_of(const CampaignTrainResult& trained) {
  std::vector<std::string> notes;
  for (const CampaignNote& n : trained.notes)
    notes.push_back(fmt::format("{} ({})", n.text, flag_for(n.field, kTrainFlags)));
  return notes;
}

/// A best value on the edge of its box: the box, not the data, may have stopped the search.
std::vector<std::string> edge_notes_of(const TrainArgs& a, const TrainSummary& s) {
  return box_edge_warnings(s, a.auto_box, [](const std::string& field) {
    return field == "auto_box"         ? std::string("--auto-box")
           : field == "search_epsilon" ? std::string("--search-epsilon")
                                       : flag_for(field, kTrainFlags);
  });
}

/// `fogdrift train --json`'s summary of one model.
nlohmann::ordered_json summary_json(const TrainArgs& a, const CampaignTrainResult& trained) {
  const TrainSummary& s = trained.trained.summary;
  const Dataset& data = trained.data;
  const DatasetOptions& dataset = trained.dataset;
  const Provenance& p = trained.trained.model.provenance;
  const std::vector<std::string> notes = notes_of(trained);
  {
    nlohmann::ordered_json j;
    j["model"] = a.output;
    j["method"] = to_string(s.method);
    j["fitness"] = s.fitness;
    j["fitness_rmse"] = s.fitness_value;
    j["cv"] = p.cv;
    for (const auto& [k, v] : s.hyperparameters) j["hyperparameters"][k] = v;
    j["training_rows"] = s.rows;
    j["recordings"] = data.groups.size();
    j["features"] = data.feature_names;
    if (s.method == Method::ssa_svr || s.method == Method::pso_svr || s.method == Method::gwo_svr) {
      const auto& t = s.tuning;
      j["search"] = {{"optimizer", opt::to_string(t.optimizer.algorithm)},
                     {"population", a.population},
                     {"iterations", t.optimizer.iterations},
                     {"evaluations", t.optimizer.evaluations},
                     {"candidates", t.candidates},
                     {"repeats", t.repeats},
                     {"fits", t.fits},
                     {"raced", t.raced},
                     {"initial_best_rmse", t.optimizer.initial_best_fitness},
                     {"seconds", t.seconds}};
      nlohmann::ordered_json log = nlohmann::ordered_json::array();
      for (const auto& r : t.optimizer.log) log.push_back(r.best_fitness);
      j["search"]["best_rmse_per_iteration"] = log;
    }
    if (s.method == Method::bp)
      j["bp"] = {{"epochs", s.mlp.epochs},
                 {"best_epoch", s.mlp.best_epoch},
                 {"early_stopped", s.mlp.status == MlpStatus::early_stopped},
                 {"train_rmse", s.mlp.train_rmse}};
    if (s.method == Method::poly) j["poly_cv_rmse_by_degree"] = s.poly_cv_rmse;
    if (s.method == Method::gp)
      j["gp"] = {{"points", s.gp.points},         {"log_likelihood", s.gp.log_likelihood},
                 {"iterations", s.gp.iterations}, {"evaluations", s.gp.evaluations},
                 {"fold_fits", s.gp.fold_fits},   {"raced", s.gp.raced},
                 {"converged", s.gp.converged}};
    j["notes"] = notes;
    nlohmann::ordered_json edges = nlohmann::ordered_json::array();
    for (const auto& e : s.box_edges)
      edges.push_back({{"parameter", e.parameter},
                       {"edge", e.upper ? "upper" : "lower"},
                       {"value", e.value},
                       {"box", {e.low, e.high}},
                       {"improvement", e.improvement}});
    j["box_edges"] = edges;
    nlohmann::ordered_json boxes = nlohmann::ordered_json::array();
    for (const auto& b : s.boxes)
      boxes.push_back({{"c", {b.c_min, b.c_max}}, {"sigma", {b.sigma_min, b.sigma_max}}});
    j["boxes_searched"] = boxes;
    if (s.held_out) {
      const HeldOutReport& h = *s.held_out;
      nlohmann::ordered_json base = nlohmann::ordered_json::array();
      for (const Baseline& b : h.baselines) base.push_back({{"name", b.name}, {"rmse", b.rmse}});
      j["held_out"] = {{"folds", h.folds},
                       {"model_rmse", h.model_rmse},
                       {"expected_share", h.expected_share},
                       {"expected_startup_share", h.expected_startup_share},
                       {"baselines", base},
                       {"warnings", h.warnings}};
    } else {
      j["held_out"] = {{"missing", s.held_out_missing}};
    }
    nlohmann::ordered_json warnings = data.warnings;
    if (s.held_out)
      for (const auto& w : s.held_out->warnings) warnings.push_back(w);
    j["warnings"] = warnings;
    j["block_s"] = dataset.preprocessing.block.block_s;
    j["rate_window_s"] = dataset.preprocessing.rates.window_s;
    j["seconds"] = s.seconds;
    return j;
  }
}

/// The text summary of one model; `heading` prefixes its first line (the axis of a model set).
void print_summary(const TrainArgs& a, const CampaignTrainResult& trained,
                   const std::string& heading) {
  const TrainSummary& s = trained.trained.summary;
  const Dataset& data = trained.data;
  const Provenance& p = trained.trained.model.provenance;
  const std::vector<std::string> notes = notes_of(trained);
  const std::vector<std::string> edge_notes = edge_notes_of(a, s);
  {
    std::string hyper;
    for (const auto& [k, v] : s.hyperparameters)
      hyper += fmt::format("{}{} = {:.6g}", hyper.empty() ? "" : ", ", k, v);
    std::cout << fmt::format("{}{}: {} on {} rows of {} training recordings ({} features)\n",
                             heading, a.campaign, to_string(s.method), s.rows, data.groups.size(),
                             data.cols());
    std::cout << fmt::format("  {}\n", hyper);
    std::cout << fmt::format("  {} RMSE {:.5f} (standardised drift){}\n", s.fitness,
                             s.fitness_value, p.cv.empty() ? "" : ", " + p.cv);
    if (!s.tuning.optimizer.log.empty())
      std::cout << fmt::format(
          "  search: {}; {} distinct candidates ({} stopped early by "
          "racing), {} SVR fits\n",
          s.tuning.optimizer.brief_report(), s.tuning.candidates, s.tuning.raced, s.tuning.fits);
    if (s.boxes.size() > 1) {
      const auto& b = s.boxes.back();
      std::cout << fmt::format(
          "  auto-box: {} searches, last box C [{:.6g}, {:.6g}], sigma "
          "[{:.6g}, {:.6g}]\n",
          s.boxes.size(), b.c_min, b.c_max, b.sigma_min, b.sigma_max);
    }
    if (s.held_out) {
      const HeldOutReport& h = *s.held_out;
      std::cout << fmt::format(
          "  expected to remove {:.0f} % of the drift on held-out rows, {:.0f} % of its variation "
          "within a start-up: {}\n",
          100.0 * h.expected_share, 100.0 * h.expected_startup_share, h.folds);
      std::string base;
      for (const Baseline& b : h.baselines) base += fmt::format(", {} {:.4f}", b.name, b.rmse);
      std::cout << fmt::format("  held-out RMSE (standardised): model {:.4f}{}\n", h.model_rmse,
                               base);
    } else if (!s.held_out_missing.empty()) {
      std::cout << fmt::format("  expected share: n/a ({})\n", s.held_out_missing);
    }
    for (const auto& n : notes) std::cout << "  note: " << n << "\n";
    if (s.held_out)
      for (const auto& w : s.held_out->warnings) std::cout << "  warning: " << w << "\n";
    for (const auto& n : edge_notes) std::cout << "  warning: " << n << "\n";
    for (const auto& w : data.warnings) std::cout << "  warning: " << w << "\n";
  }
}

void run(const TrainArgs& a) {
  TrainOptions options;
  DatasetOptions dataset;
  std::vector<std::string> thermometers;  // empty: auto
  try {
    options.method = parse_method(a.method, "--method");
    options.tune.fitness = tune::parse_fitness(a.fitness, "--fitness");
    options.tune.cv.scheme = tune::parse_cv_scheme(a.cv, "--cv");
    if (a.thermometers != "auto") thermometers = parse_thermometers(a.thermometers);
    if (a.features != "auto") dataset.features = FeatureSpec::parse(a.features, thermometers);
    dataset.preprocessing.rates.causality =
        signal::parse_causality(a.differentiator, "--differentiator");
  } catch (const OptionError& e) {
    throw as_flag(e, kTrainFlags);
  }
  options.tune.cv.folds = a.folds;
  options.tune.optimizer.run.population = a.population;
  options.tune.optimizer.run.iterations = a.iterations;
  options.tune.optimizer.run.seed = a.seed;
  options.tune.cache_mb = a.cache_mb;
  options.tune.space.c_min = a.c_min;
  options.tune.space.c_max = a.c_max;
  options.tune.space.sigma_min = a.sigma_min;
  options.tune.space.sigma_max = a.sigma_max;
  options.tune.space.epsilon = a.epsilon;
  options.tune.space.search_epsilon = a.search_epsilon;
  options.auto_box_rounds = a.auto_box ? TrainOptions::kAutoBoxRounds : 0;
  options.tune.racing = !a.no_racing;
  dataset.denoise_target = !a.no_denoise;
  options.mlp.hidden = a.hidden;
  options.poly_max_degree = a.max_degree;
  options.gp.max_points = a.gp_points;
  options.gp.ard = a.gp_kernel == "ard";
  options.gp.selection = parse_gp_selection(a.gp_fit, "--gp-fit");
  ThreadPool pool(a.threads);
  options.tune.pool = &pool;

  const bool show_progress = !a.quiet && !a.json && stderr_is_terminal();
  const auto start = std::chrono::steady_clock::now();
  if (show_progress) {
    options.tune.optimizer.run.progress = [&](const opt::IterationRecord& r) {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cerr << fmt::format(
                       "\r{}: iteration {}/{}, best {} RMSE {:.5f}, {} evaluations, {:.0f} s ",
                       a.method, r.iteration, a.iterations, a.fitness, r.best_fitness,
                       r.evaluations, s)
                << std::flush;
      return true;
    };
  }

  CampaignTrainOptions campaign_options;
  campaign_options.train = options;
  campaign_options.dataset = dataset;
  campaign_options.auto_features = a.features == "auto";
  campaign_options.thermometers = thermometers;
  campaign_options.block_s = seconds_or_auto(a.block_s, "--block-s");
  campaign_options.rate_window_s = seconds_or_auto(a.rate_window_s, "--rate-window-s");
  campaign_options.rate_degree = degree_or_auto(a.rate_degree);
  const Campaign campaign = read_campaign(a.campaign);
  // One model per target column, each with its own search and guard (docs/logs.md, "Every
  // axis"), written as one file.
  const std::vector<std::string> targets = split_list(a.targets);
  for (std::size_t i = 0; i < targets.size(); ++i) {
    target_of(targets[i], "--targets");
    if (std::find(targets.begin(), targets.begin() + static_cast<std::ptrdiff_t>(i), targets[i]) !=
        targets.begin() + static_cast<std::ptrdiff_t>(i))
      throw OptionError("--targets", fmt::format("'{}' is named twice", targets[i]));
  }
  if (targets.empty()) throw OptionError("--targets", "names no column to compensate");
  std::vector<CampaignTrainResult> results;
  for (const std::string& target : targets) {
    campaign_options.dataset.target_column = target;
    if (show_progress && targets.size() > 1) std::cerr << target << ": ";
    try {
      results.push_back(train_campaign(campaign, campaign_options));
    } catch (const OptionError& e) {
      if (show_progress) std::cerr << "\n";
      throw as_flag(e, kTrainFlags);
    }
    if (show_progress) std::cerr << "\n";
  }
  if (results.size() == 1) {
    save(results.front().trained.model, a.output);
  } else {
    ModelSet set;
    for (const auto& r : results) set.models.push_back(r.trained.model);
    save(set, a.output);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (a.json && results.size() == 1) {
    std::cout << summary_json(a, results.front()).dump(2) << "\n";
  } else if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.output;
    j["targets"] = targets;
    j["axes"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < results.size(); ++i) {
      nlohmann::ordered_json one;
      one["target"] = targets[i];
      const nlohmann::ordered_json summary = summary_json(a, results[i]);
      for (const auto& [k, v] : summary.items())
        if (k != "model") one[k] = v;
      j["axes"].push_back(one);
    }
    j["seconds"] = seconds;
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    for (std::size_t i = 0; i < results.size(); ++i)
      print_summary(a, results[i], results.size() > 1 ? targets[i] + ": " : "");
    std::cout << fmt::format("  wrote {}{} in {:.1f} s\n", a.output,
                             results.size() > 1 ? fmt::format(" ({} axes)", results.size()) : "",
                             seconds);
  }
}

}  // namespace

void add_train(CLI::App& app) {
  auto args = std::make_shared<TrainArgs>();
  auto* cmd = app.add_subcommand(
      "train",
      "Train a compensation model on the calibration recordings whose role is \"train\" and write\n"
      "it as JSON (features, scalers, regressor, provenance with SHA-256 of every data file).\n\n"
      "Methods (paper Table 2):\n"
      "  ssa-svr  ε-SVR, C and σ tuned by sparrow search (Xue & Shen 2020)   [default]\n"
      "  pso-svr  the same tuned by particle swarm;  gwo-svr  by grey wolf\n"
      "  svr      untuned: LIBSVM's defaults C = 1, γ = 1/features, ε = 0.1\n"
      "  bp       one-hidden-layer tanh network, Adam, early stopping on held-out recordings\n"
      "  poly     polynomial in the features, degree chosen by cross-validation\n"
      "  gp       Gaussian process, squared-exponential kernel, its length scale and noise\n"
      "           chosen by the same search and folds, on --gp-points rows (docs/gp.md)\n"
      "Fitness of a candidate (C, σ): 'cv' (default) is the RMSE over grouped folds that never\n"
      "split a recording: with --cv auto, three folds of whole calibration temperatures (a model\n"
      "scored where it was not trained, as a start-up at a new temperature asks), or with fewer\n"
      "than three temperatures, leave one repetition out; 'train' is the paper's training RMSE,\n"
      "which favours over-fitting. C and σ are searched in log10 space, ε is 0.05 "
      "(docs/tuning.md).\n"
      "The model records the region of feature space it was trained on; compensate, stream,\n"
      "evaluate, northfind and export-c reduce its correction outside it (docs/field.md).\n"
      "Calibrate under the start-up conditions the instrument will meet: docs/field.md gives the\n"
      "protocol (fogdrift simulate calibration --approach calibration,soaked,warm,ramping).\n"
      "Examples:\n"
      "  fogdrift simulate calibration --out cal && fogdrift train cal -o model.json\n"
      "  fogdrift train cal --method pso-svr --population 30 --iterations 40 --seed 2 -o pso.json\n"
      "  fogdrift train cal --method bp --hidden 12 -o bp.json --json");
  cmd->add_option("campaign", args->campaign, "Campaign folder (or its campaign.json)")->required();
  cmd->add_option("-o,--output", args->output, "Model file to write (JSON, atomically)")
      ->required();
  cmd->add_option("--method", args->method, "ssa-svr, pso-svr, gwo-svr, svr, bp, poly or gp")
      ->capture_default_str();
  cmd->add_option("--fitness", args->fitness, "cv (grouped cross-validation) or train")
      ->capture_default_str();
  cmd->add_option(
         "--features", args->features,
         "Feature spec: terms T, dT, grad, dgrad, t, TdT, dT@SECONDS (the rate through a "
         "lag of that time constant), each optionally with its thermometers, e.g. "
         "'T,dT(fog),grad'; auto: the paper's T,dT,grad and the rates through a 300 s lag, "
         "T,dT,grad,dT@300, over the thermometers every training recording has "
         "(T(fog),dT(fog),dT@300(fog) with one; docs/field.md)")
      ->capture_default_str();
  cmd->add_option("--thermometers", args->thermometers,
                  "The thermometers the features read, e.g. fog,acc1,acc2,case: the auto "
                  "features over them, or what a term of --features without its own list reads. "
                  "fog, acc1, acc2, or NAME of a further column temp_NAME_degc; the model then "
                  "needs its reading wherever it runs (stream, export-c). auto: those of fog, "
                  "acc1, acc2 every training recording has")
      ->capture_default_str();
  cmd->add_option("--differentiator", args->differentiator,
                  "Temperature rates: centred (offline, no delay) or causal (what the instrument "
                  "can run sample by sample; train with it for a streaming compensator)")
      ->capture_default_str();
  cmd->add_option(
         "--block-s", args->block_s,
         "Averaging block of the modelling rows, s, a whole number of samples; auto: 10 s, "
         "or the nearest whole number of samples for a log that 10 s does not divide "
         "(one sample for logs slower than 0.1 Hz)")
      ->capture_default_str();
  cmd->add_option("--rate-window-s", args->rate_window_s,
                  "Window of the temperature-rate differentiator, s; auto: 121 s centred, "
                  "61 s causal, at least 5 samples, and (centred) no longer than the shortest "
                  "recording")
      ->capture_default_str();
  cmd->add_option("--rate-degree", args->rate_degree,
                  "Degree of the polynomial the differentiator fits, 1..4; auto: 2 centred, 1 "
                  "causal. For causal rates 1 is the least noisy and lags by half the window, 2 "
                  "does not lag a steady curvature and is about four times noisier "
                  "(docs/signal.md)")
      ->capture_default_str();
  cmd->add_option("--cv", args->cv,
                  "Folds: auto (temperature with at least three temperatures, else repetition), "
                  "repetition (leave one out), recording (k folds of whole recordings) or "
                  "temperature (k folds of whole initial temperatures: the fitness of a model at "
                  "temperatures it never saw). bp, which is not refitted after early stopping, "
                  "stops on a third of the recordings unless repetition or recording is asked")
      ->capture_default_str();
  cmd->add_option("--folds", args->folds, "k for --cv recording or temperature")
      ->capture_default_str();
  cmd->add_option("--population", args->population, "Optimizer population")->capture_default_str();
  cmd->add_option("--iterations", args->iterations, "Optimizer iterations")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the search (and of BP's weights)")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads,
                  "Threads (0: one per core); results do not depend on it")
      ->capture_default_str();
  cmd->add_option("--cache-mb", args->cache_mb,
                  "Kernel-row cache of each SVR fit, MB (one fit per thread): less memory, "
                  "slower fits")
      ->capture_default_str();
  cmd->add_option("--c-min", args->c_min, "Smallest C searched")->capture_default_str();
  cmd->add_option("--c-max", args->c_max, "Largest C searched")->capture_default_str();
  cmd->add_option("--sigma-min", args->sigma_min, "Smallest σ searched (standardised features)")
      ->capture_default_str();
  cmd->add_option("--sigma-max", args->sigma_max, "Largest σ searched")->capture_default_str();
  cmd->add_option("--epsilon", args->epsilon, "ε of the tube (standardised target)")
      ->capture_default_str();
  cmd->add_flag("--search-epsilon", args->search_epsilon, "Also search ε in [0.001, 1]");
  cmd->add_flag("--no-denoise", args->no_denoise,
                "Train on the raw gyro, not its wavelet-denoised version (for recordings too "
                "short to denoise, or already smooth: a log of burst means)");
  cmd->add_flag("--auto-box", args->auto_box,
                fmt::format("When the best C, σ or ε lies on an edge of its box, widen the box a "
                            "decade there and search again (at most {} times); train warns of "
                            "such edges either way",
                            TrainOptions::kAutoBoxRounds));
  cmd->add_flag("--no-racing", args->no_racing,
                "Fit every fold of every candidate. By default a candidate whose held-out errors "
                "on the folds fitted so far already exceed the best candidate's leaves the "
                "search: the same best among the candidates visited, in about half the fits "
                "(docs/tuning.md)");
  cmd->add_option("--hidden", args->hidden, "bp: hidden tanh units")->capture_default_str();
  cmd->add_option("--max-degree", args->max_degree, "poly: highest degree tried")
      ->capture_default_str();
  cmd->add_option("--gp-points", args->gp_points,
                  "gp: training rows the Gaussian process keeps, evenly spaced, 10 … 4000; its "
                  "time grows as the cube, its C header's work per sample linearly")
      ->capture_default_str();
  cmd->add_option("--gp-fit", args->gp_fit,
                  "gp: how the hyperparameters are chosen: cv, the length scale and the noise "
                  "ratio by the search over --cv's folds, as the SVR's C and σ (population, "
                  "iterations and seed as above); likelihood, all of them by the marginal "
                  "likelihood, which favours short length scales on start-up data (docs/gp.md)")
      ->check(CLI::IsMember({"cv", "likelihood"}))
      ->capture_default_str();
  cmd->add_option("--gp-kernel", args->gp_kernel,
                  "gp: rbf, one length scale for all features, or ard, one per feature "
                  "(with --gp-fit likelihood)")
      ->check(CLI::IsMember({"ard", "rbf"}))
      ->capture_default_str();
  cmd->add_option("--targets", args->targets,
                  "The columns to compensate, comma-separated: gyro_dph and further gyro axes the "
                  "recordings carry (gyro_y_dph, ... from fogdrift import), accelerometers "
                  "(accel_x_g, accel_NAME_g: their bias), scale-factor channels (sf_NAME_ppm); "
                  "several give one model file with a model per axis, each with its own search "
                  "and guard (docs/logs.md, \"Other targets\")")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print the training summary as JSON");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->callback([args] { run(*args); });
}

}  // namespace fogdrift::app
