// Training a compensation model by any of the paper's methods (docs/method.md §2, §3):
//   ssa-svr, pso-svr, gwo-svr  ε-SVR with C and σ tuned by that optimizer (tune.hpp), then
//                              refitted on all training rows;
//   svr                        LIBSVM's defaults on standardised data: C = 1, γ = 1/features,
//                              ε = 0.1;
//   bp                         one-hidden-layer tanh network (mlp.hpp), early-stopped on the
//                              held-out recordings of the last grouped fold; not refitted, so
//                              unless repetition or recording folds are asked for it holds out
//                              a third of the recordings dealt across temperatures and
//                              repetitions, which keeps every temperature and start-up
//                              condition in training;
//   poly                       polynomial in the features, degree 1 … max chosen by grouped CV;
//   gp                         Gaussian process, hyperparameters by marginal likelihood on at
//                              most gp.max_points evenly spaced rows (gp.hpp).
// Every method reports a fitness on the standardised target: the tuner's (cv or train) for the
// SVRs, the validation RMSE for BP, the CV RMSE of the chosen degree for the polynomial, and for
// the GP the CV RMSE of its hyperparameters refitted on each fold.
#pragma once

#include <optional>

#include "fogdrift/model/gp.hpp"
#include "fogdrift/model/mlp.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/tune/held_out.hpp"
#include "fogdrift/tune/tune.hpp"

namespace fogdrift {

/// How a regressor's hyperparameters are searched (train --search): a method is a regressor and
/// a search, and ssa-svr is svr searched by ssa.
enum class Search {
  own,   ///< the method's own: ssa for ssa-svr and gp, pso for pso-svr, gwo for gwo-svr, none else
  none,  ///< none: svr with LIBSVM's defaults; bp, poly and gp's likelihood fit their own way
  ssa,   ///< sparrow search over the grouped folds (opt/ssa.hpp)
  pso,   ///< particle swarm
  gwo,   ///< grey wolf
};
/// "auto", "none", "ssa", "pso", "gwo".
std::string_view to_string(Search search);
Search parse_search(std::string_view text, std::string_view option = "search");
/// "auto, none, ssa, pso, gwo".
std::string search_names();

struct TrainOptions {
  Method method = Method::ssa_svr;
  /// With method svr, ssa/pso/gwo make it ssa-svr/pso-svr/gwo-svr (resolved()); with gp's cv
  /// fit, the optimizer of its search; own: the method's own.
  Search search = Search::own;
  tune::TuneOptions tune;           ///< fitness, folds, search box, optimizer budget, seed, pool
  MlpOptions mlp;                   ///< BP settings; its seed is set from tune.optimizer.run.seed
  std::size_t poly_max_degree = 3;  ///< highest polynomial degree tried, 1 … 6
  GpOptions gp;                     ///< gp: rows kept and the likelihood search
  /// svr: fit with these instead of LIBSVM's defaults (a study refitting a tuned SVR on other
  /// rows); the tolerance is tune.tolerance.
  std::optional<svr::Params> svr_params;
  /// The novelty guard fitted to the training rows and stored in the model (guard.hpp).
  GuardSettings guard;
  /// Tuned SVRs: when the best C, σ or ε lies on an edge of its box, widen the box by a decade
  /// there and search again, at most this many times (0: never; tune::box_edges()).
  std::size_t auto_box_rounds = 0;
  /// The rounds `train --auto-box` and Python's `auto_box=True` ask for.
  static constexpr std::size_t kAutoBoxRounds = 3;
  /// Score the model and the baselines on held-out rows (TrainSummary::held_out).
  bool held_out = true;
};

struct TrainSummary {
  Method method = Method::ssa_svr;
  std::string fitness;       ///< "cv", "train" or "validation"
  double fitness_value = 0;  ///< RMSE on the standardised target
  std::vector<std::pair<std::string, double>> hyperparameters;
  tune::TuneSummary tuning;  ///< SVR methods with a search (the last, with auto-box)
  /// Tuned SVRs: the boxes searched, in order (more than one with auto-box), and the edges the
  /// last search's best lies on.
  std::vector<tune::SearchSpace> boxes;
  std::vector<tune::BoxEdge> box_edges;
  MlpSummary mlp;                    ///< bp
  std::vector<double> poly_cv_rmse;  ///< poly: CV RMSE of degree 1, 2, …
  GpSummary gp;                      ///< gp: the likelihood search
  /// How sure train is (held_out.hpp): the model's held-out RMSE beside the baselines' on the
  /// same folds, and the share it is expected to remove. SVRs searched on the training loss are
  /// scored on the grouped folds for it (one more fit per fold); absent, with the reason in
  /// held_out_missing, when the data cannot be split into folds.
  std::optional<HeldOutReport> held_out;
  std::string held_out_missing;
  std::size_t rows = 0;
  double seconds = 0;
};

struct TrainResult {
  CompensationModel model;
  TrainSummary summary;
};

/// The options with method and search made one: svr with a search is that search's SVR method,
/// gp's optimizer is the search's, and search is then own. Throws OptionError("search") for a
/// method and a search that contradict (pso-svr with ssa) or a method with no such search (bp
/// with pso, svr-less none for gp's cv fit).
TrainOptions resolved(const TrainOptions& options);

/// Checks what can be checked without data: the search's box, budget and folds for a tuned SVR,
/// the network's for bp, the degree for poly. Throws OptionError naming the field (train_fleet
/// checks a line's options once before any unit runs).
void validate(const TrainOptions& options);

/// Trains on every row of `data`, built with `dataset` (recorded in the model).
TrainResult train(const Dataset& data, const DatasetOptions& dataset, const TrainOptions& options);

/// One warning for each best value on the edge of its box (summary.box_edges): the box, not the
/// data, may have stopped the search. The advice names what the user sets, in their own words:
/// `name_of` turns a field (c_min, c_max, sigma_min, sigma_max, search_epsilon, auto_box) into a
/// flag (--c-max) or a keyword (c_max); `auto_box` says whether the box was widened already.
std::vector<std::string> box_edge_warnings(
    const TrainSummary& summary, bool auto_box,
    const std::function<std::string(const std::string&)>& name_of);

}  // namespace fogdrift
