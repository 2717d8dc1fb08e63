// Strict, locale-independent CSV reading and writing shared by recordings and the importer.
//
// The dialect is RFC 4180 as pandas, MATLAB (readtable) and Excel write it: one header row, a
// delimiter (comma by default), fields optionally in double quotes with "" for a quote, LF or
// CRLF line ends, an optional UTF-8 byte-order mark. Numbers are read with std::from_chars, never
// through the C locale, and written in the shortest form that reads back to the same double.
#pragma once

#include <cstddef>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fogdrift::csv {

/// A CSV file read into memory, as text fields. Every row has the header's number of fields.
struct Table {
  std::string file;                            ///< name used in error messages
  std::vector<std::string> header;             ///< column names, in file order, unique
  std::vector<std::vector<std::string>> rows;  ///< data rows
  std::vector<std::size_t> row_line;           ///< 1-based line of each data row in the file
  /// What a tolerant read (ReadOptions::drop_empty) dropped, one sentence each, for people.
  std::vector<std::string> notes;

  /// Index of the column named `name`, if present.
  std::optional<std::size_t> find(std::string_view name) const;
};

struct ReadOptions {
  char delimiter = ',';  ///< field separator: ',' (default), ';' or '\t'
  /// Lines before the header that are not part of the table (a logger's preamble), skipped.
  std::size_t skip_lines = 0;
  /// Lines whose first non-blank character is this one are comments, skipped anywhere; 0: none.
  char comment = 0;
  /// A spreadsheet export's padding is dropped, with a note in Table::notes, instead of being an
  /// error: columns with no name and no value in any row, and rows whose every field is blank.
  /// A nameless column that holds a value is still an error, naming its line and column.
  bool drop_empty = false;
};

/// Reads and tokenises `path`. Throws InputError for: a missing or unreadable file, an empty file,
/// an empty (unless dropped by drop_empty) or duplicated column name, a row with a different number
/// of fields than the header, an empty line between data rows, an unterminated quote. Trailing
/// empty lines are allowed.
Table read(const std::string& path, const ReadOptions& options = {});

/// Same as read(), from text already in memory; `file` names it in error messages.
Table parse(std::string_view text, const std::string& file, const ReadOptions& options = {});

/// `s` without its leading and trailing spaces and tabs: how a header name or a blank line is
/// read.
std::string_view trim(std::string_view s);

/// Parses a finite decimal number ("1.5", "-2e-3", "+4"); surrounding spaces are allowed.
/// Returns nothing for an empty field, text, "nan", "inf" or an out-of-range value.
/// With `decimal_comma`, a single ',' is read as the decimal point ("1,5").
std::optional<double> parse_number(std::string_view field, bool decimal_comma = false);

/// Shortest decimal text that reads back to exactly `value` (std::to_chars), e.g. "0.1", "1e-07".
std::string format_number(double value);
/// format_number(value) appended to `out`, without a string of its own: the writers of
/// kilohertz logs append a row's numbers to one line.
void append_number(std::string& out, double value);

/// One line's fields as read() splits them: quoted fields ("a,b", "say ""x"""), spaces before an
/// opening quote tolerated; a quote may not span lines. InputError(file, line_no, column) for an
/// unterminated quote or text after a closing one. Fields are not trimmed.
std::vector<std::string> split_line(std::string_view line, char delimiter, const std::string& file,
                                    std::size_t line_no);

/// The first LF or CR in data[begin, end), or `end`: where a line ends (two memchr scans, which
/// the C library vectorises).
std::size_t line_end(const char* data, std::size_t begin, std::size_t end);

/// split_line()'s fields as views, without a string per field: into `line` itself when it holds
/// no quote (the common case), else into `quoted`, which holds split_line()'s fields. The views
/// live as long as `line` and `quoted` are unchanged. The same fields and errors as split_line().
void split_fields(std::string_view line, char delimiter, const std::string& file,
                  std::size_t line_no, std::vector<std::string_view>& fields,
                  std::vector<std::string>& quoted);

/// Why parse_number() found no number in `cell`, as an error message ends: "is empty", "is not
/// finite (NaN and Inf are not allowed)", "is beyond a double's range (…)" or "is not a number".
std::string why_not_a_number(std::string_view cell);

/// `field` quoted when it holds the delimiter, a quote, a line break or edge spaces.
std::string quote(std::string_view field, char delimiter = ',');
/// quote(field, delimiter) appended to `out`, without a string of its own.
void append_quoted(std::string& out, std::string_view field, char delimiter = ',');

/// A field as an error message shows it: whole up to 40 characters, else its first 40 and its
/// length ("123456…(10000000 characters)"), so that a 10 MB cell is not echoed whole.
std::string excerpt(std::string_view field);

/// The lines of a CSV arriving piece by piece (standard input, a pipe, a logger), as `stream`
/// reads them: a line ends at LF, CRLF or a lone CR, and none of them is kept; the first line
/// loses a UTF-8 byte-order mark. A line is returned as soon as its end arrives (a CR is not held
/// back to see whether an LF follows). The same lines read() sees in a file with LF or CRLF ends.
/// It takes at once whatever the stream has ready, so that a file is read a block at a time,
/// and waits for one byte only when nothing is ready.
class LineReader {
 public:
  /// `block_bytes`: the most taken at once (any size gives the same lines; tests use small ones
  /// to put line ends across blocks).
  explicit LineReader(std::istream& in, std::size_t block_bytes = std::size_t{1} << 16)
      : in_(in), block_(block_bytes > 0 ? block_bytes : 1) {}
  /// The next line into `line`; false at the end of the input with nothing left.
  bool next(std::string& line);
  /// Bytes taken from the stream and not yet returned in a line: with the stream's own
  /// in_avail(), whether a next line can come without waiting.
  std::size_t buffered() const { return end_ - begin_; }

 private:
  /// Takes what the stream has ready, waiting for one byte when it has none; false at its end.
  bool refill();

  std::istream& in_;
  std::size_t block_;
  bool first_ = true;
  bool after_cr_ = false;  ///< the last line ended at a CR: an LF next is its CRLF's
  std::string buffer_;
  std::size_t begin_ = 0, end_ = 0;  ///< the bytes of buffer_ not yet returned
};

}  // namespace fogdrift::csv
