#include "fogdrift/model/regressors.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fogdrift/base/error.hpp"

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
  // The regressor's own object with "type" written first, as text: no parse and dump again.
  std::string own = std::visit([](const auto& r) { return to_json(r); }, regressor);
  while (!own.empty() && std::isspace(static_cast<unsigned char>(own.back()))) own.pop_back();
  const std::size_t open = own.find('{');
  if (open == std::string::npos || own.back() != '}')
    throw std::logic_error("a regressor's JSON must be an object");
  const bool empty = own.find_first_not_of(" \t\r\n", open + 1) == own.size() - 1;
  const std::string type = nlohmann::json(std::string(regressor_type(regressor))).dump();
  return "{\"type\":" + type + (empty ? "" : ",") + own.substr(open + 1);
}

AnyRegressor regressor_from_json(const std::string& type, const std::string& text,
                                 const std::string& source) {
  return Registered::parse(type, text, source);
}

CRegressor to_c(const AnyRegressor& regressor, const CNames& names) {
  return std::visit([&](const auto& r) { return to_c(r, names); }, regressor);
}

}  // namespace fogdrift
