#include "fogdrift/train/tune.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "train/svr_objective.hpp"

namespace fogdrift::tune {

namespace {

constexpr std::array<EnumName<Fitness>, 2> kFitnessNames = {
    {{Fitness::cv, "cv"}, {Fitness::train, "train"}}};

}  // namespace

std::string to_string(Fitness fitness) {
  return std::string(name_in(kFitnessNames, fitness));
}

Fitness parse_fitness(const std::string& text, const std::string& option) {
  return parse_in(kFitnessNames, text, option, "a fitness");
}

std::string fitness_names() {
  return names_in(kFitnessNames);
}

OptionSpec epsilon_option_spec() {
  return {"epsilon",
          "--epsilon",
          OptionType::number,
          "",
          between(0, 10),
          "ε of the SVR's tube, in standardised drift units, when it is not searched",
          {}};
}

void check_epsilon(double epsilon) {
  if (!(epsilon >= 0 && epsilon <= kEpsilonMax))
    throw OptionError("epsilon", fmt::format("{} is outside [0, {:g}]: ε is in standardised drift "
                                             "units, and a wider tube holds every sample",
                                             epsilon, kEpsilonMax));
}

void validate(const TuneOptions& options) {
  const SearchSpace& s = options.space;
  auto range = [](double lo, double hi, const char* lo_name, const char* hi_name) {
    if (!(lo > 0 && std::isfinite(lo)))
      throw OptionError(lo_name, fmt::format("{} must be finite and > 0", lo));
    if (!(hi > lo && std::isfinite(hi)))
      throw OptionError(hi_name,
                        fmt::format("{} must be finite and above {} = {}", hi, lo_name, lo));
  };
  range(s.c_min, s.c_max, "c_min", "c_max");
  range(s.sigma_min, s.sigma_max, "sigma_min", "sigma_max");
  if (s.search_epsilon)
    range(s.epsilon_min, s.epsilon_max, "epsilon_min", "epsilon_max");
  else
    check_epsilon(s.epsilon);
  if (!(options.tolerance > 0 && std::isfinite(options.tolerance)))
    throw OptionError("tolerance", fmt::format("{} must be finite and > 0", options.tolerance));
  if (!(options.cache_mb >= 0 && std::isfinite(options.cache_mb)))
    throw OptionError("cache_mb", fmt::format("{} must be finite and ≥ 0", options.cache_mb));
  if (options.smo_iterations_per_row > kMaxSmoIterationsPerRow)
    throw OptionError(
        "smo_iterations_per_row",
        fmt::format("{} is above {}: LIBSVM's own limit is 200 a row (at least 10⁷); 0 sets no cap",
                    options.smo_iterations_per_row, kMaxSmoIterationsPerRow));
  if (!(options.candidate_resolution >= 0 &&
        options.candidate_resolution <= kMaxCandidateResolution))
    throw OptionError("candidate_resolution",
                      fmt::format("{} is outside [0, {}] decades: candidates farther apart are "
                                  "not the same candidate; 0 fits every distinct one",
                                  options.candidate_resolution, kMaxCandidateResolution));
  if ((options.cv.scheme == CvScheme::recording || options.cv.scheme == CvScheme::temperature) &&
      options.cv.folds < 2)
    throw OptionError("folds", fmt::format("{} is below 2", options.cv.folds));
  switch (options.optimizer.algorithm) {
    case opt::Algorithm::ssa:
      opt::validate(options.optimizer.run, 5);
      opt::validate(options.optimizer.ssa);
      break;
    case opt::Algorithm::pso:
      opt::validate(options.optimizer.run, 2);
      opt::validate(options.optimizer.pso);
      break;
    case opt::Algorithm::gwo:
      opt::validate(options.optimizer.run, 3);
      opt::validate(options.optimizer.gwo);
      break;
  }
}

svr::Params params_at(std::span<const double> point, const TuneOptions& options) {
  svr::Params p;
  p.c = std::pow(10.0, point[0]);
  p.kernel = svr::Kernel::rbf_sigma(std::pow(10.0, point[1]));
  p.epsilon = options.space.search_epsilon ? std::pow(10.0, point[2]) : options.space.epsilon;
  p.tolerance = options.tolerance;
  p.cache_mb = options.cache_mb;
  p.newton = options.newton;
  // The kernel in float: a row at a third of the cost (docs/svr.md, "The kernel in float").
  p.kernel_arithmetic = svr::KernelArithmetic::single;
  return p;
}

std::size_t largest_fold_rows(const Dataset& data, const TuneOptions& options) {
  if (options.fitness != Fitness::cv) return 0;
  std::size_t most = 0;
  for (const Fold& f : grouped_folds(data, options.cv)) most = std::max(most, f.train_rows.size());
  return most;
}

namespace {

// search_stride from the largest fold's training rows (largest_fold_rows).
std::size_t stride_for(std::size_t largest_fold_rows, const TuneOptions& options) {
  if (options.search_rows == 0 || options.fitness != Fitness::cv) return 1;
  if (largest_fold_rows < options.thin_from_rows) return 1;
  return std::max<std::size_t>(1, largest_fold_rows / options.search_rows);
}

}  // namespace

std::size_t search_stride(const Dataset& data, const TuneOptions& options) {
  return stride_for(largest_fold_rows(data, options), options);
}

namespace {

// The search's best complete candidates (at most kRescored, lowest loss first, ties in the
// order found) scored again on every training row; the winner is the lowest of those losses.
std::vector<Candidate> rescored(const Dataset& data, const TuneOptions& options,
                                const std::vector<Candidate>& history) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < history.size(); ++i)
    if (history[i].complete) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&history](std::size_t a, std::size_t b) {
    return history[a].loss < history[b].loss;
  });
  order.resize(std::min(order.size(), kRescored));
  // One batch of whole fits: no racing, no warm starts from another candidate's rows.
  TuneOptions all_rows = options;
  all_rows.racing = false;
  all_rows.warm_start = false;
  all_rows.smo_iterations_per_row = 0;  // the answer's fits run to the end
  SvrObjective objective(data, all_rows, [&](std::span<const double> x) {
    return history[order[static_cast<std::size_t>(x[0])]].params;
  });
  std::vector<double> index(order.size()), loss(order.size());
  std::iota(index.begin(), index.end(), 0.0);
  objective.evaluate(index, loss, 1);
  std::vector<Candidate> out;
  for (std::size_t k = 0; k < order.size(); ++k)
    out.push_back({history[order[k]].params, loss[k], true});
  return out;
}

