#include "fogdrift/regressors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "fogdrift/error.hpp"

namespace fogdrift {
namespace {

// One entry per registered type, in AnyRegressor's order.
template <class T>
struct Types;
template <class... R>
struct Types<std::variant<R...>> {
  static constexpr std::array<std::string_view, sizeof...(R)> names = {R::kType...};

  static AnyRegressor parse(const std::string& type, const std::string& text,
                            const std::string& source) {
    AnyRegressor out;
    const bool found =
        ((type == R::kType
              ? (out = regressor_from_json(std::type_identity<R>{}, text, source), true)
              : false) ||
         ...);
    if (!found)
      throw InputError(source, 0, 0,
                       fmt::format("regressor.type: '{}' is not {}", type, regressor_types()));
    return out;
  }
};
using Registered = Types<AnyRegressor>;

}  // namespace

std::string_view regressor_type(const AnyRegressor& regressor) {
  return std::visit([](const auto& r) -> std::string_view { return r.kType; }, regressor);
}

bool is_regressor_type(std::string_view type) {
  const auto& names = Registered::names;
  return std::find(names.begin(), names.end(), type) != names.end();
}

std::string regressor_types() {
  std::string out;
  const auto& names = Registered::names;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : (i + 1 == names.size() ? " or " : ", "), names[i]);
  return out;
}

std::size_t input_count(const AnyRegressor& regressor) {
  return std::visit([](const auto& r) { return input_count(r); }, regressor);
}

std::string to_json(const AnyRegressor& regressor) {
  using ojson = nlohmann::ordered_json;
  ojson out;
  out["type"] = regressor_type(regressor);
  const ojson own = ojson::parse(std::visit([](const auto& r) { return to_json(r); }, regressor));
  for (const auto& [k, v] : own.items()) out[k] = v;
  return out.dump();
}

AnyRegressor regressor_from_json(const std::string& type, const std::string& text,
                                 const std::string& source) {
  return Registered::parse(type, text, source);
}

CRegressor to_c(const AnyRegressor& regressor, const CNames& names) {
  return std::visit([&](const auto& r) { return to_c(r, names); }, regressor);
}

}  // namespace fogdrift
