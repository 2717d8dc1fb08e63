// The one problem interface every fogdrift optimizer solves (pagmo's `problem`, reduced):
// minimise a fitness over a box, lower ≤ x ≤ upper, evaluating a whole population at once.
//
// The optimizers never know their objective. They hand the problem a batch of points and get
// one fitness each back; the problem decides how to spread the batch over threads (the tuner fits
// one SVR per point and fold on a thread pool). A fitness must be a deterministic function of
// its point, so that a run depends only on its seed. A fitness that is NaN counts as +∞ (the
// point is never chosen as best); the optimizers keep going.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::opt {

/// Evaluates `fitness.size()` points stored row-major in `points` (fitness.size() × dimension).
using BatchFitness = std::function<void(std::span<const double> points, std::span<double> fitness)>;

struct Problem {
  std::vector<double> lower;  ///< lower bound of each coordinate
  std::vector<double> upper;  ///< upper bound of each coordinate, > lower
  BatchFitness evaluate;      ///< lower fitness is better

  std::size_t dimension() const { return lower.size(); }

  /// A problem from a function of one point, evaluated for a batch on `pool` (serially when
  /// null). `f` is called from several threads at once and must be safe to.
  static Problem from_function(std::vector<double> lower, std::vector<double> upper,
                               std::function<double(std::span<const double>)> f,
                               ThreadPool* pool = nullptr);
};

/// Throws OptionError("bounds", …) for empty or mismatched bounds, a non-finite bound or
/// lower ≥ upper (naming the coordinate), and OptionError("fitness", …) without a fitness.
void validate(const Problem& problem);

}  // namespace fogdrift::opt
