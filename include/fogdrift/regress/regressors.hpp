// Whichever regressor a compensation model holds (regressor.hpp), and the registry of the types a
// model file can hold. `AnyRegressor` holds any type that models `Regressor` behind one small
// interface, so no file but the registry's list names every type: the list itself is
// `src/train/registry.cpp`, one line per method with its trainer and regressor (docs/
// architecture.md, "Adding a regressor"); it defines `regressor_entries()` below.
#pragma once

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "fogdrift/base/regressor.hpp"

namespace fogdrift {

namespace detail {
// A regressor's parts, found by argument-dependent lookup (svr::Model's live in fogdrift::svr),
// under names AnyRegressor's members do not hide.
template <class R>
std::size_t inputs_of(const R& r) {
  return input_count(r);
}
template <class R>
std::string json_of(const R& r) {
  return to_json(r);
}
template <class R>
CRegressor c_of(const R& r, const CNames& names) {
  return to_c(r, names);
}
}  // namespace detail

/// A regressor of any registered type, a value: copies share the one immutable regressor. Empty
/// until a regressor is assigned (a model not yet trained or read); every operation on an empty
/// one but has_value() is a logic error.
class AnyRegressor {
 public:
  AnyRegressor() = default;
  // Explicit, so that no function taking an AnyRegressor (to_json, to_c below) is a candidate
  // for another type: a type lacking its own to_c must not model Regressor through this one.
  template <class R>
  requires requires { R::kType; }
  explicit AnyRegressor(R regressor)
      : held_(std::make_shared<const Held<R>>(std::move(regressor))) {
    static_assert(Regressor<R>, "AnyRegressor holds a type that models Regressor (regressor.hpp)");
  }
  /// Holds `regressor` from now on: model.regressor = fit_poly(…).
  template <class R>
  requires requires { R::kType; }
  AnyRegressor& operator=(R regressor) { return *this = AnyRegressor(std::move(regressor)); }

  bool has_value() const noexcept { return held_ != nullptr; }
  /// The model file's type: "svr", "mlp", … (R::kType).
  std::string_view type() const { return get().type(); }
  /// The standardised prediction for one standardised row `x`: the per-sample path of every
  /// compensator, one indirect call.
  double predict(const double* x) const { return held_->predict(x); }
  std::size_t input_count() const { return get().input_count(); }
  /// Its own JSON object, without "type" (the model file's "regressor" is to_json() below).
  std::string own_json() const { return get().own_json(); }
  CRegressor to_c(const CNames& names) const { return get().to_c(names); }

  /// The regressor if it is an R, else nullptr.
  template <Regressor R>
  const R* get_if() const noexcept {
    const auto* held = dynamic_cast<const Held<R>*>(held_.get());
    return held != nullptr ? &held->value : nullptr;
  }
  /// The regressor as an R; std::logic_error if it is another type.
  template <Regressor R>
  const R& get() const {
    if (const R* r = get_if<R>()) return *r;
    throw std::logic_error("the model's regressor is not a " + std::string(R::kType));
  }

 private:
  struct Base {
    virtual ~Base() = default;
    virtual std::string_view type() const = 0;
    virtual double predict(const double* x) const = 0;
    virtual std::size_t input_count() const = 0;
    virtual std::string own_json() const = 0;
    virtual CRegressor to_c(const CNames& names) const = 0;
  };
  template <class R>
  struct Held final : Base {
    explicit Held(R r) : value(std::move(r)) {}
    std::string_view type() const override { return R::kType; }
    double predict(const double* x) const override { return value.predict(x); }
    std::size_t input_count() const override { return detail::inputs_of(value); }
    std::string own_json() const override { return detail::json_of(value); }
    CRegressor to_c(const CNames& names) const override { return detail::c_of(value, names); }
    R value;
  };
  const Base& get() const {
    if (held_ == nullptr) throw std::logic_error("the model holds no regressor");
    return *held_;
  }
  std::shared_ptr<const Base> held_;
};

/// A registered regressor as the registry lists it: its type and how its file part is read.
struct RegressorEntry {
  std::string_view type;
  /// The regressor parsed from its own JSON text, validating (regressor.hpp).
  AnyRegressor (*from_json)(const std::string& text, const std::string& source);
};

/// The entry of regressor R; R that is not a Regressor does not compile.
template <Regressor R>
constexpr RegressorEntry regressor_entry_of() {
  return {R::kType, [](const std::string& text, const std::string& source) {
            return AnyRegressor(regressor_from_json(std::type_identity<R>{}, text, source));
          }};
}

/// Every registered regressor, in the registry's order (defined by src/train/registry.cpp).
std::span<const RegressorEntry> regressor_entries();

/// The model file's type of the regressor held: "svr", "mlp", "poly", "gp".
inline std::string_view regressor_type(const AnyRegressor& regressor) {
  return regressor.type();
}
/// Whether `type` names a registered regressor.
bool is_regressor_type(std::string_view type);
/// The registered types, comma-separated, for messages ("svr, mlp, poly or gp").
std::string regressor_types();
inline std::size_t input_count(const AnyRegressor& regressor) {
  return regressor.input_count();
}
/// The regressor's standardised prediction for one standardised row `x`.
inline double predict(const AnyRegressor& regressor, const double* x) {
  return regressor.predict(x);
}
/// {"type": …, then the regressor's own fields}: the model file's "regressor" object.
std::string to_json(const AnyRegressor& regressor);
/// The regressor of type `type` parsed from its own JSON text. Throws InputError(source, 0, 0,
/// "regressor.type: …") for a type not registered, and the regressor's own errors otherwise.
AnyRegressor regressor_from_json(const std::string& type, const std::string& text,
                                 const std::string& source);
inline CRegressor to_c(const AnyRegressor& regressor, const CNames& names) {
  return regressor.to_c(names);
}

}  // namespace fogdrift
