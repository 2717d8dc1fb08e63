// Shared by the benchmarks that run LIBSVM beside fogdrift in one process: dense fogdrift data
// as LIBSVM's svm_problem, the cross-validation folds of a dataset fitted both ways, and
// wall-clock helpers.
#pragma once

#include <svm.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/svr.hpp"
#include "fogdrift/svr/workspace.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift::bench {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct LibsvmData {
  std::vector<svm_node> nodes;
  std::vector<svm_node*> rows;
  std::vector<double> y;
  svm_problem prob{};
  explicit LibsvmData(const svr::Data& d) : nodes(d.rows * (d.cols + 1)), rows(d.rows), y(d.y) {
    for (std::size_t i = 0; i < d.rows; ++i) {
      svm_node* r = nodes.data() + i * (d.cols + 1);
      for (std::size_t k = 0; k < d.cols; ++k) r[k] = {static_cast<int>(k + 1), d.row(i)[k]};
      r[d.cols] = {-1, 0};
      rows[i] = r;
    }
    prob.l = static_cast<int>(d.rows);
    prob.y = y.data();
    prob.x = rows.data();
  }
  // prob points into the vectors' heap buffers: a move keeps them, a copy would not.
  LibsvmData(LibsvmData&&) = default;
  LibsvmData(const LibsvmData&) = delete;
  LibsvmData& operator=(const LibsvmData&) = delete;
};

/// One cold LIBSVM ε-SVR fit (RBF, shrinking, the given cache) and its squared error on `test`.
inline double libsvm_fold_sse(const LibsvmData& train, const LibsvmData& test, const svr::Params& p,
                              double cache_mb) {
  svm_parameter sp{};
  sp.svm_type = EPSILON_SVR;
  sp.kernel_type = RBF;
  sp.gamma = p.kernel.gamma;
  sp.cache_size = cache_mb;
  sp.eps = p.tolerance;
  sp.C = p.c;
  sp.p = p.epsilon;
  sp.shrinking = 1;
  svm_model* m = svm_train(&train.prob, &sp);
  double sse = 0;
  for (int i = 0; i < test.prob.l; ++i) {
    const double e = svm_predict(m, test.prob.x[i]) - test.y[static_cast<std::size_t>(i)];
    sse += e * e;
  }
  svm_free_and_destroy_model(&m);
  return sse;
}

/// A dataset's cross-validation folds (tune::grouped_folds), standardised as the tuner does,
/// held both as fogdrift training sets and as LIBSVM problems, so one candidate can be scored
/// on every fold by each engine, cold and on one thread, and timed.
class FoldPair {
 public:
  FoldPair(const Dataset& data, const tune::CvOptions& cv) : folds_(tune::grouped_folds(data, cv)) {
    for (const auto& f : folds_) {
      splits_.push_back(tune::scale_split(data, f.train_rows, f.test_rows));
      const tune::ScaledSplit& sp = splits_.back();
      lib_train_.emplace_back(sp.train);
      lib_test_.emplace_back(sp.test);
      sets_.push_back(std::make_unique<svr::TrainingSet>(sp.train));
      test_rows_.emplace_back(sp.test.rows);
      std::iota(test_rows_.back().begin(), test_rows_.back().end(), std::size_t{0});
      rows_ += sp.test.rows;
    }
  }
  std::size_t folds() const { return folds_.size(); }

  /// The floor of a fit: every row of the largest fold's kernel matrix computed once from the
  /// training set the fits use, one thread, seconds.
  double kernel_pass_s(const svr::Kernel& kernel) const {
    const auto largest =
        std::max_element(sets_.begin(), sets_.end(),
                         [](const auto& a, const auto& b) { return a->size() < b->size(); });
    const svr::TrainingSet& set = **largest;
    std::vector<float> row(set.size());
    float sink = 0;
    const auto t0 = Clock::now();
    for (std::size_t i = 0; i < set.size(); ++i) {
      set.kernel_row(kernel, i, row.data());
      sink += row[i];
    }
    const double s = seconds_since(t0);
    if (!(sink >= 0)) std::abort();  // uses the rows, so the passes are not elided; K ≥ 0
    return s;
  }

  /// One candidate on every fold: each engine's summed time and its CV loss, the RMSE over all
  /// held-out rows (the tuner's loss). Without `with_libsvm`, fogdrift's alone (LIBSVM's time
  /// and loss NaN).
  struct Scored {
    double fogdrift_s = 0, libsvm_s = 0;
    double fogdrift_loss = 0, libsvm_loss = 0;
  };
  Scored score(const svr::Params& p, double cache_mb, bool with_libsvm = true) {
    Scored out;
    double sse_lib = 0, sse_ours = 0;
    if (!with_libsvm) out.libsvm_s = sse_lib = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t f = 0; f < folds_.size(); ++f) {
      auto t0 = Clock::now();
      if (with_libsvm) {
        sse_lib += libsvm_fold_sse(lib_train_[f], lib_test_[f], p, cache_mb);
        out.libsvm_s += seconds_since(t0);
      }
      t0 = Clock::now();
      const svr::FitResult fit = svr::fit(*sets_[f], p, nullptr, &workspace_);
      sse_ours += svr::path_squared_errors(*sets_[f], std::span<const svr::FitResult>(&fit, 1),
                                           splits_[f].test, test_rows_[f])[0];
      out.fogdrift_s += seconds_since(t0);
    }
    out.libsvm_loss = std::sqrt(sse_lib / static_cast<double>(rows_));
    out.fogdrift_loss = std::sqrt(sse_ours / static_cast<double>(rows_));
    return out;
  }

 private:
  std::vector<tune::Fold> folds_;
  std::vector<tune::ScaledSplit> splits_;
  std::vector<LibsvmData> lib_train_, lib_test_;
  std::vector<std::unique_ptr<svr::TrainingSet>> sets_;
  std::vector<std::vector<std::size_t>> test_rows_;  // 0 … rows − 1 of each held-out fold
  std::size_t rows_ = 0;
  svr::Workspace workspace_;  // the memory reuse the tuner's fits have too
};

}  // namespace fogdrift::bench
