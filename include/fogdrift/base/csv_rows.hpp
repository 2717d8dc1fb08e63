// A CSV file read row by row in constant memory (docs/architecture.md, base/csv_rows): what
// csv::read() collects into a Table of text fields, without holding the file or its fields.
// Recordings are read through it, so that a kilohertz log of 150 MB costs its numbers, not ten
// strings a row (docs/reliability.md, "Size limits").
//
// The dialect and the errors are csv::read()'s (csv.hpp): one header row, fields optionally in
// double quotes, LF, CRLF or lone-CR line ends, a UTF-8 byte-order mark; UTF-16 and NUL bytes
// refused naming their line and column; an empty or duplicated column name, an empty line
// between rows, a row with another number of fields than the header, an unterminated quote.
// ReadOptions::drop_empty, which needs every row before it can drop a column, is not offered.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/base/csv.hpp"

namespace fogdrift::csv {

class RowReader {
 public:
  /// Reads up to and including the header. `file` names the input in errors. Throws InputError
  /// as csv::read() does; std::invalid_argument for options.drop_empty.
  /// `chunk_bytes`: the most read at a time (LineReader's block; any size gives the same rows,
  /// tests use small ones to put line ends across chunks).
  RowReader(std::istream& in, std::string file, const ReadOptions& options = {},
            std::size_t chunk_bytes = std::size_t{1} << 20);

  const std::vector<std::string>& header() const { return header_; }
  std::optional<std::size_t> find(std::string_view name) const;
  const std::string& file() const { return file_; }

  /// The next data row: its fields (views valid until the next call) and its 1-based line in the
  /// file. False at the end of the input.
  bool next(std::vector<std::string_view>& fields, std::size_t& line);
  /// The text of the row next() returned last, as the file has it without its line end (valid
  /// until the next call): what a writer copies whole when it would copy every field as it is.
  std::string_view row_text() const { return line_; }
  char delimiter() const { return options_.delimiter; }

 private:
  /// The next physical line, without its end (a view of line_); false at the end of the input.
  bool read_line(std::string_view& line);
  /// The fields of `line` as views, into the line or, for a quoted line, into quoted_.
  void split(std::string_view line, std::vector<std::string_view>& fields);

  std::istream& in_;
  LineReader lines_;  ///< line ends and the byte-order mark, as stream reads them
  std::string line_;  ///< the line read last, which read_line's views show
  std::string file_;
  ReadOptions options_;
  std::size_t line_no_ = 0;
  std::size_t pending_blank_ = 0;  ///< the first blank line after the header, if any
  std::vector<std::string> quoted_;
  std::vector<std::string> header_;
};

}  // namespace fogdrift::csv
