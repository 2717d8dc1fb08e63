// ε-support-vector regression (docs/method.md §2 step 3): fit, predict, save and load.
//
//   f(x) = Σ_i (α_i⁺ − α_i⁻)·K(x_i, x) + b,   b = −ρ                          (eq. 6)
//
// fit() solves the dual with the SMO engine (smo_solver.hpp) and keeps the support vectors.
// Many fits of one data set share a TrainingSet; fit_batch() spreads candidates over a thread
// pool and fit_c_path() warm-starts a sweep over C. Each fit is single-threaded and
// deterministic, so results never depend on the thread count.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "fogdrift/base/regressor.hpp"
#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/smo_solver.hpp"
#include "fogdrift/svr/workspace.hpp"

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::svr {

struct Params {
  Kernel kernel;            ///< default RBF with γ = 1 (σ = 1/√2)
  double c = 1.0;           ///< regularisation C > 0 (LIBSVM -c)
  double epsilon = 0.1;     ///< half-width ε ≥ 0 of the insensitive tube, target units (-p)
  double tolerance = 1e-3;  ///< stopping tolerance > 0 (-e)
  bool shrinking = true;    ///< (-h)
  /// Kernel rows per fit, MB (-m): all of it for rows computed in the pair solver's order (90 %
  /// when they come from a distance matrix, 10 % for rows as computed; the LIBSVM path: half and
  /// half; fit_c_path's fits hand their rows on to the next, see SolverOptions). Rows live in
  /// blocks of transparent huge pages; a Workspace keeps the blocks of its last fit for the
  /// next one (at most two, so at most about this much per workspace stays committed between
  /// fits).
  double cache_mb = 200;
  std::int64_t max_iterations = 0;  ///< 0: LIBSVM's max(10⁷, 200·l)
  bool libsvm_path = false;  ///< SolverOptions::libsvm_path: LIBSVM's working sets one for one
  /// How the RBF kernel's rows are computed (kernel.hpp): LIBSVM's floats by default, as
  /// svm-train and scikit-learn compute them; `single` computes them in float at about a third
  /// of the cost, which fogdrift's hyperparameter searches use (docs/svr.md, "The kernel in
  /// float").
  KernelArithmetic kernel_arithmetic = KernelArithmetic::libsvm;
  bool conjugate = true;  ///< SolverOptions::conjugate: the pair solver's conjugate steps
  bool newton = true;     ///< SolverOptions::newton: the pair solver's free-set Newton steps
};

/// Names to use for each parameter in error messages (the CLI passes its flags).
struct ParamNames {
  std::string c = "C", gamma = "gamma", epsilon = "epsilon", tolerance = "tolerance",
              cache_mb = "cache_mb", max_iterations = "max_iterations",
              kernel_arithmetic = "kernel_arithmetic";
};

/// Throws OptionError naming the parameter: C ≤ 0, γ ≤ 0 (σ ≤ 0), ε < 0, tolerance ≤ 0, a cache
/// below 0 MB or a negative iteration limit, or any of them not finite; a kernel arithmetic that is
/// neither `single` nor `libsvm` (a value cast from elsewhere).
void validate(const Params& params, const ParamNames& names = {});

/// A trained regressor. predict() needs no allocation and is safe from several threads.
struct Model {
  static constexpr std::string_view kType = "svr";  ///< in model files (regressor.hpp)
  Kernel kernel;
  std::size_t dims = 0;
  std::vector<double> support_vectors;  ///< n_sv × dims, row-major
  std::vector<double> coef;             ///< α⁺ − α⁻ of each support vector
  double rho = 0;                       ///< f(x) = Σ coef·K − ρ

  std::size_t size() const { return coef.size(); }
  /// f(x) for one sample of `dims` features, exactly as LIBSVM's svm_predict.
  double predict(const double* x) const noexcept;
  /// f for every row of `x` (row-major, dims columns) into `out`; parallel when a pool is given.
  void predict(std::span<const double> x, std::span<double> out, ThreadPool* pool = nullptr) const;
  std::vector<double> predict(const Data& data, ThreadPool* pool = nullptr) const;
};

struct FitSummary {
  SolverSummary solver;
  std::size_t n_sv = 0;   ///< support vectors, α⁺ ≠ α⁻
  std::size_t n_bsv = 0;  ///< of which at the bound |α⁺ − α⁻| = C·weight
  double nu = 0;  ///< Σ|α⁺ − α⁻| / (C·Σweight), LIBSVM's printed "nu" (C·l without weights)
  double seconds = 0;  ///< wall time of the fit, kernel cache set-up included
};

struct FitResult {
  Model model;
  FitSummary summary;
  DualSolution dual;  ///< for warm starts of later fits of the same data
};

/// An upper bound on the memory one fit of `rows` samples × `dims` features holds beyond its
/// TrainingSet, in bytes: the kernel rows it may cache (params.cache_mb, at most the whole
/// kernel matrix) and its per-sample arrays. fit, fit_batch (times the fits running at once) and
/// fit_c_path compare it with available_memory() (memory.hpp) before they start, and throw
/// ResourceError when it does not fit. docs/svr.md, "Memory", compares it with measured peaks.
std::uint64_t fit_bytes(std::size_t rows, std::size_t dims, const Params& params);

/// Throws ResourceError when `concurrent` fits of `params` on `set` (fit_bytes each), and the
/// `kept_bytes` of solutions the caller keeps beside them (a search's warm starts), do not fit in
/// available_memory(). A search calls it once before its first batch.
void require_fit_memory(const TrainingSet& set, const Params& params, std::size_t concurrent,
                        std::uint64_t kept_bytes = 0);

/// Fits one model; Data::weight, when given, bounds sample i's variables by C·weight_i. `warm`
/// (optional) is a previous fit of the same TrainingSet. `workspace`
/// (optional, workspace.hpp) lends this fit the memory of the caller's earlier fits and keeps
/// this one's for the next; null: the fit's memory is its own and freed at the end. The result
/// is the same either way.
FitResult fit(const TrainingSet& set, const Params& params, const DualSolution* warm = nullptr,
              Workspace* workspace = nullptr);

/// Fits every parameter set, spread over the pool's threads (one fit per thread at a time, cache
/// budgets as given per fit, the largest C first), each running fit with a workspace of the
/// batch's own. Results in the order of `params`.
std::vector<FitResult> fit_batch(const TrainingSet& set, std::span<const Params> params,
                                 ThreadPool& pool);

/// Fits `base` at each C of `c_values` in the order given, each warm-started from the previous
/// one (the first from `warm`, when given), sharing one kernel cache and one workspace:
/// `workspace` when given (as for fit), or one of the path's own. Results in the order of
/// `c_values`.
std::vector<FitResult> fit_c_path(const TrainingSet& set, const Params& base,
                                  std::span<const double> c_values, Workspace* workspace = nullptr,
                                  const DualSolution* warm = nullptr);

/// The values of C of a path or a grid, all checked before the first fit (a path would find a
/// bad one only when it reaches it): OptionError(name) when there are none or one is not a
/// finite number > 0.
void validate_c_values(std::span<const double> c_values, const std::string& name = "C");

/// Σ (f_k(x) − y)² over `rows` of `data` for each fit k of `path` (fit_c_path's result on `set`:
/// one kernel, models differing in their coefficients), as a cross-validation scores a path.
/// RBF: each kernel value between a row and a training sample is computed once for every model,
/// in float as the solver's rows are (TrainingSet::kernel_row_of), so the sums are
/// Model::predict's to float rounding of the kernel (measured: 3e-6 relative at C = 50);
/// linear: from each model's primal weights, in double. Rows in order, one thread.
/// `arithmetic` is the kernel's, as the fits' Params::kernel_arithmetic.
std::vector<double> path_squared_errors(const TrainingSet& set, std::span<const FitResult> path,
                                        const Data& data, std::span<const std::size_t> rows,
                                        KernelArithmetic arithmetic = KernelArithmetic::libsvm);

/// The predictions behind path_squared_errors: f_k(x) for each of `rows` (outer) and each fit k
/// of `path` (inner), rows.size() × path.size(), computed as it computes them (any scorer can
/// then score a path: fogdrift.SVRGridSearchCV).
std::vector<double> path_predictions(const TrainingSet& set, std::span<const FitResult> path,
                                     const Data& data, std::span<const std::size_t> rows,
                                     KernelArithmetic arithmetic = KernelArithmetic::libsvm);

/// The instruction set the engine's inner loops run with: "avx512", "avx2" or "portable". The
/// fastest this processor has, or the one the environment variable FOGDRIFT_ISA names
/// (portable, avx2, avx512; unset, empty or auto for the fastest). Every one gives the same
/// kernel rows and the same steps through the dual, so the same model, bit for bit
/// (docs/reliability.md). Chosen at the first fit or call; throws OptionError naming
/// FOGDRIFT_ISA when it names an unknown set or one this processor lacks.
std::string_view instruction_set();

/// The model as JSON text: {"format": "fogdrift-svr", "version": 1, "kernel": …, "gamma": …,
/// "dims": …, "rho": …, "coef": […], "support_vectors": [[…], …]}. Numbers are printed with
/// the shortest text that reads back to the same double.
std::string to_json(const Model& model);
/// Parses to_json's output; `source` names the text in errors. Rejects another format, a
/// newer version, missing or extra keys and inconsistent sizes with an InputError.
Model model_from_json(const std::string& text, const std::string& source);
/// The Regressor parts (regressor.hpp): model_from_json, dims, and the C of f(x), RBF or linear,
/// summed with compensation (Kahan) because terms of C in the hundreds cancel to a z of order 1.
inline Model regressor_from_json(std::type_identity<Model>, const std::string& text,
                                 const std::string& source) {
  return model_from_json(text, source);
}
inline std::size_t input_count(const Model& model) {
  return model.dims;
}
CRegressor to_c(const Model& model, const CNames& names);
/// Atomic write of to_json's text.
void save_model(const Model& model, const std::filesystem::path& path);
Model load_model(const std::filesystem::path& path);

inline constexpr int kModelFormatVersion = 1;

}  // namespace fogdrift::svr
