#include "fogdrift/tune/train.hpp"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/version.hpp"
#include "fogdrift/tune/gp_search.hpp"

namespace fogdrift {
namespace {

std::vector<std::size_t> all_rows(const Dataset& data) {
  std::vector<std::size_t> rows(data.rows);
  std::iota(rows.begin(), rows.end(), 0);
  return rows;
}

std::string describe_folds(const std::vector<tune::Fold>& folds) {
  const std::string& first = folds.front().name;
  const char* kind = first.starts_with("repetition")     ? "leave one repetition out"
                     : first.starts_with("temperatures") ? "whole initial temperatures"
                                                         : "whole recordings";
  return fmt::format("{} ({} folds)", kind, folds.size());
}

opt::Algorithm algorithm_of(Method m) {
  return m == Method::pso_svr ? opt::Algorithm::pso
                              : (m == Method::gwo_svr ? opt::Algorithm::gwo : opt::Algorithm::ssa);
}

constexpr std::array<EnumName<Search>, 5> kSearchNames = {{{Search::own, "auto"},
                                                           {Search::none, "none"},
                                                           {Search::ssa, "ssa"},
                                                           {Search::pso, "pso"},
                                                           {Search::gwo, "gwo"}}};

/// The SVR method a search makes of svr, and the optimizer of a search.
Method svr_method_of(Search s) {
  return s == Search::pso ? Method::pso_svr
                          : (s == Search::gwo ? Method::gwo_svr : Method::ssa_svr);
}
opt::Algorithm algorithm_of(Search s) {
  return s == Search::pso ? opt::Algorithm::pso
                          : (s == Search::gwo ? opt::Algorithm::gwo : opt::Algorithm::ssa);
}

}  // namespace

std::string_view to_string(Search search) {
  return name_in(kSearchNames, search);
}

Search parse_search(std::string_view text, std::string_view option) {
  return parse_in(kSearchNames, text, option, "a search");
}

std::string search_names() {
  return names_in(kSearchNames);
}

TrainOptions resolved(const TrainOptions& options) {
  TrainOptions r = options;
  r.search = Search::own;
  const Search s = options.search;
  if (s == Search::own) return r;
  const std::string method = to_string(options.method);
  const std::string search(to_string(s));
  switch (options.method) {
    case Method::svr:
      if (s != Search::none) r.method = svr_method_of(s);
      return r;
    case Method::ssa_svr:
    case Method::pso_svr:
    case Method::gwo_svr:
      if (s == Search::none || svr_method_of(s) != options.method)
        throw OptionError(
            "search", fmt::format("'{}' contradicts {{method}} {}, which is svr searched by {}; "
                                  "give {{method}} svr with {{search}} {}",
                                  search, method, method.substr(0, 3), search));
      return r;
    case Method::gp:
      if (options.gp.selection == GpSelection::likelihood)
        throw OptionError("search", fmt::format("'{}': {{gp_fit}} likelihood chooses by the "
                                                "likelihood's gradient, not by a search",
                                                search));
      if (s == Search::none)
        throw OptionError("search",
                          "gp's cv fit needs a search (ssa, pso or gwo), or {gp_fit} "
                          "likelihood");
      r.tune.optimizer.algorithm = algorithm_of(s);
      return r;
    case Method::bp:
    case Method::poly:
      if (s != Search::none)
        throw OptionError("search", fmt::format("{} has no search: {} (auto or none)", method,
                                                method == "bp" ? "it trains by Adam with early "
                                                                 "stopping"
                                                               : "cross-validation picks its "
                                                                 "degree"));
      return r;
  }
  return r;
}

void validate(const TrainOptions& given) {
  const TrainOptions options = resolved(given);
  switch (options.method) {
    case Method::ssa_svr:
    case Method::pso_svr:
    case Method::gwo_svr: {
      tune::TuneOptions t = options.tune;
      t.optimizer.algorithm = algorithm_of(options.method);
      tune::validate(t);
      break;
    }
    case Method::bp:
      validate(options.mlp);
      break;
    case Method::poly:
      if (options.poly_max_degree < 1 || options.poly_max_degree > 6)
        throw OptionError("degree", fmt::format("{} is outside 1 … 6", options.poly_max_degree));
      break;
    case Method::gp:
      validate(options.gp);
      if (options.gp.selection == GpSelection::cv) opt::validate(options.tune.optimizer.run);
      break;
    case Method::svr:
      break;
  }
}

TrainResult train(const Dataset& data, const DatasetOptions& dataset, const TrainOptions& given) {
  const auto start = std::chrono::steady_clock::now();
  const TrainOptions options = resolved(given);
  validate(options);
  if (data.rows == 0) throw OptionError("data", "there are no training rows");
  TrainResult out;
  TrainSummary& s = out.summary;
  s.method = options.method;
  s.rows = data.rows;
  CompensationModel& m = out.model;
  m.dataset = dataset;
  m.feature_names = data.feature_names;
  Provenance& p = m.provenance;
  p.method = options.method;
  // A search that is not the method's own (gp searched by pso) is said; svr's is its method.
  if (options.method == Method::gp && options.gp.selection == GpSelection::cv &&
      options.tune.optimizer.algorithm != opt::Algorithm::ssa)
    p.search = opt::to_string(options.tune.optimizer.algorithm);
  p.seed = options.tune.optimizer.run.seed;
  p.training_rows = data.rows;
  p.fogdrift_version = kVersion;

  // Scalers of all training rows, for the final fit of every method.
  const std::vector<std::size_t> rows = all_rows(data);
  const tune::ScaledSplit full = tune::scale_split(data, rows, {});
  m.x_scaler = full.x_scaler;
  m.y_scaler = full.y_scaler;

  // The folds the held-out report scores the model on, and how the model is refitted on one.
  std::vector<tune::Fold> held_folds;
  FoldPredictor held_predict;  // the chosen model refitted on a fold (held_out.hpp)

  switch (options.method) {
    case Method::ssa_svr:
    case Method::pso_svr:
    case Method::gwo_svr:
    case Method::svr: {
      svr::Params params;
      tune::TuneOptions t = options.tune;
      if (options.method == Method::svr) {
        if (options.svr_params)
          params = *options.svr_params;
        else
          params.kernel = svr::Kernel::rbf_gamma(1.0 / static_cast<double>(data.cols()));
        params.tolerance = t.tolerance;
        params.cache_mb = t.cache_mb;  // the user's kernel cache (--cache-mb), as the searches use
        s.fitness_value = tune::svr_loss(data, params, t);
      } else {
        t.optimizer.algorithm = algorithm_of(options.method);  // tune_svr validates with it
        for (std::size_t round = 0;; ++round) {
          s.boxes.push_back(t.space);
          s.tuning = tune::tune_svr(data, t);
          s.box_edges = tune::box_edges(s.tuning, t.space);
          if (s.box_edges.empty() || round == options.auto_box_rounds) break;
          const tune::SearchSpace wider = tune::widened(t.space, s.box_edges);
          if (wider == t.space) break;  // at the limits already
          t.space = wider;
        }
        params = s.tuning.best;
        s.fitness_value = s.tuning.best_fitness;
        p.population = t.optimizer.run.population;
        p.iterations = t.optimizer.run.iterations;
      }
      s.fitness = tune::to_string(t.fitness);
      if (t.fitness == tune::Fitness::cv || options.held_out) {
        // The paper's training fitness holds nothing out: its model is scored on the folds too,
        // and data that cannot be split say so instead of failing.
        try {
          held_folds = tune::grouped_folds(data, t.cv);
        } catch (const OptionError& e) {
          if (t.fitness == tune::Fitness::cv) throw;
          s.held_out_missing = fmt::format("no held-out rows: {}", e.what());
        }
      }
      if (t.fitness == tune::Fitness::cv) p.cv = describe_folds(held_folds);
      if (options.held_out) {
        held_predict = [params](const tune::ScaledSplit& split, std::size_t) {
          svr::TrainingSet set(split.train);
          return svr::fit(set, params).model.predict(split.test);
        };
      }
      svr::TrainingSet set(full.train);
      m.regressor = svr::fit(set, params).model;
      s.hyperparameters = {{"C", params.c},
                           {"sigma", params.kernel.sigma()},
                           {"gamma", params.kernel.gamma},
                           {"epsilon", params.epsilon}};
      break;
    }
    case Method::bp: {
      // Early stopping on the held-out recordings of the last grouped fold. BP is not refitted
      // after it, so what the fold holds out is never trained on: it must be like the rest. Whole
      // temperatures, or a repetition that is a start-up condition of its own (a protocol of
      // mixed start-ups), would stop it on data it cannot fit (measured: best epoch 2). So
      // unless repetition or recording folds are asked for, it holds out a third of the
      // recordings, dealt across temperatures and repetitions.
      tune::CvOptions stop = options.tune.cv;
      if (stop.scheme == tune::CvScheme::temperature || stop.scheme == tune::CvScheme::automatic)
        stop = {tune::CvScheme::recording, 3};
      const auto folds = tune::grouped_folds(data, stop);
      const tune::Fold& f = folds.back();
      const tune::ScaledSplit split = tune::scale_split(data, f.train_rows, f.test_rows);
      MlpOptions mo = options.mlp;
      mo.seed = options.tune.optimizer.run.seed;
      const MlpFit fit = fit_mlp(split.train, split.test, mo);
      m.x_scaler = split.x_scaler;
      m.y_scaler = split.y_scaler;
      m.regressor = fit.model;
      s.mlp = fit.summary;
      s.fitness = "validation";
      s.fitness_value = fit.summary.validation_rmse;
      p.cv = fmt::format("early stopping on {}", f.name);
      held_folds = {f};
      const Mlp net = fit.model;  // trained on this fold's rows, with its scalers
      held_predict = [net](const tune::ScaledSplit& split, std::size_t) {
        std::vector<double> out(split.test.rows);
        for (std::size_t r = 0; r < split.test.rows; ++r) out[r] = net.predict(split.test.row(r));
        return out;
      };
      s.hyperparameters = {{"hidden", static_cast<double>(mo.hidden)},
                           {"learning_rate", mo.learning_rate},
                           {"epochs", static_cast<double>(fit.summary.best_epoch)}};
      break;
    }
    case Method::poly: {
      const auto folds = tune::grouped_folds(data, options.tune.cv);
      std::vector<tune::ScaledSplit> splits;
      for (const auto& f : folds)
        splits.push_back(tune::scale_split(data, f.train_rows, f.test_rows));
      // Degrees with more terms than a fold has training rows cannot be fitted: the search
      // stops below them.
      std::size_t min_rows = data.rows;
      for (const auto& sp : splits) min_rows = std::min(min_rows, sp.train.rows);
      std::size_t best = 1;
      for (std::size_t degree = 1; degree <= options.poly_max_degree; ++degree) {
        if (degree > 1 && monomials(data.cols(), degree).size() / data.cols() > min_rows) break;
        double sse = 0;
        std::size_t n = 0;
        for (const auto& sp : splits) {
          const Poly poly = fit_poly(sp.train, degree);
          for (std::size_t r = 0; r < sp.test.rows; ++r) {
            const double e = poly.predict(sp.test.row(r)) - sp.test.y[r];
            sse += e * e;
          }
          n += sp.test.rows;
        }
        s.poly_cv_rmse.push_back(std::sqrt(sse / static_cast<double>(n)));
        if (s.poly_cv_rmse.back() < s.poly_cv_rmse[best - 1]) best = degree;
      }
      m.regressor = fit_poly(full.train, best);
      s.fitness = "cv";
      s.fitness_value = s.poly_cv_rmse[best - 1];
      p.cv = describe_folds(folds);
      held_folds = folds;
      held_predict = [best](const tune::ScaledSplit& split, std::size_t) {
        const Poly poly = fit_poly(split.train, best);
        std::vector<double> out(split.test.rows);
        for (std::size_t r = 0; r < split.test.rows; ++r) out[r] = poly.predict(split.test.row(r));
        return out;
      };
      s.hyperparameters = {{"degree", static_cast<double>(best)}};
      break;
    }
    case Method::gp: {
      // Hyperparameters by the grouped folds through the search (gp_search.hpp) or by the
      // marginal likelihood of the rows kept (gp.hpp); the fitness is the RMSE over the folds
      // of a GP with those hyperparameters fitted on each fold's training rows, as the held-out
      // report scores it.
      held_folds = tune::grouped_folds(data, options.tune.cv);
      std::vector<tune::ScaledSplit> splits;
      for (const auto& f : held_folds)
        splits.push_back(tune::scale_split(data, f.train_rows, f.test_rows));
      GpFit fit;
      if (options.gp.selection == GpSelection::cv) {
        fit = search_gp(splits, full.train, options.gp, options.tune.optimizer, options.tune.pool)
                  .fit;
        p.population = options.tune.optimizer.run.population;
        p.iterations = options.tune.optimizer.run.iterations;
      } else {
        fit = train_gp(full.train, options.gp);
      }
      m.regressor = fit.posterior.gp;
      s.gp = fit.summary;
      const GpHyper hyper = fit.posterior.gp.hyper;
      // The GP of each fold, fitted once: its held-out predictions give the fitness here and the
      // held-out report below (which splits the same folds the same way).
      auto predictions = std::make_shared<std::vector<std::vector<double>>>();
      double sse = 0;
      std::size_t n = 0;
      for (const tune::ScaledSplit& split : splits) {
        const Gp gp =
            fit_gp(split.train.subset(gp_rows(split.train.rows, options.gp.max_points)), hyper).gp;
        std::vector<double>& predicted = predictions->emplace_back(split.test.rows);
        for (std::size_t r = 0; r < split.test.rows; ++r) {
          predicted[r] = gp.predict(split.test.row(r));
          sse += (predicted[r] - split.test.y[r]) * (predicted[r] - split.test.y[r]);
        }
        n += split.test.rows;
      }
      held_predict = [predictions](const tune::ScaledSplit&, std::size_t fold) {
        return (*predictions)[fold];
      };
      s.fitness = "cv";
      s.fitness_value = std::sqrt(sse / static_cast<double>(n));
      p.cv = describe_folds(held_folds);
      s.hyperparameters = {{"signal_variance", hyper.signal_variance},
                           {"noise_variance", hyper.noise_variance},
                           {"points", static_cast<double>(fit.summary.points)}};
      if (options.gp.ard) {
        for (std::size_t k = 0; k < hyper.length_scale.size(); ++k)
          s.hyperparameters.emplace_back("length_scale:" + data.feature_names[k],
                                         hyper.length_scale[k]);
      } else {
        s.hyperparameters.emplace_back("length_scale", hyper.length_scale[0]);
      }
      break;
    }
  }
  // The guard's region: every training row, standardised as the regressor sees it, its unit
  // set by the spacing of the calibration temperatures (guard.hpp).
  std::vector<double> z = data.x;
  m.x_scaler.apply(z);
  std::vector<double> temps;
  for (const GroupInfo& g : data.groups) temps.push_back(g.initial_temp_degc);
  std::vector<std::size_t> labels(data.rows), conditions(data.rows);
  for (std::size_t i = 0; i < data.rows; ++i) {
    conditions[i] = static_cast<std::size_t>(data.groups[data.group[i]].repetition);
    std::size_t k = 0;
    while (temps[k] != temps[data.group[i]]) ++k;  // the first group of the same temperature
    labels[i] = k;
  }
  m.guard = NoveltyGuard::fit(z, data.cols(), labels, conditions, options.guard);
  m.guard.set_warmup_inputs(m.dataset.features.rate_inputs());
  if (options.held_out && !held_folds.empty()) {
    const std::string how =
        options.method == Method::bp ? held_folds.front().name : describe_folds(held_folds);
    s.held_out = held_out_report(data, held_folds, held_predict, how);
  }
  p.fitness = s.fitness;
  p.fitness_value = s.fitness_value;
  p.hyperparameters = s.hyperparameters;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::vector<std::string> box_edge_warnings(
    const TrainSummary& s, bool auto_box,
    const std::function<std::string(const std::string&)>& name_of) {
  std::vector<std::string> out;
  for (const auto& e : s.box_edges) {
    const std::string what = e.parameter == "C" ? name_of(e.upper ? "c_max" : "c_min")
                             : e.parameter == "sigma"
                                 ? name_of(e.upper ? "sigma_max" : "sigma_min")
                                 : fmt::format("the ε bounds of {}", name_of("search_epsilon"));
    // With auto-box the box was widened already: say how often, and only name what is left.
    const std::size_t widenings = s.boxes.empty() ? 0 : s.boxes.size() - 1;
    const std::string advice =
        !auto_box ? fmt::format("a wider box may do better: {} or {}", what, name_of("auto_box"))
        : !s.boxes.empty() && tune::widened(s.boxes.back(), {e}) == s.boxes.back()
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
