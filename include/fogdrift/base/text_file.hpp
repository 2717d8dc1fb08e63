// Reading a whole text file, with fogdrift's error for a file that cannot be opened.
#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace fogdrift {

/// The bytes of `path`. Throws InputError("PATH: cannot open (REASON)").
std::string read_text_file(const std::filesystem::path& path);

/// `path` opened to be read piece by piece (csv::RowReader), with read_text_file's checks and
/// errors: a folder is refused, and the file is noted as the run's input (run_files.hpp).
std::ifstream open_text_file(const std::filesystem::path& path);

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

/// A JSON library exception's text without its "[json.exception.out_of_range.403] " tag, as an
/// error message shows it: "key 'seed' not found".
std::string json_error_text(const std::exception& e);

/// Arrays and objects nested deeper than this are refused by every JSON reader of fogdrift: no
/// file it writes nests deeper than 6, and the JSON library writes and destroys nested values
/// by recursion, which a file nested tens of thousands deep overflows (docs/reliability.md).
inline constexpr std::size_t kMaxJsonDepth = 64;

/// Throws InputError("FILE:LINE:COLUMN: invalid JSON: arrays and objects nested deeper than
/// 64 …") at the bracket that goes one level too deep; brackets inside strings do not count.
/// Run before parsing.
void check_json_nesting(const std::string& file, const std::string& text,
                        std::size_t max_depth = kMaxJsonDepth);

}  // namespace fogdrift
