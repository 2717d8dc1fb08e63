#include "fogdrift/svr/kernel.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/memory.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/workspace.hpp"
#include "svr/loops.hpp"
#include "svr/rows.hpp"
#include "svr/workspace_state.hpp"

namespace fogdrift::svr {

namespace {

constexpr std::array<EnumName<KernelType>, 2> kKernelTypeNames = {
    {{KernelType::rbf, "rbf"}, {KernelType::linear, "linear"}}};

}  // namespace

std::string_view to_string(KernelType type) {
  return name_in(kKernelTypeNames, type);
}

double Kernel::sigma() const {
  return 1.0 / std::sqrt(2.0 * gamma);
}

double Kernel::operator()(const double* a, const double* b, std::size_t dims) const {
  double sum = 0;
  if (type == KernelType::linear) {
    for (std::size_t k = 0; k < dims; ++k) sum += a[k] * b[k];
    return sum;
  }
  for (std::size_t k = 0; k < dims; ++k) {
    const double d = a[k] - b[k];
    sum += d * d;
  }
  // Below −746 the exponential is exactly 0 in double; skipping std::exp there avoids its slow
  // underflow path, which narrow kernels hit for most support vectors.
  const double arg = -gamma * sum;
  return arg < -746.0 ? 0.0 : std::exp(arg);
}

TrainingSet::TrainingSet(Data data) : TrainingSet(std::move(data), Options{}) {}

TrainingSet::TrainingSet(Data data, const Options& options) : data_(std::move(data)) {
  validate(data_);
  const std::size_t n = data_.rows, d = data_.cols;
  if (n > kMaxRows)
    throw ResourceError(fmt::format(
        "a training set of {} rows: the SVR engine takes at most 2^30 = {} (its solvers index "
        "2·rows variables with 32-bit integers)",
        n, kMaxRows));
  const double matrix_mb = static_cast<double>(n) * static_cast<double>(n) * 4.0 / (1 << 20);
  const bool distances = d >= options.distance_min_features && options.distance_budget_mb > 0 &&
                         matrix_mb <= options.distance_budget_mb;
  // The feature-major copy and the norms, and the distance matrix when it is kept.
  const std::uint64_t need = 8 * static_cast<std::uint64_t>(n) * (2 * d + 1) +
                             (distances ? 4 * static_cast<std::uint64_t>(n) * n : 0);
  require_memory_beside_reserve(need, fmt::format("a training set of {} rows × {} features", n, d),
                                "Fewer rows or features would fit.");
  feature_major_.resize(n * d);
  squared_norms_.resize(n);
  rows_f32_.resize(n * d);
  feature_major_f32_.resize(n * d);
  for (std::size_t i = 0; i < n; ++i) {
    double sq = 0;
    for (std::size_t k = 0; k < d; ++k) {
      const double v = data_.x[i * d + k];
      feature_major_[k * n + i] = v;
      rows_f32_[i * d + k] = feature_major_f32_[k * n + i] = static_cast<float>(v);
      sq += v * v;
    }
    squared_norms_[i] = sq;
  }
  if (distances) {
    distances_.resize(n * n);
    auto fill = [&](std::size_t i) {
      detail::loops().distance_row(row_f32(i), feature_major_f32_.data(), n, n, d,
                                   distances_.data() + i * n);
    };
    if (options.pool != nullptr) {
      options.pool->parallel_for(n, fill);
    } else {
      for (std::size_t i = 0; i < n; ++i) fill(i);
    }
  }
}

std::size_t TrainingSet::bytes() const {
  return (data_.x.size() + data_.y.size() + data_.weight.size() + feature_major_.size() +
          squared_norms_.size()) *
             sizeof(double) +
         (rows_f32_.size() + feature_major_f32_.size() + distances_.size()) * sizeof(float);
}

void TrainingSet::kernel_row(const Kernel& kernel, std::size_t i, float* out,
                             KernelArithmetic arithmetic) const {
  const std::size_t n = data_.rows, d = data_.cols;
  if (kernel.type == KernelType::linear) {
    detail::loops().linear_row(data_.row(i), feature_major_.data(), n, n, d, out);
  } else if (arithmetic == KernelArithmetic::libsvm) {
    detail::loops().libsvm_rbf_row(data_.row(i), squared_norms_[i], feature_major_.data(), n,
                                   squared_norms_.data(), n, d, kernel.gamma, out);
  } else if (!distances_.empty()) {
    detail::loops().rbf_row_from_distances(distances_.data() + i * n, n, kernel.gamma, out);
  } else {
    detail::loops().rbf_row(row_f32(i), feature_major_f32_.data(), n, n, d, kernel.gamma, out);
  }
}

void TrainingSet::kernel_row_of(const Kernel& kernel, const double* x, float* out,
                                KernelArithmetic arithmetic) const {
  const std::size_t n = data_.rows, d = data_.cols;
  if (kernel.type == KernelType::linear) {
    detail::loops().linear_row(x, feature_major_.data(), n, n, d, out);
  } else if (arithmetic == KernelArithmetic::libsvm) {
    double sq = 0;  // summed in feature order, as the set's own norms
    for (std::size_t k = 0; k < d; ++k) sq += x[k] * x[k];
    detail::loops().libsvm_rbf_row(x, sq, feature_major_.data(), n, squared_norms_.data(), n, d,
                                   kernel.gamma, out);
  } else {
    const std::vector<float> x_f32(x, x + d);
    detail::loops().rbf_row(x_f32.data(), feature_major_f32_.data(), n, n, d, kernel.gamma, out);
  }
}

double TrainingSet::kernel_diagonal(const Kernel& kernel, std::size_t i,
                                    KernelArithmetic arithmetic) const {
  const double sq = squared_norms_[i];
  if (kernel.type == KernelType::linear) return sq;
  if (arithmetic == KernelArithmetic::libsvm)
    return std::exp(-kernel.gamma * ((sq + sq) - 2.0 * sq));
  return 1.0;  // kernel_exp(−γ·0), exactly (src/svr/loops.hpp)
}

KernelCache::KernelCache(const TrainingSet& set, const Kernel& kernel, double cache_mb,
                         Workspace* workspace, KernelArithmetic arithmetic)
    : set_(set),
      kernel_(kernel),
      arithmetic_(arithmetic),
      n_(set.size()),
      own_workspace_(workspace != nullptr ? nullptr : std::make_unique<Workspace>()),
      workspace_(workspace != nullptr ? workspace : own_workspace_.get()) {
  const double row_bytes = static_cast<double>(n_) * sizeof(float);
  const double rows = std::floor(std::max(0.0, cache_mb) * (1 << 20) / row_bytes);
  // At least two rows (the solver holds two at once), at most every row.
  capacity_ = static_cast<std::size_t>(std::max(2.0, std::min(rows, static_cast<double>(n_))));
  diagonal_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) diagonal_[i] = set.kernel_diagonal(kernel, i, arithmetic_);
  slot_of_row_.assign(n_, -1);
  row_of_slot_.reserve(capacity_);
  prev_.reserve(capacity_);
  next_.reserve(capacity_);
  slots_ = std::make_unique<detail::RowArena>(capacity_, n_, &workspace_->state().blocks);
}

