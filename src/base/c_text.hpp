// Numbers and tables as C source text, for the C header (c_header.cpp) and the regressors'
// parts of it (regressor.hpp, to_c; c_parts.hpp). Internal header.
#pragma once

#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace fogdrift::detail {

/// `v` with the 17 significant digits that read back to the same double.
std::string c_number(double v);
/// The values as a C initialiser list, `per_line` to a line, each line indented by four.
std::string c_array(std::span<const double> values, std::size_t per_line = 4);
/// `text` with every @KEY@ replaced by its value: the C templates read as C, without fmt's
/// doubled braces.
std::string fill_template(std::string text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values);

}  // namespace fogdrift::detail
