#include "base/c_text.hpp"

#include <fmt/format.h>

namespace fogdrift::detail {

std::string c_number(double v) {
  return fmt::format("{:.17g}", v);
}

std::string c_array(std::span<const double> values, std::size_t per_line) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i % per_line == 0) out += "\n    ";
    out += c_number(values[i]);
    if (i + 1 < values.size()) out += ", ";
  }
  return out;
}

std::string fill_template(std::string text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values) {
  for (const auto& [key, value] : values)
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
      text.replace(at, key.size(), value), at += value.size();
  return text;
}

}  // namespace fogdrift::detail
