#include "fogdrift/train/svr_trainer.hpp"

#include <fmt/format.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

Search SvrTrainer::search(Search requested, const TrainOptions&) {
  return requested == Search::none ? Search::own : requested;
}

void SvrTrainer::validate(const TrainOptions& options) {
  if (is_optimizer(options.method.search)) tune::validate(options.tune);
}

Trained SvrTrainer::train(const TrainContext& c) {
  const TrainOptions& options = c.options;
  Trained out;
  TrainSummary& s = out.summary;
  svr::Params params;
  tune::TuneOptions t = options.tune;
  if (!is_optimizer(options.method.search)) {
    if (const auto& given = options.trainers.get<Options>().params)
      params = *given;
    else
      params.kernel = svr::Kernel::rbf_gamma(1.0 / static_cast<double>(c.data.cols()));
    params.tolerance = t.tolerance;
    params.cache_mb = t.cache_mb;  // the user's kernel cache (--cache-mb), as the searches use
    s.fitness_value = tune::svr_loss(c.data, params, t);
  } else {
    for (std::size_t round = 0;; ++round) {
      s.boxes.push_back(t.space);
      s.tuning = tune::tune_svr(c.data, t);
      s.box_edges = tune::box_edges(s.tuning, t.space);
      if (s.box_edges.empty() || round == options.auto_box_rounds) break;
      const tune::SearchSpace wider = tune::widened(t.space, s.box_edges);
      if (wider == t.space) break;  // at the limits already
      t.space = wider;
    }
    params = s.tuning.best;
    s.fitness_value = s.tuning.best_fitness;
    out.population = t.optimizer.run.population;
    out.iterations = t.optimizer.run.iterations;
    const tune::TuneSummary& u = s.tuning;
    nlohmann::ordered_json rescored = nlohmann::ordered_json::array();
    for (const tune::Candidate& r : u.rescored)
      rescored.push_back({{"C", r.params.c}, {"sigma", r.params.kernel.sigma()}, {"rmse", r.loss}});
    nlohmann::ordered_json log = nlohmann::ordered_json::array();
    for (const auto& r : u.optimizer.log) log.push_back(r.best_fitness);
    s.record["search"] = {{"optimizer", opt::to_string(u.optimizer.algorithm)},
                          {"population", t.optimizer.run.population},
                          {"iterations", u.optimizer.iterations},
                          {"status", opt::to_string(u.optimizer.status)},
                          {"evaluations", u.optimizer.evaluations},
                          {"candidates", u.candidates},
                          {"repeats", u.repeats},
                          {"fits", u.fits},
                          {"raced", u.raced},
                          {"row_stride", u.stride},
                          {"rescored", rescored},
                          {"initial_best_rmse", u.optimizer.initial_best_fitness},
                          {"seconds", u.seconds},
                          {"best_rmse_per_iteration", log}};
  }
  s.fitness = tune::to_string(t.fitness);
  if (t.fitness == tune::Fitness::cv || options.held_out) {
    // The paper's training fitness holds nothing out: its model is scored on the folds too,
    // and data that cannot be split say so instead of failing.
    try {
      out.held_folds = tune::grouped_folds(c.data, t.cv);
      out.held_description = describe_folds(out.held_folds);
    } catch (const OptionError& e) {
      if (t.fitness == tune::Fitness::cv) throw;
      s.held_out_missing = fmt::format("no held-out rows: {}", e.what());
    }
  }
  if (t.fitness == tune::Fitness::cv) out.cv = out.held_description;
  out.held_predict = [params](const tune::ScaledSplit& split, std::size_t) {
    svr::TrainingSet set(split.train);
    return svr::fit(set, params).model.predict(split.test);
  };
  svr::TrainingSet set(c.full.train);
  out.regressor = svr::fit(set, params).model;
  s.hyperparameters = {{"C", params.c},
                       {"sigma", params.kernel.sigma()},
                       {"gamma", params.kernel.gamma},
                       {"epsilon", params.epsilon}};
  return out;
}

}  // namespace fogdrift
