// Hyperparameter tuning of the ε-SVR (docs/method.md §2 step 4), on the grouped folds every
// method shares (folds.hpp).
//
// The problem handed to an optimizer (opt/problem.hpp) has the coordinates log10 C, log10 σ and,
// optionally, log10 ε, inside SearchSpace's bounds. Its fitness is the RMSE of the drift on the
// standardised target, either
//   - cv (default): pooled over the held-out rows of grouped folds. A fold never splits a
//     recording: leave one repetition out, k folds of whole recordings, or k folds of whole
//     initial temperatures. Features and target are standardised with the statistics of each
//     fold's training rows only; or
//   - train (the paper's choice): on the training rows themselves, which rewards over-fitting.
//
// Speed: each fold's data is prepared once (svr::TrainingSet) and reused by every candidate; a
// population is fitted in parallel, one (candidate, fold) fit per task; a candidate already
// evaluated is never refitted (the optimizers often revisit a bound); held-out rows are scored
// with vectorised kernel rows over the support vectors; and a new fit is warm-started from the
// nearest candidate (in log coordinates) already solved on that fold with the same σ, whose dual
// solution is rescaled to the new C (smo_solver.hpp), or else from the nearest one when it lies
// within 0.3 decade in C and σ (its gradient rebuilt). Each fold keeps its solutions up to 48 MiB
// (every one of a paper-sized search on the paper's campaign). Warm starts come only from
// earlier batches, so results do not depend on the thread count.
//
// Racing: the loss is sqrt(Σ squared errors / held-out rows), so a candidate whose errors on the
// folds run so far already exceed the best complete candidate's total cannot beat it. Once an
// earlier batch has completed a candidate, a batch runs each candidate's folds as a chain (the
// fold where the best candidate errs most first) and a candidate that cannot win leaves the
// race, its chain stopped. The optimizer then sees its errors so far scaled to all folds as the
// best candidate's errors spread over them: an estimate of its loss, above the best. A
// candidate that would beat the best is never stopped, so the best of the candidates a search
// visits is the one full evaluation would choose; the estimates order the losers a little
// differently from their full losses, so the later candidates may differ. On 5,940-row
// campaigns it spares half the fits (docs/tuning.md).
//
// A cap on the fits (TuneOptions::smo_iterations_per_row): a fit stops after so many SMO
// iterations a training row, unfinished. Its candidate's loss is what the optimizer sees, but it
// never bounds a race nor counts towards stopping one, and before the search answers, a capped
// candidate whose loss is the lowest has its capped fits run to the end (from where they
// stopped) and competes with its finished loss; this repeats until the lowest is a finished
// candidate. The answer is therefore the best of the visited candidates as finished fits score
// them, among those the optimizer's unfinished losses did not steer it away from
// (docs/tuning.md, "A cap on the search's fits").
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/opt/optimizer.hpp"
#include "fogdrift/svr/svr.hpp"
#include "fogdrift/train/folds.hpp"

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::tune {

enum class Fitness {
  cv,     ///< grouped cross-validation RMSE (default)
  train,  ///< training RMSE, the paper's fitness
};
std::string to_string(Fitness fitness);
Fitness parse_fitness(const std::string& text, const std::string& option = "fitness");
/// "cv, train".
std::string fitness_names();

/// The search box, in natural units; the optimizer sees log10 of each. σ is in standardised
/// feature units, ε in standardised target units.
struct SearchSpace {
  double c_min = 1e-2, c_max = 1e3;
  double sigma_min = 0.05, sigma_max = 20;
  bool search_epsilon = false;  ///< also tune ε (a third coordinate)
  /// ε when not searched. 0.05, not LIBSVM's 0.1: measured on the simulator, the cv fitness
  /// improves down to 0.05 and no further, and the models transfer better (docs/paper.md).
  double epsilon = 0.05;
  double epsilon_min = 1e-3, epsilon_max = 1;

  bool operator==(const SearchSpace&) const = default;
};

/// The largest ε: in standardised drift units (the drift's STD is 1), a tube of 10 holds every
/// sample and leaves a flat model.
inline constexpr double kEpsilonMax = 10;

/// The one description of the option ε (`epsilon`, --epsilon) that train and paper take: its
/// keyword, flag, range and help (docs/options.md).
OptionSpec epsilon_option_spec();

/// OptionError("epsilon") unless ε is a finite number in [0, kEpsilonMax]: the rule of
/// epsilon_option_spec, checked by validate(TuneOptions) and by the paper's validate.
void check_epsilon(double epsilon);

struct TuneOptions {
  Fitness fitness = Fitness::cv;
  CvOptions cv;
  SearchSpace space;
  opt::OptimizerOptions optimizer;  ///< algorithm, population, iterations, seed, progress
  double tolerance = 1e-3;          ///< SMO stopping tolerance of every fit (LIBSVM -e)
  double cache_mb = 64;             ///< kernel-row cache of each concurrent fit, MB
  bool warm_start = true;           ///< warm-start fits from the nearest solved candidate
  bool racing = true;               ///< stop candidates that cannot beat the best (header)
  bool newton = true;               ///< svr::Params::newton of every fit (docs/svr.md)
  /// cv: the fewest training rows a fold may be thinned to for the search. A campaign with at
  /// least twice as many in a fold is searched on every k-th training row (C × k), the largest
  /// k that leaves this many, and its best kRescored candidates are scored again on all rows,
  /// the best of those winning (docs/tuning.md, "A search on fewer rows"). 0: every row.
  std::size_t search_rows = 0;
  /// cv: a fold of fewer training rows than this is searched on every row whatever search_rows
  /// says: thinning a small campaign saves little and costs its search the most (docs/tuning.md,
  /// "Why small campaigns keep every row"). 0: search_rows alone decides.
  std::size_t thin_from_rows = 0;
  /// The SMO iterations each of the search's fits may take, per training row of the largest
  /// fold (before any thinning). A fit stopped there is unfinished: its candidate's loss
  /// steers the optimizer but never bounds a race, and a candidate that would be the search's
  /// answer is fitted to the end first (docs/tuning.md, "A cap on the search's fits"). 0: no
  /// cap beyond the solver's own (LIBSVM's). At most kMaxSmoIterationsPerRow.
  std::size_t smo_iterations_per_row = 0;
  /// Candidates within this distance in every coordinate of the search (decades of C, σ and ε)
  /// are one candidate: the later one takes the loss of the one fitted, and the search's answer
  /// is always a fitted candidate. A loss is known only to its fits' tolerance, which moves it
  /// by about as much as such a step does (docs/tuning.md, "One candidate within a
  /// resolution"). 0: only equal points are one candidate.
  double candidate_resolution = 0;
  ThreadPool* pool = nullptr;  ///< fits a population in parallel when given
};

/// The largest TuneOptions::candidate_resolution, in decades (2.3 % of C or σ).
inline constexpr double kMaxCandidateResolution = 0.01;

/// The largest TuneOptions::smo_iterations_per_row; LIBSVM's own limit is 200 a row (at least
/// 10⁷ in all).
inline constexpr std::size_t kMaxSmoIterationsPerRow = 1000;

/// Throws OptionError naming the field: bounds not positive or not increasing, ε outside its
/// bounds, a bad tolerance or cache size, or bad optimizer settings.
void validate(const TuneOptions& options);

/// The SVR of a point in the search coordinates (RBF kernel, the options' tolerance).
svr::Params params_at(std::span<const double> point, const TuneOptions& options);

/// One distinct candidate of a search, in the order it was first evaluated.
struct Candidate {
  svr::Params params;
  double loss = 0;  ///< the fitness: RMSE on the standardised target
  /// false: stopped by racing before its last fold; `loss` is then an estimate, above the best
  bool complete = true;
  /// A fit of it stopped at the search's cap (TuneOptions::smo_iterations_per_row): `loss` is
  /// that of unfinished fits, what the optimizer saw.
  bool capped = false;
};

/// Candidates of a search on every k-th row scored again on all rows (TuneOptions::search_rows).
inline constexpr std::size_t kRescored = 3;

/// The training rows of the largest cv fold of `data` (0 for the training-loss fitness): what
/// decides whether a search thins its folds.
std::size_t largest_fold_rows(const Dataset& data, const TuneOptions& options);

/// The stride of a search on `data` (cv only): the largest fold's training rows divided by
/// options.search_rows, rounded down, and at least 1; 1 with search_rows 0 or when the largest
/// fold holds fewer than options.thin_from_rows.
std::size_t search_stride(const Dataset& data, const TuneOptions& options);

struct TuneSummary {
  svr::Params best;                ///< C, σ (kernel) and ε of the best candidate
  double best_fitness = 0;         ///< RMSE on the standardised target
  opt::Summary optimizer;          ///< best point in log10 coordinates, per-iteration log
  std::vector<std::string> folds;  ///< fold names (empty for the training loss)
  std::size_t candidates = 0;      ///< distinct candidates evaluated
  std::size_t repeats = 0;         ///< evaluations answered from the memo
  /// evaluations answered by a candidate within TuneOptions::candidate_resolution
  std::size_t near_repeats = 0;
  std::size_t fits = 0;            ///< SVR fits made, the rescored candidates' included
  std::size_t warm_fits = 0;       ///< of which warm-started
  std::size_t raced = 0;           ///< candidates stopped by racing before their last fold
  std::size_t capped_fits = 0;     ///< fits stopped at the cap (smo_iterations_per_row)
  double fit_seconds = 0;          ///< sum of the fits' own times (over all threads)
  std::vector<Candidate> history;  ///< every distinct candidate and its loss
  /// The search's stride (search_stride); above 1, `history` holds the losses of fits on every
  /// k-th training row and `rescored` the best of them scored again on all rows, best first
  /// in the search's order; `best` and `best_fitness` are the rescored winner's.
  std::size_t stride = 1;
  std::size_t largest_fold_rows = 0;  ///< largest_fold_rows, which set the stride
  std::vector<Candidate> rescored;
  /// Capped candidates fitted to the end because one of them would have been the answer, in
  /// the order finished, each with its finished loss (stride 1; above it the rescoring fits
  /// the answer to the end). `best` is a candidate whose every fit finished.
  std::vector<Candidate> finished;
  double seconds = 0;  ///< wall time of the search
};

/// Searches C, σ (and ε) for `data` (training recordings only) with the chosen optimizer.
TuneSummary tune_svr(const Dataset& data, const TuneOptions& options);

/// A searched parameter whose best value lies on an edge of its box: the search may have been
/// stopped by the box rather than by the data (docs/tuning.md, "Box edges").
struct BoxEdge {
  std::string parameter;     ///< "C", "sigma" or "epsilon"
  bool upper = false;        ///< the upper edge (else the lower)
  double value = 0;          ///< the best value found
  double low = 0, high = 0;  ///< the box searched
  /// How much better the best fitness is than the best at least a quarter of the box's log10
  /// span (at most one decade) further inside: (inside − best) / inside, >= 0. Large means the
  /// fitness was still improving toward the edge.
  double improvement = 0;
};

/// The searched parameters whose best value is within 2 % of the box's log10 span of an edge.
std::vector<BoxEdge> box_edges(const TuneSummary& summary, const SearchSpace& space);

/// The box widened by one decade beyond each edge in `edges`, within C in [1e-6, 1e8],
/// σ in [1e-4, 1e4] and ε in [1e-6, 10]; unchanged where an edge is already at that limit.
SearchSpace widened(const SearchSpace& space, const std::vector<BoxEdge>& edges);

/// The fitness of one parameter set, as the search computes it (for baselines and reports).
double svr_loss(const Dataset& data, const svr::Params& params, const TuneOptions& options);

}  // namespace fogdrift::tune
