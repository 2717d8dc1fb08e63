// The names of an enum's values, as files and command lines write them: one table per enum, and
// the lookups every enum needs. A table lists each value once under its canonical name, first,
// and may add aliases after it (e.g. "centered" for centred); messages list canonical names only.
//
//   inline constexpr std::array<EnumName<Shrinkage>, 2> kShrinkageNames = {{
//       {Shrinkage::soft, "soft"}, {Shrinkage::hard, "hard"}}};
//   std::string_view to_string(Shrinkage s) { return name_in(kShrinkageNames, s); }
//   Shrinkage parse_shrinkage(std::string_view text, std::string_view option) {
//     return parse_in(kShrinkageNames, text, option, "a shrinkage mode");
//   }
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

template <typename E>
struct EnumName {
  E value;
  std::string_view name;
};

/// The canonical name of `value` ("?" if the table lacks it, which a test of each table rules
/// out).
template <typename E, std::size_t N>
constexpr std::string_view name_in(const std::array<EnumName<E>, N>& table, E value) {
  for (const auto& e : table)
    if (e.value == value) return e.name;
  return "?";
}

/// The value named `text` (a canonical name or an alias), if any.
template <typename E, std::size_t N>
constexpr std::optional<E> find_in(const std::array<EnumName<E>, N>& table, std::string_view text) {
  for (const auto& e : table)
    if (e.name == text) return e.value;
  return std::nullopt;
}

/// The canonical names, "a, b, c".
template <typename E, std::size_t N>
std::string names_in(const std::array<EnumName<E>, N>& table) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    bool first = true;  // only the first entry of each value is its canonical name
    for (std::size_t j = 0; j < i; ++j)
      if (table[j].value == table[i].value) first = false;
    if (!first) continue;
    if (!out.empty()) out += ", ";
    out += table[i].name;
  }
  return out;
}

/// The value named `text`; otherwise OptionError(option, "'TEXT' is not WHAT (a, b, c)").
template <typename E, std::size_t N>
E parse_in(const std::array<EnumName<E>, N>& table, std::string_view text, std::string_view option,
           std::string_view what) {
  if (const auto v = find_in(table, text)) return *v;
  throw OptionError(std::string(option), "'" + std::string(text) + "' is not " + std::string(what) +
                                             " (" + names_in(table) + ")");
}

}  // namespace fogdrift
