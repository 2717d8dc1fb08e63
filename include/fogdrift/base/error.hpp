// Errors fogdrift reports for bad input or configuration.
//
// Three kinds of failure, three mechanisms (see docs): bad input or configuration throws one of
// these exceptions, whose message names the file, line and column (or the JSON path, or the
// option) and the rule broken; a broken internal invariant is an assertion; a solver that does not
// converge reports it in its summary. A job too large for the machine is a ResourceError
// (memory.hpp), raised before the job starts.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace fogdrift {

/// A problem with an input file. what() reads "FILE:LINE:COLUMN: MESSAGE" (line and column are
/// 1-based and left out when 0), the form compilers use, so editors can jump to the place.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::size_t line, std::size_t column, std::string message);

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }      ///< 1-based; 0 when the whole file is meant
  std::size_t column() const { return column_; }  ///< 1-based; 0 when the whole line is meant
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  std::size_t line_;
  std::size_t column_;
  std::string message_;
};

/// An impossible option or parameter value: what() names the option, the value and the rule.
class OptionError : public std::invalid_argument {
 public:
  OptionError(const std::string& option, const std::string& message);
  const std::string& option() const { return option_; }
  const std::string& message() const { return message_; }  ///< what() without "option X: "

 private:
  std::string option_;
  std::string message_;
};

}  // namespace fogdrift
