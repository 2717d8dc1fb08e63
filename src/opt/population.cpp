#include "opt/population.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/interrupt.hpp"
#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::opt {

namespace {

constexpr std::array<EnumName<Algorithm>, 3> kAlgorithmNames = {
    {{Algorithm::ssa, "ssa"}, {Algorithm::pso, "pso"}, {Algorithm::gwo, "gwo"}}};

constexpr std::array<EnumName<Status>, 3> kStatusNames = {
    {{Status::iteration_limit, "iteration_limit"},
     {Status::stopped, "stopped"},
     {Status::converged, "converged"}}};

}  // namespace

std::string to_string(Algorithm algorithm) {
  return std::string(name_in(kAlgorithmNames, algorithm));
}

Algorithm parse_algorithm(const std::string& text, const std::string& option) {
  return parse_in(kAlgorithmNames, text, option, "an optimizer");
}

std::string to_string(Status status) {
  return std::string(name_in(kStatusNames, status));
}

std::string Summary::brief_report() const {
  return fmt::format("{}: best {:.6g} after {} iterations, {} evaluations, {:.1f} s{}",
                     to_string(algorithm), best_fitness, iterations, evaluations, seconds,
                     status == Status::iteration_limit ? "" : " (" + to_string(status) + ")");
}

bool stalled(const std::vector<IterationRecord>& log, std::size_t iterations, double tolerance) {
  if (iterations == 0 || log.size() <= iterations) return false;
  const double then = log[log.size() - 1 - iterations].best_fitness;
  const double now = log.back().best_fitness;
  if (!std::isfinite(then)) return false;  // nothing finite found yet: keep looking
  // An improvement of less than `tolerance` of |then| (or none at all when then is 0).
  return then - now <= tolerance * std::abs(then);
}

void validate(const RunOptions& options, std::size_t min_population) {
  if (options.population < min_population)
    throw OptionError("population", fmt::format("{} is too small: at least {}", options.population,
                                                min_population));
  if (options.population > 100000)
    throw OptionError("population", fmt::format("{} is above 100000", options.population));
  if (options.iterations < 1) throw OptionError("iterations", "must be at least 1");
  if (options.iterations > 10000000)
    throw OptionError("iterations", fmt::format("{} is above 10000000", options.iterations));
  if (options.stall_iterations > 10000000)
    throw OptionError("stall_iterations",
                      fmt::format("{} is above 10000000", options.stall_iterations));
  if (!(options.stall_tolerance >= 0 && options.stall_tolerance < 1))
    throw OptionError("stall_tolerance",
                      fmt::format("{} is outside [0, 1): a relative improvement of the best "
                                  "fitness, e.g. 0.001",
                                  options.stall_tolerance));
}

void validate(const Problem& problem) {
  if (problem.lower.empty()) throw OptionError("bounds", "the problem has no coordinates");
  if (problem.lower.size() != problem.upper.size())
    throw OptionError("bounds", fmt::format("{} lower bounds but {} upper bounds",
                                            problem.lower.size(), problem.upper.size()));
  for (std::size_t j = 0; j < problem.lower.size(); ++j) {
    const double lo = problem.lower[j], hi = problem.upper[j];
    if (!std::isfinite(lo) || !std::isfinite(hi))
      throw OptionError("bounds", fmt::format("coordinate {}: bounds must be finite", j + 1));
    if (!(lo < hi))
      throw OptionError(
          "bounds", fmt::format("coordinate {}: lower {} is not below upper {}", j + 1, lo, hi));
  }
  if (!problem.evaluate) throw OptionError("fitness", "the problem has no fitness function");
}

Problem Problem::from_function(std::vector<double> lower, std::vector<double> upper,
                               std::function<double(std::span<const double>)> f, ThreadPool* pool) {
  Problem p;
  p.lower = std::move(lower);
  p.upper = std::move(upper);
  const std::size_t d = p.lower.size();
  p.evaluate = [f = std::move(f), d, pool](std::span<const double> points,
                                           std::span<double> fitness) {
    auto one = [&](std::size_t i) { fitness[i] = f(points.subspan(i * d, d)); };
    if (pool)
      pool->parallel_for(fitness.size(), one);
    else
      for (std::size_t i = 0; i < fitness.size(); ++i) one(i);
  };
  return p;
}

namespace detail {

std::vector<double> uniform_points(const Problem& problem, std::size_t count, Rng& rng) {
  const std::size_t d = problem.dimension();
  std::vector<double> x(count * d);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t j = 0; j < d; ++j)
      x[i * d + j] = rng.uniform(problem.lower[j], problem.upper[j]);
  return x;
}

Run::Run(Algorithm algorithm, const Problem& problem, const RunOptions& options)
    : problem_(problem), options_(options), start_(std::chrono::steady_clock::now()) {
  summary_.algorithm = algorithm;
  summary_.best_fitness = std::numeric_limits<double>::infinity();
  summary_.best_point.assign(problem.dimension(), 0.0);
  // Until anything is evaluated, the best point is the box centre.
  for (std::size_t j = 0; j < problem.dimension(); ++j)
    summary_.best_point[j] = 0.5 * (problem.lower[j] + problem.upper[j]);
}

void Run::evaluate(std::span<const double> points, std::span<double> fitness) {
  if (fitness.empty()) return;
  problem_.evaluate(points, fitness);
  summary_.evaluations += fitness.size();
  const std::size_t d = problem_.dimension();
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    fitness[i] = sanitized(fitness[i]);
    if (fitness[i] < summary_.best_fitness) {
      summary_.best_fitness = fitness[i];
      std::copy_n(points.begin() + static_cast<std::ptrdiff_t>(i * d), d,
                  summary_.best_point.begin());
    }
  }
}

bool Run::end_iteration(std::size_t iteration, std::span<const double> population_fitness) {
  check_interrupt();  // base/interrupt.hpp
  IterationRecord record;
  record.iteration = iteration;
  record.evaluations = summary_.evaluations;
  record.best_fitness = summary_.best_fitness;
  record.best_point = summary_.best_point;
  double sum = 0;
  std::size_t finite = 0;
  for (double f : population_fitness)
    if (std::isfinite(f)) sum += f, ++finite;
  record.mean_fitness =
      finite ? sum / static_cast<double>(finite) : std::numeric_limits<double>::infinity();
  if (iteration == 0) summary_.initial_best_fitness = summary_.best_fitness;
  summary_.iterations = iteration;
  summary_.log.push_back(record);
  if (options_.progress && !options_.progress(summary_.log.back())) {
    summary_.status = Status::stopped;
    return false;
  }
  if (stalled(summary_.log, options_.stall_iterations, options_.stall_tolerance)) {
    summary_.status = Status::converged;
    return false;
  }
  return true;
}

void Run::count(const char* name, std::int64_t n) {
  for (auto& [key, value] : summary_.counters)
    if (key == name) {
      value += n;
      return;
    }
  summary_.counters.emplace_back(name, n);
}

Summary Run::finish() {
  summary_.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return std::move(summary_);
}

}  // namespace detail
}  // namespace fogdrift::opt
