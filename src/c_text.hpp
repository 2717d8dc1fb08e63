// Numbers and tables as C source text, for the C header (c_header.cpp) and the regressors'
// parts of it (regressor.hpp, to_c). Internal header.
#pragma once

#include <span>
#include <string>

namespace fogdrift::detail {

/// `v` with the 17 significant digits that read back to the same double.
std::string c_number(double v);
/// The values as a C initialiser list, `per_line` to a line, each line indented by four.
std::string c_array(std::span<const double> values, std::size_t per_line = 4);

}  // namespace fogdrift::detail
