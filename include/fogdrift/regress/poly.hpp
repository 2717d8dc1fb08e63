// The classical compensation baseline: the drift as a polynomial in the (standardised) features,
//   ŷ = Σ_m c_m · Π_k x_k^(e_mk)     over all monomials of total degree ≤ D,
// fitted by least squares with a tiny ridge (λ = ridge · mean diagonal of AᵀA, the constant
// term unpenalised) so that collinear temperature terms do not make the normal equations
// singular. fogdrift chooses D by grouped cross-validation (train.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fogdrift/base/data.hpp"
#include "fogdrift/base/regressor.hpp"

namespace fogdrift {

struct Poly {
  static constexpr std::string_view kType = "poly";  ///< in model files (regressor.hpp)
  std::size_t inputs = 0;
  std::size_t degree = 0;
  std::vector<std::uint8_t> exponents;  ///< terms × inputs, graded order, the constant first
  std::vector<double> coef;             ///< one per term

  std::size_t terms() const { return coef.size(); }
  /// ŷ for one sample of `inputs` values; no allocation.
  double predict(const double* x) const noexcept;
};

/// The polynomial as JSON text, the regressor object of a model file without its "type":
/// {"inputs", "degree", "exponents" (one row of exponents per term), "coef"}.
std::string to_json(const Poly& poly);
/// Parses to_json's text. Throws InputError(source, 0, 0, "FIELD: rule") for a missing or
/// mistyped field, an exponent outside 0 … degree, or rows that disagree with the inputs.
Poly poly_from_json(const std::string& text, const std::string& source);
/// The Regressor parts (regressor.hpp): poly_from_json, inputs, and the C of ŷ.
inline Poly regressor_from_json(std::type_identity<Poly>, const std::string& text,
                                const std::string& source) {
  return poly_from_json(text, source);
}
inline std::size_t input_count(const Poly& poly) {
  return poly.inputs;
}
CRegressor to_c(const Poly& poly, const CNames& names);

/// The monomials of total degree ≤ `degree` in `inputs` variables, in graded order
/// (C(inputs + degree, degree) of them), as rows of exponents.
std::vector<std::uint8_t> monomials(std::size_t inputs, std::size_t degree);

/// Least-squares fit. Throws OptionError("degree", …) for degree 0 or above 6, or when the data
/// has fewer rows than terms.
Poly fit_poly(const Data& train, std::size_t degree, double ridge = 1e-10);

}  // namespace fogdrift