KernelCache::~KernelCache() {
  workspace_->state().forget(*this);  // the order's rows may have come from this cache
}

void KernelCache::unlink(std::int32_t s) {
  if (prev_[s] >= 0)
    next_[prev_[s]] = next_[s];
  else
    head_ = next_[s];
  if (next_[s] >= 0)
    prev_[next_[s]] = prev_[s];
  else
    tail_ = prev_[s];
}

void KernelCache::push_front(std::int32_t s) {
  prev_[s] = -1;
  next_[s] = head_;
  if (head_ >= 0) prev_[head_] = s;
  head_ = s;
  if (tail_ < 0) tail_ = s;
}

void KernelCache::touch(std::int32_t s) {
  if (head_ == s) return;
  unlink(s);
  push_front(s);
}

const float* KernelCache::row(std::size_t i) {
  std::int32_t s = slot_of_row_[i];
  if (s >= 0) {
    touch(s);
    return slots_->row(static_cast<std::size_t>(s));
  }
  if (used_ < capacity_) {
    s = static_cast<std::int32_t>(used_++);
    row_of_slot_.push_back(-1);
    prev_.push_back(-1);
    next_.push_back(-1);
  } else {
    s = tail_;  // evict the least recently used row
    unlink(s);
    slot_of_row_[row_of_slot_[s]] = -1;
  }
  row_of_slot_[s] = static_cast<std::int32_t>(i);
  slot_of_row_[i] = s;
  push_front(s);
  float* out = slots_->row(static_cast<std::size_t>(s));
  set_.kernel_row(kernel_, i, out, arithmetic_);
  ++rows_computed_;
  return out;
}

}  // namespace fogdrift::svr
