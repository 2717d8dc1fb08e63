// Training a compensation model (docs/method.md §2, §3): the method's trainer (trainer.hpp,
// the registry in trainers.hpp) fits its regressor and reports a fitness on the standardised
// target; what every method shares is here: method and search made one, the scalers of all
// training rows, the novelty guard over them, the held-out report and the provenance. The
// regressor-specific options are each trainer's own (TrainOptions::trainers), declared in its
// own option table; the search's box and budget (tune) are shared with fogdrift paper.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>

#include "fogdrift/model/model.hpp"
#include "fogdrift/train/held_out.hpp"
#include "fogdrift/train/method.hpp"
#include "fogdrift/train/trainer_options.hpp"
#include "fogdrift/train/trainer_record.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift {

/// Iterations without a 0.1 % gain after which train's search stops (opt::RunOptions; docs/
/// tuning.md, "A search that stops when it stops learning"). fogdrift paper keeps the paper's
/// fixed budget.
inline constexpr std::size_t kTrainStallIterations = 10;
/// The fewest training rows a fold is thinned to for train's search, and the fewest a fold must
/// hold to be thinned at all (tune::TuneOptions::search_rows, thin_from_rows; docs/tuning.md, "A
/// search on fewer rows"): the seven-sweep protocol's 8,640 a fold are searched on every seventh
/// row, the five-sweep protocol's 5,760 on every fourth, and the paper's 3 × 11 start-ups (at
/// most 4,320) and the four-start-up-set-point protocol's (3,060) on all their rows. fogdrift
/// paper searches every row, as the paper did.
inline constexpr std::size_t kTrainSearchRows = 1200;
inline constexpr std::size_t kTrainThinFromRows = 5000;
/// The SMO iterations each of train's search fits may take per training row of the largest fold
/// (tune::TuneOptions::smo_iterations_per_row; docs/tuning.md, "A cap on the search's fits"):
/// it stops the slow fits of the over-fitting corner, and left the population study's shares
/// within a point. fogdrift paper fits every candidate to the end, as the paper did.
inline constexpr std::size_t kTrainSmoIterationsPerRow = 20;
/// Decades of C, σ and ε within which train's search takes two candidates for one (tune::
/// TuneOptions::candidate_resolution; docs/tuning.md, "One candidate within a resolution"): SSA's
/// scroungers crowd the best, where a loss is known only to its fits' tolerance (about 0.1 % of
/// it), and 0.01 decade is 2.3 % of C or σ. Against 0.005 decade and against fitting every
/// candidate, over three population studies with other search seeds, 60 models a condition, it
/// moved no condition's share one way (mean at most 0.7 point lower, sign test p ≥ 0.21), and the
/// eleven paper-sized searches of bench/RESULTS.md took 189 s instead of 221 s, each under 30 s.
/// fogdrift paper fits every distinct candidate, as the paper did.
inline constexpr double kTrainCandidateResolution = 0.01;

/// The search train runs unless told otherwise: TuneOptions' defaults, stopping on a stall,
/// thinning a fold of kTrainThinFromRows or more to no fewer than kTrainSearchRows rows,
/// capping the search's fits at kTrainSmoIterationsPerRow iterations a row, and one candidate
/// within kTrainCandidateResolution.
inline tune::TuneOptions train_search_defaults() {
  tune::TuneOptions t;
  t.optimizer.run.stall_iterations = kTrainStallIterations;
  t.search_rows = kTrainSearchRows;
  t.thin_from_rows = kTrainThinFromRows;
  t.smo_iterations_per_row = kTrainSmoIterationsPerRow;
  t.candidate_resolution = kTrainCandidateResolution;
  return t;
}

struct TrainOptions {
  Method method = Method::ssa_svr;
  /// A search for a method whose name implies none (svr with pso is pso-svr, gp's cv fit with
  /// gwo searches by gwo); own: the method's own (resolved()).
  Search search = Search::own;
  /// fitness, folds, search box, optimizer budget and stall rule, seed, pool
  tune::TuneOptions tune = train_search_defaults();
  /// Each trainer's own options, by their type (T::Options; trainer_options.hpp):
  /// trainers.get<PolyTrainer::Options>().max_degree.
  TrainerOptions trainers;
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
  Method method = Method::ssa_svr;  ///< resolved(): the search it ran is its own
  std::string fitness;              ///< "cv", "train" or "validation"
  double fitness_value = 0;         ///< RMSE on the standardised target
  std::vector<std::pair<std::string, double>> hyperparameters;
  /// The trainer's own record (trainer_record.hpp), of its own type: SvrSearchRecord,
  /// BpRecord, PolyRecord, GpRecord, each declared in its trainer's header.
  TrainerRecord record;
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

/// The options with method and search made one: the method's search is the one its name implies
/// or `search` asks for, as its trainer resolves it (trainer.hpp); search is then own, and the
/// optimizer is the search's. Throws OptionError("search") for a method and a search that
/// contradict (pso-svr with ssa) or a trainer with no use for the search (bp with pso, none for
/// gp's cv fit), and OptionError("method") for a trainer not registered.
TrainOptions resolved(const TrainOptions& options);

/// Checks what can be checked without data, by the method's trainer: the search's box, budget
/// and folds for a tuned SVR, the network's for bp, the degree for poly. Throws OptionError naming
/// the field (train_fleet checks a line's options once before any unit runs).
void validate(const TrainOptions& options);

/// Trains on every row of `data`, built with `dataset` (recorded in the model).
TrainResult train(const Dataset& data, const DatasetOptions& dataset, const TrainOptions& options);

}  // namespace fogdrift
