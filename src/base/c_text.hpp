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
/// `text` as it may stand inside a C block comment: printable ASCII kept, except that every
/// byte that could end the comment, open another, splice a line or form a trigraph ('*', '/',
/// '\\', '?' next to one of them) and every other byte is written as \xNN, so no text from a
/// model file can end the comment (docs/reliability.md, "Generated code").
std::string c_comment_text(std::string_view text);
/// `text` as a C string literal, quotes included: '"', '\\' and '?' escaped (no trigraph can
/// form), every byte outside printable ASCII as a three-digit octal escape.
std::string c_string_literal(std::string_view text);
/// Whether `name` is a C identifier that C99 does not reserve: letters, digits and '_', not
/// starting with a digit, not a keyword, not starting with '_' (reserved when a capital or a
/// second '_' follows, and at file scope always).
bool is_plain_c_identifier(std::string_view name);

/// `text` with every @KEY@ replaced by its value: the C templates read as C, without fmt's
/// doubled braces.
std::string fill_template(std::string text,
                          std::initializer_list<std::pair<std::string_view, std::string>> values);

}  // namespace fogdrift::detail
