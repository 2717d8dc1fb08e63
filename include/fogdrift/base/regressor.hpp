// One shape for every regressor a compensation model can hold (docs/architecture.md,
// "Adding a regressor"). A regressor is a value type R with
//   R::kType                     its name in model files ("svr", "mlp", "poly", "gp")
//   r.predict(x)                 ŷ for one row of standardised features, no allocation
//   input_count(r)               how many features it takes
//   to_json(r)                   its JSON text, the model file's "regressor" without "type"
//   regressor_from_json(std::type_identity<R>{}, text, source)   the inverse, validating
//   to_c(r, names)               its part of the C header (c_header.hpp)
// found by argument-dependent lookup, so each lives beside its regressor. The registry
// (regressors.hpp) lists the types a model file can hold and checks each against the concept:
// a regressor that lacks a part does not compile.
#pragma once

#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

namespace fogdrift {

/// The names a regressor's C uses: `prefix` for identifiers (unit42_sv), `upper` for macros
/// (UNIT42_N_FEATURES).
struct CNames {
  std::string prefix;
  std::string upper;
};

/// A regressor's part of the C header: its constant tables, and the statements inside
/// PREFIX_predict that declare and compute `z`, the standardised prediction, from `x`, the
/// standardised features. Both may use the header's placeholders: @REAL@ for the arithmetic
/// type and @F@ for the suffix of <math.h>'s functions in it (c_header.cpp).
struct CRegressor {
  std::string tables;
  std::string body;
};

template <class R>
concept Regressor = std::copyable<R> &&
    requires(const R& r, const double* x, const std::string& text, const CNames& names) {
  { R::kType } -> std::convertible_to<std::string_view>;
  { r.predict(x) } -> std::same_as<double>;
  { input_count(r) } -> std::same_as<std::size_t>;
  { to_json(r) } -> std::same_as<std::string>;
  { regressor_from_json(std::type_identity<R>{}, text, text) } -> std::same_as<R>;
  { to_c(r, names) } -> std::same_as<CRegressor>;
};

}  // namespace fogdrift
