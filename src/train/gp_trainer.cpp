#include "fogdrift/train/gp_trainer.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "fogdrift/base/error.hpp"
#include "fogdrift/train/gp_search.hpp"

namespace fogdrift {

OptionTable<GpTrainer::Options> GpTrainer::option_table() {
  OptionTable<Options> t;
  t.push_back(whole_option<Options>(
      {"gp_points",
       "--gp-points",
       {},
       "",
       between(10, 4000),
       "gp: training rows the Gaussian process keeps, evenly spaced; its time grows "
       "as the cube, its C header's work per sample linearly",
       {}},
      [](auto& o) -> auto& { return o.max_points; }));
  t.push_back({{"gp_fit",
                "--gp-fit",
                OptionType::choice,
                "",
                gp_selection_names(),
                "gp: how the hyperparameters are chosen: cv, the length scale and the noise "
                "ratio by the search over the folds of {cv}, as the SVR's C and σ ({population}, "
                "{iterations} and {seed} as above); likelihood, all of them by the marginal "
                "likelihood, which favours short length scales on start-up data (docs/gp.md)",
                {}},
               [](const Options& o) { return std::string(to_string(o.selection)); },
               [](Options& o, const std::string& text) {
                 o.selection = parse_gp_selection(text, "gp_fit");
               }});
  t.push_back({{"gp_kernel",
                "--gp-kernel",
                OptionType::choice,
                "",
                "rbf, ard",
                "gp: rbf, one length scale for all features, or ard, one per feature (with "
                "{gp_fit} likelihood)",
                {}},
               [](const Options& o) { return std::string(o.ard ? "ard" : "rbf"); },
               [](Options& o, const std::string& text) {
                 if (text != "rbf" && text != "ard")
                   throw OptionError("gp_kernel", fmt::format("'{}' is not rbf or ard", text));
                 o.ard = text == "ard";
               }});
  return t;
}

Search GpTrainer::search(Search requested, const TrainOptions& options) {
  const GpOptions& gp = options.trainers.get<Options>();
  if (gp.selection == GpSelection::likelihood) {
    if (requested != Search::own)
      throw OptionError("search", fmt::format("'{}': {{gp_fit}} likelihood chooses by the "
                                              "likelihood's gradient, not by a search",
                                              to_string(requested)));
    return Search::own;
  }
  if (requested == Search::none)
    throw OptionError("search",
                      "gp's cv fit needs a search (ssa, pso or gwo), or {gp_fit} likelihood");
  return requested == Search::own ? Search::ssa : requested;
}

void GpTrainer::validate(const TrainOptions& options) {
  const GpOptions& gp = options.trainers.get<Options>();
  fogdrift::validate(gp);
  if (gp.selection == GpSelection::cv) opt::validate(options.tune.optimizer.run);
}

Trained GpTrainer::train(const TrainContext& c) {
  const TrainOptions& options = c.options;
  const GpOptions& gp = options.trainers.get<Options>();
  Trained out;
  TrainSummary& s = out.summary;
  out.held_folds = tune::grouped_folds(c.data, options.tune.cv);
  const std::vector<tune::ScaledSplit> splits = tune::scale_splits(c.data, out.held_folds);
  GpFit fit;
  if (gp.selection == GpSelection::cv) {
    fit = search_gp(splits, c.full.train, gp, options.tune.optimizer, options.tune.pool).fit;
    out.population = options.tune.optimizer.run.population;
    out.iterations = options.tune.optimizer.run.iterations;
    // The model file says a search other than the default; ssa-svr's is in its name.
    if (options.method.search != Search::ssa) out.search = to_string(options.method.search);
  } else {
    fit = train_gp(c.full.train, gp);
  }
  out.regressor = fit.posterior.gp;
  const GpHyper hyper = fit.posterior.gp.hyper;
  // The GP of each fold, fitted once: its held-out predictions give the fitness here and the
  // held-out report (which splits the same folds the same way).
  auto predictions = std::make_shared<tune::FoldPredictions>(
      tune::fold_predictions(splits, [&](const Data& train) {
        return fit_gp(train.subset(gp_rows(train.rows, gp.max_points)), hyper).gp;
      }));
  out.held_predict = [predictions](const tune::ScaledSplit&, std::size_t fold) {
    return (*predictions)[fold];
  };
  s.fitness = "cv";
  s.fitness_value = tune::pooled_rmse(splits, *predictions);
  out.cv = describe_folds(out.held_folds);
  out.held_description = out.cv;
  s.hyperparameters = {{"signal_variance", hyper.signal_variance},
                       {"noise_variance", hyper.noise_variance},
                       {"points", static_cast<double>(fit.summary.points)}};
  if (gp.ard) {
    for (std::size_t k = 0; k < hyper.length_scale.size(); ++k)
      s.hyperparameters.emplace_back("length_scale:" + c.data.feature_names[k],
                                     hyper.length_scale[k]);
  } else {
    s.hyperparameters.emplace_back("length_scale", hyper.length_scale[0]);
  }
  s.record = TrainerRecord(Record{fit.summary});
  return out;
}

nlohmann::ordered_json to_json(const GpTrainer::Record& record) {
  const GpSummary& g = record.fit;
  nlohmann::ordered_json j;
  j["gp"] = {{"points", g.points},         {"log_likelihood", g.log_likelihood},
             {"iterations", g.iterations}, {"evaluations", g.evaluations},
             {"fold_fits", g.fold_fits},   {"raced", g.raced},
             {"converged", g.converged}};
  return j;
}

}  // namespace fogdrift
