// Whole numbers read from JSON files: a field that must be a count or an id is checked to be a
// JSON integer in T's range before it is converted (a float such as 7.7e80 converted to an integer
// type is undefined behaviour; found by fuzzing, docs/reliability.md). Internal header.
#pragma once

#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

namespace fogdrift::detail {

/// `v` as T. Throws the JSON library's type_error (which the readers already turn into an
/// InputError naming the field) when `v` is not an integer or not in T's range.
template <class T, class Json>
T whole_number(const Json& v) {
  static_assert(std::is_integral_v<T>);
  const auto fail = [&] {
    return nlohmann::detail::type_error::create(
        302,
        "must be a whole number from " + std::to_string(std::numeric_limits<T>::min()) + " to " +
            std::to_string(std::numeric_limits<T>::max()) + ", found " + v.dump(),
        &v);
  };
  if (!v.is_number_integer()) throw fail();
  if (v.is_number_unsigned()) {
    const auto u = v.template get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<T>::max())) throw fail();
    return static_cast<T>(u);
  }
  const auto s = v.template get<std::int64_t>();
  if constexpr (std::is_unsigned_v<T>) {
    if (s < 0 || static_cast<std::uint64_t>(s) > std::numeric_limits<T>::max()) throw fail();
  } else {
    if (s < std::numeric_limits<T>::min() || s > std::numeric_limits<T>::max()) throw fail();
  }
  return static_cast<T>(s);
}

}  // namespace fogdrift::detail