// The search's answer when some fits stopped at the cap (docs/tuning.md, "A cap on the search's
// fits"): the complete candidate of lowest loss, where a capped candidate's loss counts only
// once its capped fits have been run to the end. Finishes capped candidates in order of the loss
// the optimizer saw until the lowest is a finished one; each is finished at most once. Returns
// its index in history (SIZE_MAX when no candidate is complete) and the finished ones in `out`.
std::size_t finish_best(SvrObjective& objective, const std::vector<Candidate>& history,
                        std::vector<Candidate>& out, double& best_loss) {
  std::map<std::size_t, double> finished;
  for (;;) {
    std::size_t best = SIZE_MAX;
    double lowest = INFINITY;
    for (std::size_t i = 0; i < history.size(); ++i) {
      if (!history[i].complete) continue;
      const auto f = finished.find(i);
      const double loss = f != finished.end() ? f->second : history[i].loss;
      if (loss < lowest) lowest = loss, best = i;
    }
    if (best == SIZE_MAX || !history[best].capped || finished.contains(best)) {
      best_loss = lowest;
      return best;
    }
    const double loss = objective.finish(best);
    finished.emplace(best, loss);
    out.push_back({history[best].params, loss, true, true});
  }
}

}  // namespace

TuneSummary tune_svr(const Dataset& data, const TuneOptions& options) {
  validate(options);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t largest = largest_fold_rows(data, options);
  const std::size_t stride = stride_for(largest, options);
  SvrObjective objective(
      data, options, [&options](std::span<const double> x) { return params_at(x, options); },
      stride);
  const SearchSpace& s = options.space;
  opt::Problem problem;
  problem.lower = {std::log10(s.c_min), std::log10(s.sigma_min)};
  problem.upper = {std::log10(s.c_max), std::log10(s.sigma_max)};
  if (s.search_epsilon) {
    problem.lower.push_back(std::log10(s.epsilon_min));
    problem.upper.push_back(std::log10(s.epsilon_max));
  }
  const std::size_t dims = problem.lower.size();
  problem.evaluate = [&objective, dims](std::span<const double> x, std::span<double> f) {
    objective.evaluate(x, f, dims);
  };

  TuneSummary out;
  out.optimizer = opt::minimize(problem, options.optimizer);
  out.best = params_at(objective.measured(out.optimizer.best_point), options);
  out.best_fitness = out.optimizer.best_fitness;
  if (stride == 1 && objective.capped_fits_ > 0) {
    double loss = 0;
    const std::size_t best = finish_best(objective, objective.history_, out.finished, loss);
    // Unchanged when the optimizer's best had no capped fit: the same answer to the byte.
    if (!out.finished.empty() && best != SIZE_MAX) {
      out.best = objective.history_[best].params;
      out.best_fitness = loss;
    }
  }
  out.folds = objective.fold_names();
  out.candidates = objective.candidates_;
  out.repeats = objective.repeats_;
  out.near_repeats = objective.near_repeats_;
  out.fits = objective.fits_;
  out.warm_fits = objective.warm_fits_;
  out.raced = objective.raced_;
  out.capped_fits = objective.capped_fits_;
  out.history = std::move(objective.history_);
  out.fit_seconds = objective.fit_seconds_;
  out.stride = stride;
  out.largest_fold_rows = largest;
  if (stride > 1) {
    out.rescored = rescored(data, options, out.history);
    out.fits += out.rescored.size() * std::max<std::size_t>(1, out.folds.size());
    const auto best =
        std::min_element(out.rescored.begin(), out.rescored.end(),
                         [](const Candidate& a, const Candidate& b) { return a.loss < b.loss; });
    if (best != out.rescored.end()) {
      out.best = best->params;
      out.best_fitness = best->loss;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

double svr_loss(const Dataset& data, const svr::Params& params, const TuneOptions& options) {
  svr::validate(params);
  TuneOptions whole = options;
  whole.smo_iterations_per_row = 0;  // one candidate's loss: its fits run to the end
  SvrObjective objective(data, whole, [&params](std::span<const double>) { return params; });
  const double point = 0;
  double loss = 0;
  objective.evaluate(std::span<const double>(&point, 1), std::span<double>(&loss, 1), 1);
  return loss;
}

}  // namespace fogdrift::tune

namespace fogdrift::tune {

namespace {

/// A searched parameter: its name, its bounds in SearchSpace, the limits a widened box keeps
/// within, and its value in a candidate.
struct Axis {
  const char* name;
  double SearchSpace::*low;
  double SearchSpace::*high;
  double floor, ceiling;
  double (*get)(const svr::Params&);
};

const std::array<Axis, 3> kAxes = {{
    {"C", &SearchSpace::c_min, &SearchSpace::c_max, 1e-6, 1e8,
     [](const svr::Params& p) { return p.c; }},
    {"sigma", &SearchSpace::sigma_min, &SearchSpace::sigma_max, 1e-4, 1e4,
     [](const svr::Params& p) { return p.kernel.sigma(); }},
    {"epsilon", &SearchSpace::epsilon_min, &SearchSpace::epsilon_max, 1e-6, 10.0,
     [](const svr::Params& p) { return p.epsilon; }},
}};

}  // namespace

std::vector<BoxEdge> box_edges(const TuneSummary& summary, const SearchSpace& space) {
  std::vector<BoxEdge> edges;
  // The best's loss as the search saw it (on every k-th row when it had a stride), comparable
  // with the history's; a capped candidate's is not its parameters' loss.
  double best_loss = summary.best_fitness;
  for (const Candidate& c : summary.history)
    if (c.complete && !c.capped && c.params.c == summary.best.c &&
        c.params.epsilon == summary.best.epsilon &&
        c.params.kernel.gamma == summary.best.kernel.gamma)
      best_loss = c.loss;
  for (const Axis& a : kAxes) {
    if (a.name == std::string_view("epsilon") && !space.search_epsilon) continue;
    const double lo = std::log10(space.*a.low), hi = std::log10(space.*a.high), span = hi - lo;
    const double best = std::log10(a.get(summary.best));
    for (const bool upper : {false, true}) {
      const double edge = upper ? hi : lo;
      if (std::fabs(best - edge) > 0.02 * span) continue;
      // The best fitness at least `inset` (log10) further inside than the edge.
      const double inset = std::min(1.0, 0.25 * span);
      double inside = std::numeric_limits<double>::infinity();
      for (const Candidate& c : summary.history) {
        if (!c.complete || c.capped) continue;  // an estimate, or an unfinished fit's loss
        const double x = std::log10(a.get(c.params));
        if ((upper ? edge - x : x - edge) >= inset) inside = std::min(inside, c.loss);
      }
      BoxEdge e;
      e.parameter = a.name;
      e.upper = upper;
      e.value = a.get(summary.best);
      e.low = space.*a.low;
      e.high = space.*a.high;
      e.improvement =
          std::isfinite(inside) && inside > 0 ? std::max(0.0, (inside - best_loss) / inside) : 0.0;
      edges.push_back(e);
    }
  }
  return edges;
}

SearchSpace widened(const SearchSpace& space, const std::vector<BoxEdge>& edges) {
  SearchSpace w = space;
  for (const BoxEdge& e : edges) {
    for (const Axis& a : kAxes) {
      if (e.parameter != a.name) continue;
      if (e.upper)
        w.*a.high = std::min(a.ceiling, w.*a.high * 10.0);
      else
        w.*a.low = std::max(a.floor, w.*a.low / 10.0);
    }
  }
  return w;
}

}  // namespace fogdrift::tune
