// A CSV file read row by row (csv_rows.hpp).
#include "fogdrift/base/csv_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <unordered_set>

#include "fogdrift/base/error.hpp"

namespace fogdrift::csv {
RowReader::RowReader(std::istream& in, std::string file, const ReadOptions& options,
                     std::size_t chunk_bytes)
    : in_(in), lines_(in, chunk_bytes), file_(std::move(file)), options_(options) {
  if (options.drop_empty)
    throw std::invalid_argument("csv::RowReader: drop_empty needs the whole table (csv::read)");
  std::string_view line;
  std::vector<std::string_view> fields;
  while (read_line(line)) {
    if (line_no_ <= options_.skip_lines) continue;
    if (options_.comment != 0 && !trim(line).empty() && trim(line).front() == options_.comment)
      continue;
    if (trim(line).empty())
      throw InputError(file_, line_no_, 0, "empty line where the header row was expected");
    split(line, fields);
    std::unordered_set<std::string> seen;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      std::string name(trim(fields[c]));
      if (name.empty()) throw InputError(file_, line_no_, c + 1, "empty column name in the header");
      if (!seen.insert(name).second)
        throw InputError(file_, line_no_, c + 1,
                         fmt::format("duplicated column name '{}' in the header", name));
      header_.push_back(std::move(name));
    }
    return;
  }
  throw InputError(file_, 0, 0, "empty file: a header row is required");
}

std::optional<std::size_t> RowReader::find(std::string_view name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header_.begin());
}

bool RowReader::next(std::vector<std::string_view>& fields, std::size_t& line) {
  std::string_view text;
  while (read_line(text)) {
    if (options_.comment != 0 && !trim(text).empty() && trim(text).front() == options_.comment)
      continue;
    if (trim(text).empty()) {
      if (pending_blank_ == 0) pending_blank_ = line_no_;
      continue;
    }
    if (pending_blank_ != 0)
      throw InputError(file_, pending_blank_, 0, "empty line between data rows");
    split(text, fields);
    if (fields.size() != header_.size())
      throw InputError(file_, line_no_, 0,
                       fmt::format("row has {} fields but the header has {} columns", fields.size(),
                                   header_.size()));
    line = line_no_;
    return true;
  }
  return false;
}

bool RowReader::read_line(std::string_view& line) {
  if (!lines_.next(line_)) return false;
  line = line_;
  ++line_no_;
  if (line_no_ == 1) {
    // UTF-16 (a spreadsheet's "Unicode text"): its mark, or NULs between ASCII letters.
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(line[k]); };
    const bool utf16_mark = line.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) ||
                                                 (byte(0) == 0xFE && byte(1) == 0xFF));
    const bool nul_pattern = line.size() >= 4 && (line[0] == '\0' || line[1] == '\0') &&
                             (line[2] == '\0' || line[3] == '\0');
    if (utf16_mark || nul_pattern)
      throw InputError(file_, 1, 1,
                       "is UTF-16 text, not UTF-8: save it as \"CSV UTF-8\" (or convert it, e.g. "
                       "iconv -f UTF-16 -t UTF-8)");
    // A byte-order mark and nothing else (LineReader took the mark): an empty file, as read()
    // finds it.
    if (line.empty() && in_.eof()) return false;
  }
  if (const std::size_t nul = line.find('\0'); nul != std::string_view::npos)
    throw InputError(file_, line_no_, nul + 1, "contains a NUL byte: this is not a text CSV file");
  return true;
}

void RowReader::split(std::string_view line, std::vector<std::string_view>& fields) {
  split_fields(line, options_.delimiter, file_, line_no_, fields, quoted_);
}

}  // namespace fogdrift::csv
