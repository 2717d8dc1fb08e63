// Shared machinery of the population-based optimizers: evaluation in batches, bounds, the
// best-so-far tracker and the per-iteration log. Internal to src/opt.
#pragma once

#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "fogdrift/opt/problem.hpp"
#include "fogdrift/opt/summary.hpp"

namespace fogdrift::opt::detail {

inline double sanitized(double f) {
  return std::isnan(f) ? std::numeric_limits<double>::infinity() : f;
}

inline void clip(std::span<double> x, const Problem& problem) {
  for (std::size_t j = 0; j < x.size(); ++j)
    x[j] = std::min(std::max(x[j], problem.lower[j]), problem.upper[j]);
}

/// Points uniform in the box, row-major.
std::vector<double> uniform_points(const Problem& problem, std::size_t count, Rng& rng);

/// Runs one optimizer: evaluates batches, keeps the best ever and the log, and asks the
/// progress callback whether to go on.
class Run {
 public:
  Run(Algorithm algorithm, const Problem& problem, const RunOptions& options);

  /// Fitness of `count` points (row-major) into `fitness`, NaN read as +∞; updates the best.
  void evaluate(std::span<const double> points, std::span<double> fitness);
  /// Closes an iteration: logs it with the mean of `population_fitness` and returns false if the
  /// progress callback asked to stop.
  bool end_iteration(std::size_t iteration, std::span<const double> population_fitness);
  void count(const char* name, std::int64_t n = 1);

  double best_fitness() const { return summary_.best_fitness; }
  std::span<const double> best_point() const { return summary_.best_point; }
  Summary finish();

 private:
  const Problem& problem_;
  const RunOptions& options_;
  Summary summary_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace fogdrift::opt::detail
