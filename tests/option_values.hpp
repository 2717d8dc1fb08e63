// Helpers for the option table tests: values a test sets an option to.
#pragma once

#include <initializer_list>
#include <string>

#include "fogdrift/base/option_table.hpp"

namespace fogdrift::test {

/// The first of `candidates` (numbers as a user writes them) that differs from `current` and
/// that the option's bounds allow; `current` when none does.
inline std::string allowed_other(const OptionSpec& spec, const std::string& current,
                                 std::initializer_list<const char*> candidates) {
  for (const char* c : candidates)
    if (c != current && spec.range.contains(std::stod(c))) return c;
  return current;
}

}  // namespace fogdrift::test
