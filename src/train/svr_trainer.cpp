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
  Record r;
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
      r.boxes.push_back(t.space);
      r.tuning = tune::tune_svr(c.data, t);
      r.box_edges = tune::box_edges(r.tuning, t.space);
      if (r.box_edges.empty() || round == options.auto_box_rounds) break;
      const tune::SearchSpace wider = tune::widened(t.space, r.box_edges);
      if (wider == t.space) break;  // at the limits already
      t.space = wider;
    }
    params = r.tuning.best;
    s.fitness_value = r.tuning.best_fitness;
    out.population = t.optimizer.run.population;
    out.iterations = t.optimizer.run.iterations;
    r.population = t.optimizer.run.population;
    s.record = TrainerRecord(std::move(r));
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

nlohmann::ordered_json to_json(const SvrTrainer::Record& r) {
  const tune::TuneSummary& u = r.tuning;
  nlohmann::ordered_json rescored = nlohmann::ordered_json::array();
  for (const tune::Candidate& c : u.rescored)
    rescored.push_back({{"C", c.params.c}, {"sigma", c.params.kernel.sigma()}, {"rmse", c.loss}});
  nlohmann::ordered_json finished = nlohmann::ordered_json::array();
  for (const tune::Candidate& c : u.finished) {
    double seen = c.loss;
    for (const tune::Candidate& h : u.history)
      if (h.params.c == c.params.c && h.params.kernel == c.params.kernel &&
          h.params.epsilon == c.params.epsilon)
        seen = h.loss;
    finished.push_back({{"C", c.params.c},
                        {"sigma", c.params.kernel.sigma()},
                        {"capped_rmse", seen},
                        {"rmse", c.loss}});
  }
  nlohmann::ordered_json log = nlohmann::ordered_json::array();
  for (const auto& i : u.optimizer.log) log.push_back(i.best_fitness);
  nlohmann::ordered_json j;
  j["search"] = {{"optimizer", opt::to_string(u.optimizer.algorithm)},
                 {"population", r.population},
                 {"iterations", u.optimizer.iterations},
                 {"status", opt::to_string(u.optimizer.status)},
                 {"evaluations", u.optimizer.evaluations},
                 {"candidates", u.candidates},
                 {"repeats", u.repeats},
                 {"near_repeats", u.near_repeats},
                 {"fits", u.fits},
                 {"raced", u.raced},
                 {"capped_fits", u.capped_fits},
                 {"finished", finished},
                 {"row_stride", u.stride},
                 {"largest_fold_rows", u.largest_fold_rows},
                 {"rescored", rescored},
                 {"initial_best_rmse", u.optimizer.initial_best_fitness},
                 {"seconds", u.seconds},
                 {"best_rmse_per_iteration", log}};
  nlohmann::ordered_json edges = nlohmann::ordered_json::array();
  for (const auto& e : r.box_edges)
    edges.push_back({{"parameter", e.parameter},
                     {"edge", e.upper ? "upper" : "lower"},
                     {"value", e.value},
                     {"box", {e.low, e.high}},
                     {"improvement", e.improvement}});
  j["box_edges"] = edges;
  nlohmann::ordered_json boxes = nlohmann::ordered_json::array();
  for (const auto& b : r.boxes)
    boxes.push_back({{"c", {b.c_min, b.c_max}}, {"sigma", {b.sigma_min, b.sigma_max}}});
  j["boxes_searched"] = boxes;
  j["fits"] = u.fits;
  return j;
}

std::vector<std::string> box_edge_warnings(
    const TrainSummary& s, bool auto_box,
    const std::function<std::string(const std::string&)>& name_of) {
  std::vector<std::string> out;
  const SvrTrainer::Record* r = s.record.get<SvrTrainer::Record>();
  if (r == nullptr) return out;
  for (const auto& e : r->box_edges) {
    const std::string what = e.parameter == "C" ? name_of(e.upper ? "c_max" : "c_min")
                             : e.parameter == "sigma"
                                 ? name_of(e.upper ? "sigma_max" : "sigma_min")
                                 : fmt::format("the ε bounds of {}", name_of("search_epsilon"));
    // With auto-box the box was widened already: say how often, and only name what is left.
    const std::size_t widenings = r->boxes.empty() ? 0 : r->boxes.size() - 1;
    const std::string advice =
        !auto_box ? fmt::format("a wider box may do better: {} or {}", what, name_of("auto_box"))
        : !r->boxes.empty() && tune::widened(r->boxes.back(), {e}) == r->boxes.back()
            ? fmt::format(
                  "{} widened it {} times, to fogdrift's limit for {}: the data do not "
                  "bound it",
                  name_of("auto_box"), widenings, e.parameter)
            : fmt::format("{} widened it {} times, its most; a wider box may still do better: {}",
                          name_of("auto_box"), widenings, what);
    out.push_back(fmt::format(
        "{} = {:.6g} is at the {} edge of its box [{:.6g}, {:.6g}]; the fitness there is {:.1f} % "
        "better than further inside; {}",
        e.parameter, e.value, e.upper ? "upper" : "lower", e.low, e.high, 100.0 * e.improvement,
        advice));
  }
  return out;
}

}  // namespace fogdrift
