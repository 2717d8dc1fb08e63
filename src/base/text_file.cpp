#include "fogdrift/base/text_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"

namespace fogdrift {

std::ifstream open_text_file(const std::filesystem::path& path) {
  // A folder opens as an empty stream on Linux; given for a file (a campaign where a model file
  // belongs, say), it would read as an empty file.
  std::error_code dir_ec;
  if (std::filesystem::is_directory(path, dir_ec))
    throw InputError(path.string(), 0, 0, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(), 0, 0, fmt::format("cannot open ({})", std::strerror(errno)));
  note_input(path);
  return in;
}

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in = open_text_file(path);
  // A regular file is read straight into a string of its size: one buffer, no copy.
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) {
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec) {
      std::string text(static_cast<std::size_t>(size), '\0');
      in.read(text.data(), static_cast<std::streamsize>(size));
      text.resize(static_cast<std::size_t>(in.gcount()));
      if (in.peek() == std::char_traits<char>::eof()) return text;
      // The file grew while it was read: read the rest too.
      std::ostringstream rest;
      rest << in.rdbuf();
      return text + rest.str();
    }
  }
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::pair<std::size_t, std::size_t> line_column_of(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

void throw_json_syntax_error(const std::string& file, const std::string& text, std::size_t byte,
                             const std::string& what) {
  const auto [line, column] = line_column_of(text, byte == 0 ? 0 : byte - 1);
  const auto cut = what.find("syntax error");
  throw InputError(file, line, column,
                   "invalid JSON: " + (cut == std::string::npos ? what : what.substr(cut)));
}

void throw_json_number_error(const std::string& file, const std::string& text,
                             const std::string& what) {
  const auto open = what.find('\'');
  const auto close = open == std::string::npos ? open : what.find('\'', open + 1);
  const std::string number =
      close == std::string::npos ? std::string() : what.substr(open + 1, close - open - 1);
  const std::size_t at = number.empty() ? std::string::npos : text.find(number);
  const auto [line, column] = at == std::string::npos ? std::pair<std::size_t, std::size_t>{0, 0}
                                                      : line_column_of(text, at);
  throw InputError(file, line, column,
                   fmt::format("invalid JSON: the number {} is beyond the range of a double",
                               number.empty() ? std::string("here") : number));
}

std::string json_error_text(const std::exception& e) {
  const std::string_view what = e.what();
  if (what.starts_with("[json.exception.")) {
    const auto close = what.find("] ");
    if (close != std::string_view::npos) return std::string(what.substr(close + 2));
  }
  return std::string(what);
}

void check_json_nesting(const std::string& file, const std::string& text, std::size_t max_depth) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character, a quote included, cannot end the string
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_depth) {
        const auto [line, column] = line_column_of(text, i);
        throw InputError(file, line, column,
                         fmt::format("invalid JSON: arrays and objects nested deeper than {} "
                                     "levels; no fogdrift file needs more",
                                     max_depth));
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace fogdrift
