// The registry of regressors a compensation model can hold (regressor.hpp), and the operations
// on whichever one a model holds. Adding a regressor is its own file pair, its test, and its type
// in AnyRegressor below; model files, the C header and prediction then take it.
#pragma once

#include <string>
#include <variant>

#include "fogdrift/base/regressor.hpp"
#include "fogdrift/model/gp.hpp"
#include "fogdrift/model/mlp.hpp"
#include "fogdrift/model/poly.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift {

using AnyRegressor = std::variant<svr::Model, Mlp, Poly, Gp>;

namespace detail {
template <class T>
struct AllRegressors;
template <class... R>
struct AllRegressors<std::variant<R...>> : std::bool_constant<(Regressor<R> && ...)> {};
}  // namespace detail
static_assert(detail::AllRegressors<AnyRegressor>::value,
              "every type of AnyRegressor must model Regressor (regressor.hpp)");

/// The model file's type of the regressor held: "svr", "mlp", "poly", "gp".
std::string_view regressor_type(const AnyRegressor& regressor);
/// Whether `type` names a registered regressor.
bool is_regressor_type(std::string_view type);
/// The registered types, comma-separated, for messages ("svr, mlp, poly or gp").
std::string regressor_types();
std::size_t input_count(const AnyRegressor& regressor);
/// The regressor's standardised prediction for one standardised row `x` (inline: the per-sample
/// path of every compensator).
inline double predict(const AnyRegressor& regressor, const double* x) {
  return std::visit([x](const auto& r) { return r.predict(x); }, regressor);
}
/// {"type": …, then the regressor's own fields}: the model file's "regressor" object.
std::string to_json(const AnyRegressor& regressor);
/// The regressor of type `type` parsed from its own JSON text. Throws InputError(source, 0, 0,
/// "regressor.type: …") for a type not registered, and the regressor's own errors otherwise.
AnyRegressor regressor_from_json(const std::string& type, const std::string& text,
                                 const std::string& source);
CRegressor to_c(const AnyRegressor& regressor, const CNames& names);

}  // namespace fogdrift
