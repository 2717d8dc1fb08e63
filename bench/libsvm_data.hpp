// Shared by the benchmarks that run LIBSVM beside fogdrift in one process: dense fogdrift data
// as LIBSVM's svm_problem, and wall-clock helpers.
#pragma once

#include <svm.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "fogdrift/svr/kernel.hpp"

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

}  // namespace fogdrift::bench
