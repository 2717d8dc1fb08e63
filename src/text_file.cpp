#include "fogdrift/text_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "fogdrift/error.hpp"

namespace fogdrift {

std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path.string(), 0, 0, fmt::format("cannot open ({})", std::strerror(errno)));
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

}  // namespace fogdrift
