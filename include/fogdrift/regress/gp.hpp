// A Gaussian-process regressor (docs/gp.md): the drift as the posterior mean of a zero-mean GP on
// the standardised features, with a squared-exponential kernel of one length scale for all inputs
// (or one per input, ARD) and white noise,
//   k(x, x') = s² · exp(−½ Σ_k (x_k − x'_k)² / ℓ_k²) + σn² · [x = x']           (docs/gp.md eq. 1)
//   f̄(x)     = Σ_i α_i · s² · exp(−½ Σ_k (x_k − p_ik)² / ℓ_k²),  α = (K + σn² I)⁻¹ y     (eq. 2)
//   V[f(x)]  = s² − k*ᵀ (K + σn² I)⁻¹ k*                                            (eq. 3)
// The hyperparameters are chosen one of two ways (GpSelection): by grouped cross-validation of ℓ
// and λ = σn²/s² through fogdrift's search (gp_search.hpp, the default), or all of them by
// maximising the log marginal likelihood of the training rows (eq. 4) by L-BFGS over their
// logarithms within fixed bounds (train_gp below). Either way one data set gives one model.
// Exact inference costs O(n³): the GP keeps at most `max_points` training rows, evenly spaced in
// row order (a subset of data), and the same rows choose the hyperparameters.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "fogdrift/base/data.hpp"
#include "fogdrift/base/regressor.hpp"

namespace fogdrift {

struct GpHyper {
  double signal_variance = 1;        ///< s², in the standardised target's units squared
  std::vector<double> length_scale;  ///< ℓ_k, one per input, in standardised feature units
  double noise_variance = 0.1;       ///< σn²
};

/// The bounds the likelihood search keeps each hyperparameter in (docs/gp.md, "By the marginal
/// likelihood").
struct GpBounds {
  double signal_min = 1e-3, signal_max = 1e3;
  double length_min = 1e-2, length_max = 1e3;
  double noise_min = 1e-6, noise_max = 10;
};

/// How train chooses the hyperparameters (docs/gp.md, "Choosing the hyperparameters").
enum class GpSelection {
  cv,         ///< ℓ and λ = σn²/s² by grouped cross-validation (gp_search.hpp); s² by eq. 7
  likelihood  ///< every hyperparameter by the marginal likelihood (train_gp)
};
/// "cv", "likelihood".
std::string_view to_string(GpSelection selection);
GpSelection parse_gp_selection(const std::string& text, const std::string& option = "gp_fit");
/// "cv, likelihood".
std::string gp_selection_names();

/// The box of the cross-validated search, in natural units; it searches log10 of each.
struct GpSearchBox {
  double length_min = 0.05, length_max = 20;  ///< ℓ, standardised feature units (as SVR's σ)
  double ratio_min = 1e-6, ratio_max = 1;     ///< λ = σn²/s²
};

struct GpOptions {
  GpSelection selection = GpSelection::cv;
  std::size_t max_points = 800;     ///< training rows the GP keeps, 10 … 4000
  std::size_t max_iterations = 80;  ///< L-BFGS iterations of the likelihood search, 1 … 10000
  /// One length scale per input (likelihood only: a search of one per feature by
  /// cross-validation would need far more candidates); false: one for all.
  bool ard = false;
  GpBounds bounds;
  GpSearchBox box;
};

/// Throws OptionError naming the field (gp_points, gp_iterations, gp_kernel, gp_bounds,
/// gp_box) for a value outside its range or settings that do not go together.
void validate(const GpOptions& options);

struct Gp {
  static constexpr std::string_view kType = "gp";
  std::size_t inputs = 0;
  GpHyper hyper;
  std::vector<double> points;  ///< the rows kept, size() × inputs, row-major
  std::vector<double> alpha;   ///< (K + σn² I)⁻¹ y, one per row kept (eq. 2)

  std::size_t size() const { return alpha.size(); }
  /// f̄(x) for one sample of `inputs` values (eq. 2); no allocation.
  double predict(const double* x) const noexcept;
};

/// Gp with its Cholesky factor, for the predictive variance (eq. 3). The factor has size()²
/// numbers, so model files do not carry it; fit_gp and factor() make it.
struct GpPosterior {
  Gp gp;
  std::vector<double> lower;  ///< L with L·Lᵀ = K + σn² I, size() × size(), row-major
  /// V[f(x)], the variance of the latent drift at x (eq. 3), ≥ 0.
  double variance(const double* x) const;
  /// log p(y | X, θ) (eq. 4) of the rows it was fitted on, whose targets are `y`.
  double log_likelihood(std::span<const double> y) const;
};

/// The GP of `train` with the given hyperparameters (no search). Throws OptionError when
/// K + σn² I is not positive definite in floating point.
GpPosterior fit_gp(const Data& train, const GpHyper& hyper);
/// The factor of a Gp read from a file.
GpPosterior factor(const Gp& gp);

/// log p(y | X, θ) (eq. 4) and its gradient with respect to θ = (log s², log ℓ_1 … log ℓ_d,
/// log σn²) (eq. 5); with one length scale, θ = (log s², log ℓ, log σn²).
struct GpLikelihood {
  double value = 0;
  std::vector<double> gradient;
};
GpLikelihood log_marginal_likelihood(const Data& train, const GpHyper& hyper, bool ard = true);

/// The rows a GP of at most `max_points` keeps from `rows`: all of them, or max_points evenly
/// spaced, row ⌊i·rows / max_points⌋.
std::vector<std::size_t> gp_rows(std::size_t rows, std::size_t max_points);

struct GpSummary {
  double log_likelihood = 0;  ///< at the chosen hyperparameters
  std::size_t iterations = 0, evaluations = 0;
  std::size_t points = 0;  ///< rows kept
  bool converged = false;  ///< the search stopped on its tolerance, not its iteration limit
  /// The cross-validated search (gp_search.hpp): GPs fitted on folds, and candidates stopped
  /// by racing before their last fold; 0 for the likelihood search.
  std::size_t fold_fits = 0, raced = 0;
};
struct GpFit {
  GpPosterior posterior;
  GpSummary summary;
};
/// Chooses the hyperparameters on gp_rows(train.rows, max_points) by the likelihood search,
/// starting from s² = 1, ℓ_k = √d, σn² = 0.1, and fits the GP there.
GpFit train_gp(const Data& train, const GpOptions& options);

/// The GP as JSON text, the regressor object of a model file without its "type": {"inputs",
/// "signal_variance", "length_scale", "noise_variance", "points", "alpha"}.
std::string to_json(const Gp& gp);
/// Parses to_json's text. Throws InputError(source, 0, 0, "FIELD: rule") for a missing or
/// mistyped field, a hyperparameter that is not finite and > 0, or sizes that disagree.
Gp regressor_from_json(std::type_identity<Gp>, const std::string& text, const std::string& source);
inline std::size_t input_count(const Gp& gp) {
  return gp.inputs;
}
/// The C of f̄ (eq. 2): the rows kept, 1 / 2ℓ_k², and s²·α_i, the operations of predict().
CRegressor to_c(const Gp& gp, const CNames& names);

}  // namespace fogdrift
