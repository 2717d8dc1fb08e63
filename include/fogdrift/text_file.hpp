// Reading a whole text file, with fogdrift's error for a file that cannot be opened.
#pragma once

#include <filesystem>
#include <string>

namespace fogdrift {

/// The bytes of `path`. Throws InputError("PATH: cannot open (REASON)").
std::string read_text_file(const std::filesystem::path& path);

/// Line and column (1-based) of a byte offset in `text`, for error messages.
std::pair<std::size_t, std::size_t> line_column_of(const std::string& text, std::size_t byte);

/// Throws the InputError for a JSON syntax error reported by the parser at `byte` (nlohmann's
/// 1-based byte count) with message `what`: "FILE:LINE:COLUMN: invalid JSON: syntax error …".
[[noreturn]] void throw_json_syntax_error(const std::string& file, const std::string& text,
                                          std::size_t byte, const std::string& what);

/// A JSON number beyond a double's range, which the JSON parser reports as out of range with
/// `what` ("… number overflow parsing '6e524'"): an InputError naming the file and, where the
/// number is found in `text`, its line and column.
[[noreturn]] void throw_json_number_error(const std::string& file, const std::string& text,
                                          const std::string& what);

}  // namespace fogdrift
