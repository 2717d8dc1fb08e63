// The registry's lookups by type (regressors.hpp); the list itself is src/train/registry.cpp.
#include "fogdrift/regress/regressors.hpp"

#include <fmt/format.h>

#include <cctype>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

bool is_regressor_type(std::string_view type) {
  for (const RegressorEntry& e : regressor_entries())
    if (e.type == type) return true;
  return false;
}

std::string regressor_types() {
  std::string out;
  const auto entries = regressor_entries();
  for (std::size_t i = 0; i < entries.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : (i + 1 == entries.size() ? " or " : ", "),
                       entries[i].type);
  return out;
}

std::string to_json(const AnyRegressor& regressor) {
  // The regressor's own object with "type" written first, as text: no parse and dump again.
  std::string own = regressor.own_json();
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
  for (const RegressorEntry& e : regressor_entries())
    if (e.type == type) return e.from_json(text, source);
  throw InputError(source, 0, 0,
                   fmt::format("regressor.type: '{}' is not {}", type, regressor_types()));
}

}  // namespace fogdrift
