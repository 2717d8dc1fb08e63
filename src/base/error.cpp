#include "fogdrift/base/error.hpp"

#include <fmt/format.h>

namespace fogdrift {
namespace {

std::string format_location(const std::string& file, std::size_t line, std::size_t column,
                            const std::string& message) {
  std::string where = file;
  if (line > 0) where += fmt::format(":{}", line);
  if (line > 0 && column > 0) where += fmt::format(":{}", column);
  return fmt::format("{}: {}", where, message);
}

}  // namespace

InputError::InputError(std::string file, std::size_t line, std::size_t column, std::string message)
    : std::runtime_error(format_location(file, line, column, message)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      message_(std::move(message)) {}

OptionError::OptionError(const std::string& option, const std::string& message)
    : std::invalid_argument(fmt::format("option {}: {}", option, message)),
      option_(option),
      message_(message) {}

}  // namespace fogdrift
