// The loss of SVR candidates over grouped folds (or the training rows), as tune_svr's searches
// evaluate it: each fold prepared once, a memo of candidates, warm starts from the nearest solved
// candidate, racing, the cap on a fit's SMO iterations with finish() for a capped candidate, and
// vectorised scoring (fogdrift/train/tune.hpp, docs/tuning.md "Speed", "A cap on the search's
// fits").
// Private to train/: the searches build one per campaign, or two when the search fits every k-th
// training row (docs/tuning.md, "A search on fewer rows").
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/fold_paths.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift::tune {

// The loss of SVR candidates over the folds (or the training data), with the memo and the warm
// starts described in the header.
class SvrObjective {
 public:
  using ToParams = std::function<svr::Params(std::span<const double>)>;

  /// `stride` k > 1 (cv only) fits each fold on every k-th of its training rows with C × k, so
  /// that the fit keeps the full data's balance of margin and errors, and scores every held-out
  /// row as before: losses stay comparable with a search on all rows (docs/tuning.md).
  SvrObjective(const Dataset& data, const TuneOptions& options, ToParams to_params,
               std::size_t stride = 1)
      : options_(options), to_params_(std::move(to_params)) {
    auto add = [this](ScaledSplit s) {
      std::vector<std::size_t> rows(s.test.rows);
      std::iota(rows.begin(), rows.end(), 0);
      folds_.push_back({std::make_unique<svr::TrainingSet>(std::move(s.train)),
                        std::move(s.test),
                        std::move(rows),
                        {}});
    };
    std::size_t largest_rows = data.rows;  // of the fitness on the training rows
    if (options.fitness == Fitness::cv) {
      c_scale_ = static_cast<double>(stride);
      largest_rows = 0;
      for (const Fold& f : grouped_folds(data, options.cv)) {
        largest_rows = std::max(largest_rows, f.train_rows.size());
        std::vector<std::size_t> kept;
        for (std::size_t i = 0; i < f.train_rows.size(); i += stride)
          kept.push_back(f.train_rows[i]);
        add(scale_split(data, kept, f.test_rows));
        fold_names_.push_back(f.name);
      }
    } else {
      std::vector<std::size_t> all(data.rows);
      std::iota(all.begin(), all.end(), 0);
      add(scale_split(data, all, all));
    }
    max_iterations_ = static_cast<std::int64_t>(options.smo_iterations_per_row * largest_rows);
    for (const FoldState& f : folds_) {
      test_rows_ += f.test.rows;
      scoring_.push_back({f.set.get(), &f.test, f.test_rows, {}});
    }
    // Every thread may run a fit of the largest fold at once, and every fold keeps up to
    // kKeptBytesPerFold of warm starts, about one a candidate of the optimizer's budget
    // (population × (iterations + 1)) at the most: checked once, here, so that a search too
    // large for this machine fails before its first batch.
    const auto largest = std::max_element(folds_.begin(), folds_.end(), [](auto& a, auto& b) {
      return a.set->size() < b.set->size();
    });
    svr::Params p;
    p.cache_mb = options.cache_mb;
    const opt::RunOptions& run = options.optimizer.run;
    const std::size_t candidates = run.population * (run.iterations + 1);
    std::uint64_t kept = 0;
    for (const FoldState& f : folds_)
      kept += std::min(kept_solutions(*f.set), candidates) * solution_bytes(*f.set);
    svr::require_fit_memory(*largest->set, p, options.pool ? options.pool->size() : 1, kept);
  }

  const std::vector<std::string>& fold_names() const { return fold_names_; }

  void evaluate(std::span<const double> points, std::span<double> fitness, std::size_t dims) {
    const std::size_t n = fitness.size(), folds = folds_.size();
    // New distinct candidates of this batch, in order of first appearance.
    std::vector<std::vector<double>> fresh;
    std::vector<std::size_t> slot(n);
    std::map<std::vector<double>, std::size_t> in_batch;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<double> key(points.begin() + static_cast<std::ptrdiff_t>(i * dims),
                              points.begin() + static_cast<std::ptrdiff_t>((i + 1) * dims));
      if (memo_.contains(key)) {
        ++repeats_;
        slot[i] = SIZE_MAX;
        continue;
      }
      // Within the resolution of a candidate measured in an earlier batch, or of a new one
      // earlier in this batch: the same candidate (TuneOptions::candidate_resolution).
      if (options_.candidate_resolution > 0 && !in_batch.contains(key)) {
        const auto [near, near_d] = nearest_within(measured_, key);
        const auto [near_fresh, near_fresh_d] = nearest_within(fresh, key);
        if (near_fresh != nullptr && (near == nullptr || near_fresh_d < near_d)) {
          stand_in_.emplace(key, *near_fresh);
          ++near_repeats_;
          slot[i] = in_batch.at(*near_fresh);
          continue;
        }
        if (near != nullptr) {
          stand_in_.emplace(key, *near);
          memo_.emplace(key, memo_.at(*near));
          ++near_repeats_;
          slot[i] = SIZE_MAX;
          continue;
        }
      }
      auto [it, inserted] = in_batch.try_emplace(key, fresh.size());
      if (inserted)
        fresh.push_back(key);
      else
        ++repeats_;
      slot[i] = it->second;
    }

    // One path task of one C per (candidate, fold) on the engine every search runs on
    // (fold_paths.hpp); warm starts only from earlier batches. Tasks are handed out longest
    // first (LPT), the length guessed from the nearest solved candidate's fit time, so that both
    // threads finish the batch together; the order never changes a result.
    const std::size_t tasks = fresh.size() * folds;
    std::vector<double> sse(tasks, 0.0), seconds(tasks, 0.0);
    std::vector<std::shared_ptr<const svr::DualSolution>> duals(tasks);
    std::vector<char> warm(tasks, 0), ran(tasks, 0), capped(tasks, 0);

    // Racing (header): once a complete candidate is known, each candidate's folds run as a
    // chain, the fold where the best candidate errs most first, and a candidate whose squared
    // errors so far already exceed the best's total leaves the race. Before that, every fold
    // of every candidate runs. A chain goes on as soon as its own fold is scored, without
    // waiting for the other candidates' (fold_paths.hpp, run_path_chains). Only the errors of
    // fits that finished count towards the bound: a capped fit's errors are not its
    // parameters' and may lie above them, so they never stop a candidate (docs/tuning.md, "A cap
    // on the search's fits").
    const double stop_above = options_.racing && folds > 1 && std::isfinite(best_loss_)
                                  ? best_loss_ * best_loss_ * static_cast<double>(test_rows_)
                                  : INFINITY;
    const bool racing = std::isfinite(stop_above);
    std::vector<double> partial(fresh.size(), 0.0);
    std::vector<char> alive(fresh.size(), 1);
    std::vector<std::size_t> order(folds);
    if (racing)
      order = fold_order();
    else
      std::iota(order.begin(), order.end(), 0);
    // Task k is fold order[k % folds] of candidate k / folds; t its slot in sse, duals, ….
    auto slot_of = [&](std::size_t k) { return (k / folds) * folds + order[k % folds]; };
    std::vector<svr::PathTask> paths(tasks);
    for (std::size_t k = 0; k < tasks; ++k) {
      const std::size_t c = k / folds, f = order[k % folds];
      svr::PathTask& p = paths[k];
      p = task_for(fresh[c], f);
      p.params.max_iterations = max_iterations_;
      if (options_.warm_start) p.warm = warm_start_for(folds_[f], fresh[c]);
      p.keep_duals = true;
      p.guess_seconds = guessed_seconds(folds_[f], fresh[c]);
      warm[slot_of(k)] = p.warm != nullptr;
    }
    const std::vector<svr::PathScores> scores =
        svr::run_path_chains(scoring_, paths, racing ? folds : 1, options_.pool, workspaces_,
                             [&](std::size_t k, const svr::PathScores& s) {
                               const std::size_t c = k / folds;
                               if (s.status[0] != svr::SolverStatus::iteration_limit)
                                 partial[c] += s.sse[0];
                               if (partial[c] > stop_above) alive[c] = 0;
                               return alive[c] != 0;
                             });
    for (std::size_t k = 0; k < tasks; ++k) {
      if (scores[k].sse.empty()) continue;  // its candidate left the race before this fold
      const std::size_t t = slot_of(k);
      sse[t] = scores[k].sse[0];
      seconds[t] = scores[k].seconds[0];
      duals[t] = scores[k].duals[0];
      capped[t] = scores[k].status[0] == svr::SolverStatus::iteration_limit;
      ran[t] = 1;
    }

    std::vector<double> loss(fresh.size());
    std::vector<char> any_capped(fresh.size(), 0);
    for (std::size_t c = 0; c < fresh.size(); ++c) {
      double s = 0;
      bool complete = true;
      for (std::size_t f = 0; f < folds; ++f) {
        const std::size_t t = c * folds + f;
        if (!ran[t]) {
          complete = false;
          continue;
        }
        s += sse[t];
        fit_seconds_ += seconds[t];
        warm_fits_ += warm[t] ? 1 : 0;
        ++fits_;
        if (capped[t]) any_capped[c] = 1, ++capped_fits_;
      }
      // A candidate out of the race: its squared errors so far, scaled to all folds as the best
      // candidate's errors spread over them; above the best loss, since they alone exceed it.
      double scale = 1;
      if (!complete) {
        double all = 0, run_part = 0;
        for (std::size_t f = 0; f < folds; ++f) {
          all += best_fold_sse_[f];
          if (ran[c * folds + f]) run_part += best_fold_sse_[f];
        }
        if (run_part > 0) scale = all / run_part;
      }
      loss[c] = std::sqrt(s * scale / static_cast<double>(test_rows_));
      memo_.emplace(fresh[c], loss[c]);
      history_.push_back({to_params_(fresh[c]), loss[c], complete, any_capped[c] != 0});
      if (!complete) ++raced_;
      // A complete capped candidate may yet be the answer: keep what finish() needs.
      if (complete && any_capped[c]) {
        Unfinished& u = unfinished_[history_.size() - 1];
        u.point = fresh[c];
        for (std::size_t f = 0; f < folds; ++f) {
          const std::size_t t = c * folds + f;
          u.sse.push_back(sse[t]);
          u.duals.push_back(capped[t] ? duals[t] : nullptr);
        }
      }
    }
    // The best complete candidate so far bounds the next batches' races; one with an
    // unfinished fit does not, since its loss is not yet the loss of its parameters.
    for (std::size_t c = 0; c < fresh.size(); ++c) {
      if (!alive[c] || any_capped[c] || !(loss[c] < best_loss_)) continue;
      best_loss_ = loss[c];
      best_fold_sse_.assign(sse.begin() + static_cast<std::ptrdiff_t>(c * folds),
                            sse.begin() + static_cast<std::ptrdiff_t>((c + 1) * folds));
    }
    // Keep the most recent solutions of each fold as warm starts for later batches, as many as
    // kKeptBytesPerFold holds.
    for (std::size_t f = 0; f < folds; ++f) {
      auto& kept = folds_[f].solved;
      for (std::size_t c = 0; c < fresh.size(); ++c)
        if (ran[c * folds + f])
          kept.push_back({fresh[c], duals[c * folds + f], seconds[c * folds + f]});
      const std::size_t keep = kept_solutions(*folds_[f].set);
      if (kept.size() > keep)
        kept.erase(kept.begin(), kept.end() - static_cast<std::ptrdiff_t>(keep));
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (slot[i] == SIZE_MAX) {
        std::vector<double> key(points.begin() + static_cast<std::ptrdiff_t>(i * dims),
                                points.begin() + static_cast<std::ptrdiff_t>((i + 1) * dims));
        fitness[i] = memo_.at(key);
      } else {
        fitness[i] = loss[slot[i]];
      }
    }
    candidates_ += fresh.size();
    measured_.insert(measured_.end(), fresh.begin(), fresh.end());
  }

  /// The candidate whose loss the optimizer saw for `point`: the point itself, or the measured
  /// candidate it stood within the resolution of.
  std::vector<double> measured(std::span<const double> point) const {
    std::vector<double> key(point.begin(), point.end());
    const auto it = stand_in_.find(key);
    return it == stand_in_.end() ? key : it->second;
  }

  /// The loss of history_[index], a complete capped candidate, with its capped fits run to the
  /// end (no cap), each warm-started from its own unfinished solution; its other folds keep
  /// their scores. The fits count in fits_ and fit_seconds_.
  double finish(std::size_t index) {
    const Unfinished& u = unfinished_.at(index);
    std::vector<svr::PathTask> paths;
    std::vector<std::size_t> fold_of;
    for (std::size_t f = 0; f < folds_.size(); ++f) {
      if (u.duals[f] == nullptr) continue;
      svr::PathTask p = task_for(u.point, f);  // no cap
      p.warm = u.duals[f].get();
      paths.push_back(std::move(p));
      fold_of.push_back(f);
    }
    const std::vector<svr::PathScores> scores =
        svr::run_paths(scoring_, paths, options_.pool, workspaces_);
    std::vector<double> sse = u.sse;
    for (std::size_t k = 0; k < paths.size(); ++k) {
      sse[fold_of[k]] = scores[k].sse[0];
      fit_seconds_ += scores[k].seconds[0];
      ++fits_;
      ++warm_fits_;
    }
    return std::sqrt(std::accumulate(sse.begin(), sse.end(), 0.0) /
                     static_cast<double>(test_rows_));
  }

  std::size_t candidates_ = 0, repeats_ = 0, fits_ = 0, warm_fits_ = 0, raced_ = 0;
  std::size_t near_repeats_ = 0;  // candidates within the resolution of a measured one
  std::size_t capped_fits_ = 0;
  std::vector<Candidate> history_;
  double fit_seconds_ = 0;

 private:
  struct Solved {
    std::vector<double> point;
    std::shared_ptr<const svr::DualSolution> dual;
    double seconds;
  };
  // The fit of `point` on fold f, one C (× the stride), without a cap or a warm start.
  svr::PathTask task_for(const std::vector<double>& point, std::size_t f) const {
    svr::PathTask p;
    p.fold = f;
    p.params = to_params_(point);
    p.params.c *= c_scale_;
    p.c_values = {p.params.c};
    return p;
  }

  // A complete candidate with a capped fit: its point, each fold's squared errors, and the
  // unfinished solution of each fold that hit the cap (null where the fit finished).
  struct Unfinished {
    std::vector<double> point;
    std::vector<double> sse;
    std::vector<std::shared_ptr<const svr::DualSolution>> duals;
  };
  struct FoldState {
    std::unique_ptr<svr::TrainingSet> set;
    svr::Data test;
    std::vector<std::size_t> test_rows;  // 0 … test.rows − 1
    std::vector<Solved> solved;          // read concurrently during a batch, changed only between
  };

  // The solved candidate nearest to `point` in log coordinates (ties: the latest), optionally
  // only among those with the same kernel (σ).
  static const Solved* nearest(const FoldState& fold, const std::vector<double>& point,
                               bool same_kernel) {
    const Solved* best = nullptr;
    double best_d = INFINITY;
    for (const Solved& s : fold.solved) {
      if (same_kernel && s.point[1] != point[1]) continue;
      double d = 0;
      for (std::size_t j = 0; j < point.size(); ++j)
        d += (s.point[j] - point[j]) * (s.point[j] - point[j]);
      if (d <= best_d) best_d = d, best = &s;
    }
    return best;
  }

  // The warm start of a fit (docs/tuning.md, "Speed"): the nearest solved candidate with the same
  // kernel, whose gradient is rescaled rather than rebuilt; else the nearest of all when it lies
  // within 0.3 decade in both C and σ. Rebuilding the gradient for another σ costs about one pass
  // over the kernel, which a near solution's saved iterations repay many times on the C = 1000
  // edge; on the paper's campaign 0.2, 0.3, 0.5 decade and any distance took as many iterations.
  static constexpr double kNearLog10 = 0.3;
  // The solutions kept as warm starts, per fold: a search of the paper's size on its campaign
  // keeps every one (200 candidates of 207 kB: 4,320 rows), which took a quarter fewer SMO
  // iterations than keeping the last two batches (docs/tuning.md, "How far a warm start
  // reaches").
  static constexpr std::size_t kKeptBytesPerFold = std::size_t{48} << 20;
  // A DualSolution's three vectors of 2l doubles, and how many a fold keeps (at least one).
  static std::size_t solution_bytes(const svr::TrainingSet& set) {
    return 3 * 2 * set.size() * sizeof(double);
  }
  static std::size_t kept_solutions(const svr::TrainingSet& set) {
    return std::max<std::size_t>(1,
                                 kKeptBytesPerFold / std::max<std::size_t>(1, solution_bytes(set)));
  }
  static const svr::DualSolution* warm_start_for(const FoldState& fold,
                                                 const std::vector<double>& point) {
    if (const Solved* s = nearest(fold, point, true)) return s->dual.get();
    const Solved* s = nearest(fold, point, false);
    if (s == nullptr || std::fabs(s->point[0] - point[0]) > kNearLog10 ||
        std::fabs(s->point[1] - point[1]) > kNearLog10)
      return nullptr;
    return s->dual.get();
  }

  static double guessed_seconds(const FoldState& fold, const std::vector<double>& point) {
    const Solved* s = nearest(fold, point, false);
    return s ? s->seconds : INFINITY;
  }

  static double chebyshev(const std::vector<double>& a, const std::vector<double>& b) {
    double d = 0;
    for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::fabs(a[k] - b[k]));
    return d;
  }

  // The point of `points` nearest `key` (largest coordinate difference, in decades) if within
  // the resolution, the first of equals, and its distance; nullptr when none is.
  std::pair<const std::vector<double>*, double> nearest_within(
      const std::vector<std::vector<double>>& points, const std::vector<double>& key) const {
    const std::vector<double>* out = nullptr;
    double best = options_.candidate_resolution;
    for (const std::vector<double>& p : points) {
      const double d = chebyshev(p, key);
      if (out == nullptr ? d <= best : d < best) {
        out = &p;
        best = d;
      }
    }
    return {out, best};
  }

  // The folds by the best candidate's squared error on them, largest first (ties: in order):
  // the fold most likely to take a poor candidate past the bound runs first.
  std::vector<std::size_t> fold_order() const {
    std::vector<std::size_t> order(folds_.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [this](std::size_t a, std::size_t b) {
      return best_fold_sse_[a] > best_fold_sse_[b];
    });
    return order;
  }

  const TuneOptions& options_;
  ToParams to_params_;
  double c_scale_ = 1;  // the stride: C of every fit on every k-th training row
  std::vector<FoldState> folds_;
  std::vector<svr::ScoringFold> scoring_;  // folds_ as the engine sees them
  std::size_t test_rows_ = 0;              // held-out rows over all folds
  double best_loss_ = INFINITY;            // of the complete candidates of earlier batches
  std::vector<double> best_fold_sse_;      // its squared error on each fold
  // One workspace per fit running at once, kept for the whole search: each fit reuses the
  // memory of an earlier one instead of new pages.
  svr::WorkspacePool workspaces_;
  std::vector<std::string> fold_names_;
  std::map<std::vector<double>, double> memo_;
  std::vector<std::vector<double>> measured_;  // every candidate fitted, in order
  // A candidate within the resolution of a measured one, and that one.
  std::map<std::vector<double>, std::vector<double>> stand_in_;
  std::int64_t max_iterations_ = 0;               // of each fit (smo_iterations_per_row); 0: no cap
  std::map<std::size_t, Unfinished> unfinished_;  // by index in history_
};

}  // namespace fogdrift::tune
