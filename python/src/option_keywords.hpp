// Python keywords from option descriptions (option_table.hpp): a keyword's value turned into
// the text the library's table parses, by the option's type, and the descriptions handed to
// python/fogdrift/_options.py, which builds the function's signature and docstring from them.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "fogdrift/base/option_table.hpp"

namespace fogdrift::python {

/// The text of `value` for an option of `spec`'s type; a TypeError "FUNCTION(): KEYWORD must be
/// WHAT, not TYPE (REPR)" when the value is not of a Python type the option takes (a value of the
/// right type but outside the option's values is the library's OptionError, a ValueError).
std::string keyword_text(const OptionSpec& spec, const pybind11::handle& value,
                         const std::string& function);

/// Sets on `o` each option of `table` that `kwargs` gives, in the table's order, from its value
/// as keyword_text reads it. A keyword the table lacks is a TypeError "FUNCTION() got an
/// unexpected keyword argument 'K'; WHAT are A, B, …", listing `own` (the function's other
/// arguments) and then the table's keywords.
template <class O>
void apply_keywords(const OptionTable<O>& table, O& o, const pybind11::kwargs& kwargs,
                    const std::string& function, const std::vector<std::string>& own = {},
                    const std::string& what = "its keywords") {
  for (const auto& item : kwargs) {
    const auto name = item.first.template cast<std::string>();
    if (find_option(table, name)) continue;
    std::string known;
    for (const auto& k : own) known += (known.empty() ? "" : ", ") + k;
    for (const auto& option : table) known += (known.empty() ? "" : ", ") + option.spec.keyword;
    throw pybind11::type_error(function + "() got an unexpected keyword argument '" + name + "'; " +
                               what + " are " + known);
  }
  for (const auto& option : table)
    if (kwargs.contains(option.spec.keyword.c_str()))
      option.set(o, keyword_text(option.spec, kwargs[option.spec.keyword.c_str()], function));
}

/// One dict per option, in order: keyword, type (to_string(OptionType)), default (as text),
/// unit, doc (option_help's: with the unit and the values allowed, other options named by
/// keyword), flag.
pybind11::list describe_options(const std::vector<OptionSpec>& specs,
                                const std::vector<std::string>& defaults);

/// describe_options of a whole table, with its struct's defaults.
template <class O>
pybind11::list describe_options(const OptionTable<O>& table) {
  return describe_options(specs_of(table), defaults_of(table));
}

}  // namespace fogdrift::python
