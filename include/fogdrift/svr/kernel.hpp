// Kernels, training data and kernel rows for the ε-SVR engine (docs/method.md eq. 7).
//
// The RBF kernel is K(x, x') = exp(−‖x − x'‖² / (2σ²)) in the paper's σ, which is LIBSVM's
// exp(−γ‖x − x'‖²) with γ = 1/(2σ²). Training evaluates it as LIBSVM does, through
// ‖x‖² + ‖x'‖² − 2x·x' in double and a float result, so the engine sees the same kernel matrix.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/base/data.hpp"
#include "fogdrift/svr/workspace.hpp"

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::svr {
namespace detail {
class RowArena;
}  // namespace detail

enum class KernelType { linear, rbf };

/// "linear" or "rbf".
std::string_view to_string(KernelType type);

struct Kernel {
  KernelType type = KernelType::rbf;
  double gamma = 1.0;  ///< RBF: γ = 1/(2σ²), in 1/(feature unit)²; unused for linear

  static Kernel rbf_gamma(double gamma) { return {KernelType::rbf, gamma}; }
  /// The paper's parameterisation (eq. 7); σ in feature units.
  static Kernel rbf_sigma(double sigma) { return {KernelType::rbf, 1.0 / (2.0 * sigma * sigma)}; }
  static Kernel linear() { return {KernelType::linear, 0.0}; }
  /// σ = 1/√(2γ).
  double sigma() const;

  /// K(a, b) evaluated as LIBSVM's prediction does (Σ(a_k − b_k)² for RBF), in double.
  double operator()(const double* a, const double* b, std::size_t dims) const;

  bool operator==(const Kernel&) const = default;
};

/// The engine's training data is fogdrift's (base/data.hpp).
using Data = fogdrift::Data;
using fogdrift::validate;

/// How the rows of the RBF kernel are computed (docs/svr.md, "The kernel in float"). Either way a
/// row is stored in float.
enum class KernelArithmetic {
  /// In float: the features rounded to float, Σ_f (x_if − x_jf)² with fused multiply-adds, and an
  /// exponential in float within two float steps of e^y; a row at about a third of the cost.
  /// fogdrift's hyperparameter searches use it.
  single,
  /// As LIBSVM: (‖x_i‖² + ‖x_j‖²) − 2·x_i·x_j and the exponential in double, rounded to float, so
  /// that a fit gives svm-train's and scikit-learn's model (the LIBSVM path: to the iteration).
  /// The default.
  libsvm,
};

/// A data set prepared once for many fits: feature-major copies for vectorised kernel rows (in
/// double for the linear kernel, in float for the RBF kernel, whose rows are computed in float:
/// docs/svr.md, "The kernel in float"), the squared norms, and, when it fits the memory budget
/// and pays off, the matrix of pairwise squared distances, from which a row of any σ costs one
/// exponential per entry.
class TrainingSet {
 public:
  struct Options {
    /// Largest distance matrix to keep, MB (float, N² × 4 bytes). The matrix is built only when
    /// reading a row of it is cheaper than recomputing the row from the features, that is when
    /// there are at least `distance_min_features` features. 0 disables it.
    double distance_budget_mb = 1024;
    std::size_t distance_min_features = 24;
    ThreadPool* pool = nullptr;  ///< builds the distance matrix in parallel when given
  };

  /// The most rows a training set may have: the solvers index 2·rows variables with 32-bit
  /// integers.
  static constexpr std::size_t kMaxRows = std::size_t{1} << 30;

  /// Validates `data` (InputError) and checks that its copies fit in memory (ResourceError,
  /// memory.hpp; also for more than kMaxRows rows).
  explicit TrainingSet(Data data);
  TrainingSet(Data data, const Options& options);

  const Data& data() const { return data_; }
  std::size_t size() const { return data_.rows; }
  std::size_t dims() const { return data_.cols; }
  bool has_distances() const { return !distances_.empty(); }
  /// Bytes held (features in double twice and in float twice, norms, distances).
  std::size_t bytes() const;

  /// Writes row i of the kernel matrix (size() floats). Safe to call from several threads. The
  /// distance matrix, when kept, serves the single arithmetic.
  void kernel_row(const Kernel& kernel, std::size_t i, float* out,
                  KernelArithmetic arithmetic = KernelArithmetic::libsvm) const;
  /// The kernel between a point `x` (dims() values, not a sample of the set) and every sample,
  /// as kernel_row forms a row from the features (size() floats). Safe from several threads.
  void kernel_row_of(const Kernel& kernel, const double* x, float* out,
                     KernelArithmetic arithmetic = KernelArithmetic::libsvm) const;
  /// K(x_i, x_i) in double, LIBSVM's QD, as the rows of that arithmetic hold it.
  double kernel_diagonal(const Kernel& kernel, std::size_t i,
                         KernelArithmetic arithmetic = KernelArithmetic::libsvm) const;
  /// ‖x_i‖², summed over the features in order, as the kernel rows use it.
  double squared_norm(std::size_t i) const { return squared_norms_[i]; }
  /// Sample i's features rounded to float, contiguous, as the RBF rows read them.
  const float* row_f32(std::size_t i) const { return rows_f32_.data() + i * data_.cols; }

 private:
  Data data_;
  std::vector<double> feature_major_;  // cols × rows
  std::vector<double> squared_norms_;
  std::vector<float> rows_f32_;           // rows × cols
  std::vector<float> feature_major_f32_;  // cols × rows
  std::vector<float> distances_;          // rows × rows, when kept
};

/// Kernel rows for one fit, or for a sequence of fits of one kernel (fit_c_path), with a
/// least-recently-used cache bounded in bytes (LIBSVM's -m). Not thread-safe: each fit owns one.
class KernelCache {
 public:
  /// `cache_mb` bounds the cached rows; at least two rows are always kept. The rows' memory, and
  /// everything the solvers keep between fits on this cache, live in `workspace` when one is
  /// given (it must outlive the cache), or in a workspace of the cache's own.
  KernelCache(const TrainingSet& set, const Kernel& kernel, double cache_mb,
              Workspace* workspace = nullptr,
              KernelArithmetic arithmetic = KernelArithmetic::libsvm);
  ~KernelCache();
  KernelCache(const KernelCache&) = delete;
  KernelCache& operator=(const KernelCache&) = delete;

  std::size_t size() const { return n_; }
  const Kernel& kernel() const { return kernel_; }
  KernelArithmetic arithmetic() const { return arithmetic_; }
  const TrainingSet& training_set() const { return set_; }
  /// The workspace of the fits on this cache: the pair solver takes its arrays from it and leaves
  /// its sample order there for the next fit on this cache.
  Workspace& workspace() const { return *workspace_; }
  /// Row i (size() floats). Valid until the next call to row().
  const float* row(std::size_t i);
  double diagonal(std::size_t i) const { return diagonal_[i]; }
  std::int64_t rows_computed() const { return rows_computed_; }
  std::size_t capacity_rows() const { return capacity_; }

 private:
  const TrainingSet& set_;
  Kernel kernel_;
  KernelArithmetic arithmetic_;
  std::size_t n_;
  std::size_t capacity_;
  std::vector<double> diagonal_;
  std::vector<std::int32_t> slot_of_row_;  // −1 when not cached
  std::vector<std::int32_t> row_of_slot_;
  std::vector<std::int32_t> prev_, next_;  // LRU list of slots; head_ most recent
  std::int32_t head_ = -1, tail_ = -1;
  std::unique_ptr<Workspace> own_workspace_;  // when none was given; outlives slots_
  Workspace* workspace_;
  std::unique_ptr<detail::RowArena> slots_;  // capacity_ rows, reserved, committed when written
  std::size_t used_ = 0;                     // slots handed out so far
  std::int64_t rows_computed_ = 0;

  void touch(std::int32_t slot);
  void unlink(std::int32_t slot);
  void push_front(std::int32_t slot);
};

}  // namespace fogdrift::svr
