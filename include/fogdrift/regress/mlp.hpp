// The BP baseline (docs/method.md §2, paper Table 2 "BP"): a one-hidden-layer perceptron
//   ŷ = w2ᵀ·tanh(W1·x + b1) + b2
// trained by back-propagation of the mean squared error with Adam (Kingma & Ba, ICLR 2015; the
// update of their Algorithm 1 with β1 = 0.9, β2 = 0.999, ε̂ = 1e-8) over the full batch, and
// early stopping on held-out recordings: training stops after `patience` epochs without a new
// best validation error and the weights of the best epoch are kept. Weights start from Glorot
// uniform draws of a seeded fogdrift::Rng, and full-batch updates have no order to shuffle, so a
// seed gives the same network on every machine. Inputs and target are expected standardised.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fogdrift/base/data.hpp"
#include "fogdrift/base/regressor.hpp"

namespace fogdrift {

struct MlpOptions {
  std::size_t hidden = 10;        ///< tanh units, 1 … 1000
  double learning_rate = 0.01;    ///< Adam step size α > 0
  std::size_t max_epochs = 3000;  ///< full-batch updates, ≥ 1
  std::size_t patience = 200;     ///< epochs without a better validation error before stopping
  std::uint64_t seed = 1;         ///< initial weights
};

/// Throws OptionError naming the field for a value outside its range.
void validate(const MlpOptions& options);

struct Mlp {
  static constexpr std::string_view kType = "mlp";  ///< in model files (regressor.hpp)
  std::size_t inputs = 0, hidden = 0;
  std::vector<double> w1;  ///< hidden × inputs, row-major
  std::vector<double> b1;  ///< hidden
  std::vector<double> w2;  ///< hidden
  double b2 = 0;

  /// ŷ for one sample of `inputs` values; no allocation.
  double predict(const double* x) const noexcept;
};

/// The network as JSON text, the regressor object of a model file without its "type":
/// {"activation": "tanh", "inputs", "hidden", "w1", "b1", "w2", "b2"}.
std::string to_json(const Mlp& mlp);
/// Parses to_json's text. Throws InputError(source, 0, 0, "FIELD: rule") for a missing or
/// mistyped field, another activation, or weights whose sizes disagree.
Mlp mlp_from_json(const std::string& text, const std::string& source);
/// The Regressor parts (regressor.hpp): mlp_from_json, inputs, and the C of ŷ.
inline Mlp regressor_from_json(std::type_identity<Mlp>, const std::string& text,
                               const std::string& source) {
  return mlp_from_json(text, source);
}
inline std::size_t input_count(const Mlp& mlp) {
  return mlp.inputs;
}
CRegressor to_c(const Mlp& mlp, const CNames& names);

enum class MlpStatus { early_stopped, epoch_limit };

struct MlpSummary {
  MlpStatus status = MlpStatus::epoch_limit;
  std::size_t epochs = 0;      ///< updates made
  std::size_t best_epoch = 0;  ///< epoch whose weights were kept
  double train_rmse = 0;       ///< at the best epoch
  double validation_rmse = 0;  ///< at the best epoch
  double seconds = 0;
};

struct MlpFit {
  Mlp model;
  MlpSummary summary;
};

/// Trains on `train`, stopping early on `validation` (same columns; when it has no rows, the
/// training error decides and the run ends at max_epochs or when it stalls for `patience`).
MlpFit fit_mlp(const Data& train, const Data& validation, const MlpOptions& options);

}  // namespace fogdrift
