#include "base/c_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

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

std::string c_comment_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    const bool risky = c == '*' || c == '/' || c == '\\' || c == '?';
    if (byte >= 0x20 && byte < 0x7f && !risky)
      out += c;
    else
      out += fmt::format("\\x{:02x}", byte);
  }
  return out;
}

std::string c_string_literal(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\' || c == '?')
      out += '\\', out += c;
    else if (byte >= 0x20 && byte < 0x7f)
      out += c;
    else
      out += fmt::format("\\{:03o}", byte);
  }
  return out + '"';
}

bool is_plain_c_identifier(std::string_view name) {
  static constexpr std::array<std::string_view, 37> kKeywords = {
      "auto",     "break",  "case",   "char",     "const",     "continue", "default",  "do",
      "double",   "else",   "enum",   "extern",   "float",     "for",      "goto",     "if",
      "inline",   "int",    "long",   "register", "restrict",  "return",   "short",    "signed",
      "sizeof",   "static", "struct", "switch",   "typedef",   "union",    "unsigned", "void",
      "volatile", "while",  "_Bool",  "_Complex", "_Imaginary"};
  if (name.empty() || name.front() == '_' || (name.front() >= '0' && name.front() <= '9'))
    return false;
  const bool characters = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
  return characters && std::find(kKeywords.begin(), kKeywords.end(), name) == kKeywords.end();
}

std::string fill_template(std::string text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values) {
  for (const auto& [key, value] : values)
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at))
      text.replace(at, key.size(), value), at += value.size();
  return text;
}

}  // namespace fogdrift::detail
