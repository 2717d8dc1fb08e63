// What every optimizer returns (Ceres' Solver::Summary, pagmo's get_log()): the best point, its
// fitness, how many evaluations it took, why it stopped, and one log record per iteration.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fogdrift::opt {

enum class Algorithm { ssa, pso, gwo };

/// "ssa", "pso", "gwo".
std::string to_string(Algorithm algorithm);
/// Parses to_string's names; throws OptionError naming `option` otherwise.
Algorithm parse_algorithm(const std::string& text, const std::string& option = "algorithm");

enum class Status {
  iteration_limit,  ///< ran every iteration asked for
  stopped,          ///< the progress callback asked to stop
  converged,        ///< the best stopped improving (RunOptions::stall_iterations)
};

/// The state after one iteration (iteration 0 is the initial population).
struct IterationRecord {
  std::size_t iteration = 0;
  std::size_t evaluations = 0;     ///< fitness evaluations so far
  double best_fitness = 0;         ///< best ever
  double mean_fitness = 0;         ///< mean over the population's finite fitness values
  std::vector<double> best_point;  ///< where best_fitness was found
};

/// Called after every iteration; return false to stop the run early.
using Progress = std::function<bool(const IterationRecord&)>;

/// Settings every optimizer shares.
struct RunOptions {
  std::size_t population = 20;  ///< individuals, ≥ 2 (SSA: ≥ 5 so that every role has one)
  std::size_t iterations = 50;  ///< iterations after the initial population, ≥ 1
  std::uint64_t seed = 1;       ///< the whole run is a function of this seed
  /// Stop once the best fitness has improved by less than stall_tolerance (relative) over the
  /// last stall_iterations iterations; 0 runs every iteration. The rule reads only the best
  /// fitness after each iteration, so a stopped run is the full run's prefix (docs/tuning.md,
  /// "A search that stops when it stops learning").
  std::size_t stall_iterations = 0;
  double stall_tolerance = 1e-3;  ///< relative improvement that counts, in [0, 1)
  Progress progress;              ///< optional
};

struct Summary {
  Algorithm algorithm = Algorithm::ssa;
  Status status = Status::iteration_limit;
  std::vector<double> best_point;
  double best_fitness = 0;
  double initial_best_fitness = 0;  ///< best of the initial population
  std::size_t iterations = 0;       ///< iterations completed
  std::size_t evaluations = 0;      ///< fitness evaluations requested
  double seconds = 0;
  std::vector<IterationRecord> log;  ///< iteration 0 … iterations
  /// How often each update rule fired, e.g. SSA's "scout_toward_best" (eq. 5, f_i > f_g).
  std::vector<std::pair<std::string, std::int64_t>> counters;

  /// "ssa: best 0.1234 after 50 iterations, 1020 evaluations, 3.2 s"
  std::string brief_report() const;
};

/// "iteration_limit", "stopped", "converged".
std::string to_string(Status status);

/// True when the best fitness after iteration `log.back()` is less than a `tolerance` relative
/// improvement on the best `iterations` iterations earlier (false before then, or with 0).
bool stalled(const std::vector<IterationRecord>& log, std::size_t iterations, double tolerance);

/// Throws OptionError naming the option for a population or iteration count out of range.
void validate(const RunOptions& options, std::size_t min_population = 2);

}  // namespace fogdrift::opt
