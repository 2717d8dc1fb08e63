// A CSV file read row by row (csv_rows.hpp).
#include "fogdrift/base/csv_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <unordered_set>

#include "fogdrift/base/error.hpp"

namespace fogdrift::csv {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

RowReader::RowReader(std::istream& in, std::string file, const ReadOptions& options,
                     std::size_t chunk_bytes)
    : in_(in),
      file_(std::move(file)),
      options_(options),
      chunk_(std::max<std::size_t>(1, chunk_bytes)) {
  if (options.drop_empty)
    throw std::invalid_argument("csv::RowReader: drop_empty needs the whole table (csv::read)");
  std::string_view line;
  std::vector<std::string_view> fields;
  while (read_line(line)) {
    if (line_no_ <= options_.skip_lines) continue;
    if (options_.comment != 0 && !trimmed(line).empty() &&
        trimmed(line).front() == options_.comment)
      continue;
    if (trimmed(line).empty())
      throw InputError(file_, line_no_, 0, "empty line where the header row was expected");
    split(line, fields);
    std::unordered_set<std::string> seen;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      std::string name(trimmed(fields[c]));
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
    if (options_.comment != 0 && !trimmed(text).empty() &&
        trimmed(text).front() == options_.comment)
      continue;
    if (trimmed(text).empty()) {
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
  for (;;) {
    // A line end in the bytes read: LF, CR LF, or a lone CR (its next byte must be read to know).
    const char* data = buffer_.data();
    const std::size_t at = line_end(data, begin_, end_);
    const bool cr_needs_next = at < end_ && data[at] == '\r' && at + 1 == end_ && !at_eof_;
    if ((at < end_ && !cr_needs_next) || (at_eof_ && begin_ < end_)) {
      std::size_t next = at;
      if (at < end_)
        next = at + (data[at] == '\r' && at + 1 < end_ && data[at + 1] == '\n' ? 2 : 1);
      line = std::string_view(data + begin_, at - begin_);
      begin_ = next;
      ++line_no_;
      if (line_no_ == 1) {
        // UTF-16 (a spreadsheet's "Unicode text"), then a UTF-8 byte-order mark.
        const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(line[k]); };
        const bool utf16_mark = line.size() >= 2 && ((byte(0) == 0xFF && byte(1) == 0xFE) ||
                                                     (byte(0) == 0xFE && byte(1) == 0xFF));
        const bool nul_pattern = line.size() >= 4 && (line[0] == '\0' || line[1] == '\0') &&
                                 (line[2] == '\0' || line[3] == '\0');
        if (utf16_mark || nul_pattern)
          throw InputError(file_, 1, 1,
                           "is UTF-16 text, not UTF-8: save it as \"CSV UTF-8\" (or convert it, "
                           "e.g. iconv -f UTF-16 -t UTF-8)");
        if (line.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) {
          line.remove_prefix(3);
          if (line.empty() && at == end_) return false;  // a mark and nothing else: empty
        }
      }
      if (const std::size_t nul = line.find('\0'); nul != std::string_view::npos)
        throw InputError(file_, line_no_, nul + 1,
                         "contains a NUL byte: this is not a text CSV file");
      return true;
    }
    if (at_eof_) return false;
    // Keep the unread bytes, then read a chunk more (the buffer grows for a longer line).
    buffer_.erase(0, begin_);
    end_ -= begin_;
    begin_ = 0;
    if (buffer_.size() < end_ + chunk_) buffer_.resize(end_ + chunk_);
    in_.read(buffer_.data() + end_, static_cast<std::streamsize>(buffer_.size() - end_));
    const auto got = static_cast<std::size_t>(in_.gcount());
    end_ += got;
    if (got == 0) at_eof_ = true;
  }
}

void RowReader::split(std::string_view line, std::vector<std::string_view>& fields) {
  split_fields(line, options_.delimiter, file_, line_no_, fields, quoted_);
}

}  // namespace fogdrift::csv
