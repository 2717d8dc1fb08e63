#include "fogdrift/base/csv.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift::csv {
std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

namespace {

bool all_blank(const std::vector<std::string>& fields) {
  for (const auto& f : fields)
    if (!trim(f).empty()) return false;
  return true;
}

// drop_empty: removes the header's nameless columns (indices in increasing order) from the table;
// one that holds a value anywhere is an error naming its first such cell.
void drop_nameless(Table& table, const std::vector<std::size_t>& nameless) {
  for (std::size_t c : nameless) {
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      if (!trim(table.rows[i][c]).empty()) {
        throw InputError(table.file, table.row_line[i], c + 1,
                         fmt::format("'{}' is in a column with no name in the header; name the "
                                     "column, or empty it",
                                     excerpt(table.rows[i][c])));
      }
    }
  }
  auto keep = [&](std::vector<std::string>& fields) {
    std::vector<std::string> kept;
    kept.reserve(fields.size() - nameless.size());
    for (std::size_t c = 0, next = 0; c < fields.size(); ++c) {
      if (next < nameless.size() && nameless[next] == c) {
        ++next;
        continue;
      }
      kept.push_back(std::move(fields[c]));
    }
    fields = std::move(kept);
  };
  keep(table.header);
  for (auto& row : table.rows) keep(row);
  std::vector<std::string> where;
  for (std::size_t c : nameless) where.push_back(std::to_string(c + 1));
  table.notes.push_back(fmt::format("dropped {} empty column(s) with no name (column {})",
                                    nameless.size(), fmt::join(where, ", ")));
}

}  // namespace

std::vector<std::string> split_line(std::string_view line, char delimiter, const std::string& file,
                                    std::size_t line_no) {
  std::vector<std::string> fields;
  std::string field;
  std::size_t i = 0;
  while (true) {
    field.clear();
    // Leading spaces before an opening quote are tolerated, as pandas does with skipinitialspace.
    std::size_t j = i;
    while (j < line.size() && line[j] == ' ') ++j;
    if (j < line.size() && line[j] == '"') {
      i = j + 1;
      bool closed = false;
      while (i < line.size()) {
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          closed = true;
          ++i;
          break;
        }
        field += line[i++];
      }
      if (!closed) {
        throw InputError(file, line_no, fields.size() + 1,
                         "unterminated quoted field (quotes must close on the same line)");
      }
      while (i < line.size() && line[i] == ' ') ++i;
      if (i < line.size() && line[i] != delimiter) {
        throw InputError(file, line_no, fields.size() + 1, "unexpected text after a closing quote");
      }
    } else {
      const std::size_t end = line.find(delimiter, i);
      field.assign(
          line.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i));
      i = end == std::string_view::npos ? line.size() : end;
    }
    fields.push_back(field);
    if (i >= line.size()) break;
    ++i;  // skip the delimiter
    if (i == line.size()) {
      fields.emplace_back();  // a trailing delimiter makes one more (empty) field
      break;
    }
  }
  return fields;
}

std::optional<std::size_t> Table::find(std::string_view name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return i;
  }
  return std::nullopt;
}

Table read(const std::string& path, const ReadOptions& options) {
  return parse(read_text_file(path), path, options);
}

Table parse(std::string_view text, const std::string& file, const ReadOptions& options) {
  Table table;
  table.file = file;
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
      static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF) {
    text.remove_prefix(3);
  }
  // UTF-16 (a spreadsheet's "Unicode text"): a byte-order mark, or NULs between ASCII letters.
  const bool utf16_mark = text.size() >= 2 && ((static_cast<unsigned char>(text[0]) == 0xFF &&
                                                static_cast<unsigned char>(text[1]) == 0xFE) ||
                                               (static_cast<unsigned char>(text[0]) == 0xFE &&
                                                static_cast<unsigned char>(text[1]) == 0xFF));
  if (const std::size_t nul = text.find('\0'); utf16_mark || nul != std::string_view::npos) {
    const bool utf16 = utf16_mark || (text.size() >= 4 && (text[0] == '\0' || text[1] == '\0') &&
                                      (text[2] == '\0' || text[3] == '\0'));
    if (utf16)
      throw InputError(file, 1, 1,
                       "is UTF-16 text, not UTF-8: save it as \"CSV UTF-8\" (or convert it, e.g. "
                       "iconv -f UTF-16 -t UTF-8)");
    const std::string before(text.substr(0, nul));
    std::size_t line = 1, column = 1;
    for (char c : before) (c == '\n') ? (++line, column = 1) : ++column;
    throw InputError(file, line, column, "contains a NUL byte: this is not a text CSV file");
  }
  // Lone CRs end lines (old Mac files), as csv::LineReader reads them for stream.
  std::string lf_text;
  for (std::size_t cr = text.find('\r'); cr != std::string_view::npos;
       cr = text.find('\r', cr + 1)) {
    if (cr + 1 < text.size() && text[cr + 1] == '\n') continue;
    lf_text.assign(text);
    for (std::size_t i = cr; i < lf_text.size(); ++i)
      if (lf_text[i] == '\r' && (i + 1 == lf_text.size() || lf_text[i + 1] != '\n'))
        lf_text[i] = '\n';
    text = lf_text;
    break;
  }

  std::size_t pos = 0;
  std::size_t line_no = 0;
  std::size_t pending_blank_line = 0;  // first blank line seen after the header, if any
  bool have_header = false;
  std::vector<std::size_t> nameless;  // drop_empty: header fields with no name, in file order
  std::size_t blank_rows = 0;         // drop_empty: rows of empty fields dropped
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line_no <= options.skip_lines) continue;
    if (options.comment != 0 && !trim(line).empty() && trim(line).front() == options.comment)
      continue;
    if (trim(line).empty()) {
      if (!have_header) {
        throw InputError(file, line_no, 0, "empty line where the header row was expected");
      }
      if (pending_blank_line == 0) pending_blank_line = line_no;
      continue;
    }
    if (pending_blank_line != 0) {
      throw InputError(file, pending_blank_line, 0, "empty line between data rows");
    }
    std::vector<std::string> fields = split_line(line, options.delimiter, file, line_no);
    if (have_header && options.drop_empty && all_blank(fields)) {
      ++blank_rows;  // a spreadsheet's row of empty cells (",,,,")
      continue;
    }
    if (!have_header) {
      std::unordered_set<std::string> seen;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        std::string name(trim(fields[c]));
        if (name.empty() && options.drop_empty) {
          nameless.push_back(c);
          continue;
        }
        if (name.empty()) throw InputError(file, line_no, c + 1, "empty column name in the header");
        if (!seen.insert(name).second) {
          throw InputError(file, line_no, c + 1,
                           fmt::format("duplicated column name '{}' in the header", name));
        }
        fields[c] = std::move(name);
      }
      table.header = std::move(fields);  // nameless ones included until the rows are read
      have_header = true;
      continue;
    }
    if (fields.size() != table.header.size()) {
      throw InputError(file, line_no, 0,
                       fmt::format("row has {} fields but the header has {} columns", fields.size(),
                                   table.header.size()));
    }
    table.rows.push_back(std::move(fields));
    table.row_line.push_back(line_no);
  }
  if (!have_header) throw InputError(file, 0, 0, "empty file: a header row is required");
  if (!nameless.empty()) drop_nameless(table, nameless);
  if (blank_rows > 0)
    table.notes.push_back(fmt::format("dropped {} row(s) with every field empty", blank_rows));
  return table;
}

namespace {

// Whether a decimal number that from_chars found out of range is too small rather than too
// large: the power of ten of its first non-zero digit, with its exponent, is negative.
bool underflows(std::string_view s) {
  if (!s.empty() && (s.front() == '-' || s.front() == '+')) s.remove_prefix(1);
  const std::size_t e = s.find_first_of("eE");
  const std::string_view mantissa = s.substr(0, e);
  long long exponent = 0;
  if (e != std::string_view::npos) {
    std::string_view x = s.substr(e + 1);
    const bool negative = !x.empty() && x.front() == '-';
    if (!x.empty() && (x.front() == '-' || x.front() == '+')) x.remove_prefix(1);
    for (char ch : x) exponent = std::min<long long>(exponent * 10 + (ch - '0'), 1LL << 40);
    if (negative) exponent = -exponent;
  }
  const std::size_t point = std::min(mantissa.find('.'), mantissa.size());
  const std::size_t first = mantissa.find_first_of("123456789");
  if (first == std::string_view::npos) return true;
  const long long place = first < point ? static_cast<long long>(point - first) - 1
                                        : -static_cast<long long>(first - point);
  return place + exponent < 0;
}

// The numbers loggers write, read without from_chars: an optional '-', digits, optionally
// `point` and more digits (at most 19 digits in all), and optionally an exponent ("e-05", at
// most 4 digits). Its digits as an integer m and its power of ten p (the exponent less the
// fraction's length) give the value m × 10^p; with m ≤ 2^53 and |p| ≤ 22 both are exact doubles,
// so the one correctly rounded multiplication or division is the correctly rounded value, the
// double from_chars returns (Clinger's fast path; docs/architecture.md, base/csv). nullopt for
// any other text, which parse_number then reads with from_chars.
std::optional<double> short_decimal(std::string_view s, char point) {
  static constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const char* p = s.data();
  const char* const end = p + s.size();
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  std::uint64_t m = 0;  // 19 digits fit; more wrap, and are refused below
  const char* const whole = p;
  for (; p != end && static_cast<unsigned>(*p - '0') < 10; ++p)
    m = m * 10 + static_cast<unsigned>(*p - '0');
  std::ptrdiff_t count = p - whole, fraction = 0;
  if (count == 0) return std::nullopt;
  if (p != end && *p == point) {
    const char* const first = ++p;
    for (; p != end && static_cast<unsigned>(*p - '0') < 10; ++p)
      m = m * 10 + static_cast<unsigned>(*p - '0');
    fraction = p - first;
    if (fraction == 0) return std::nullopt;
    count += fraction;
  }
  std::ptrdiff_t exponent = 0;
  if (p != end && (*p == 'e' || *p == 'E')) {
    ++p;
    const bool below = p != end && *p == '-';
    if (p != end && (*p == '-' || *p == '+')) ++p;
    const char* const first = p;
    for (; p != end && static_cast<unsigned>(*p - '0') < 10 && p - first < 4; ++p)
      exponent = exponent * 10 + (*p - '0');
    if (p == first) return std::nullopt;
    if (below) exponent = -exponent;
  }
  const std::ptrdiff_t power = exponent - fraction;
  if (p != end || count > 19 || power < -22 || power > 22 || m > (std::uint64_t{1} << 53))
    return std::nullopt;
  const double value =
      power < 0 ? static_cast<double>(m) / kPow10[-power] : static_cast<double>(m) * kPow10[power];
  return negative ? -value : value;
}

}  // namespace

std::optional<double> parse_number(std::string_view field, bool decimal_comma) {
  field = trim(field);
  if (field.empty()) return std::nullopt;
  if (field.front() == '+') field.remove_prefix(1);
  if (field.empty()) return std::nullopt;
  if (const auto quick = short_decimal(field, decimal_comma ? ',' : '.')) return quick;
  std::string replaced;
  if (decimal_comma) {
    if (field.find('.') != std::string_view::npos) return std::nullopt;
    replaced.assign(field);
    const auto comma = replaced.find(',');
    if (comma != std::string::npos) {
      if (replaced.find(',', comma + 1) != std::string::npos) return std::nullopt;
      replaced[comma] = '.';
    }
    field = replaced;
  }
  // from_chars accepts "nan" and "inf"; fogdrift never does.
  for (char ch : field) {
    if (!(std::isdigit(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-' || ch == 'e' ||
          ch == 'E' || ch == '+')) {
      return std::nullopt;
    }
  }
  double value = 0.0;
  const char* first = field.data();
  const char* last = field.data() + field.size();
  const auto result = std::from_chars(first, last, value, std::chars_format::general);
  // A number too small for a double (1e-400) is one: it rounds to zero. Too large is none.
  if (result.ec == std::errc::result_out_of_range && result.ptr == last && underflows(field))
    return field.front() == '-' ? -0.0 : 0.0;
  if (result.ec != std::errc() || result.ptr != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::size_t line_end(const char* data, std::size_t begin, std::size_t end) {
  const void* lf = std::memchr(data + begin, '\n', end - begin);
  const std::size_t stop = lf ? static_cast<std::size_t>(static_cast<const char*>(lf) - data) : end;
  const void* cr = std::memchr(data + begin, '\r', stop - begin);
  return cr ? static_cast<std::size_t>(static_cast<const char*>(cr) - data) : stop;
}

void split_fields(std::string_view line, char delimiter, const std::string& file,
                  std::size_t line_no, std::vector<std::string_view>& fields,
                  std::vector<std::string>& quoted) {
  fields.clear();
  if (line.find('"') != std::string_view::npos) {
    quoted = split_line(line, delimiter, file, line_no);
    for (const std::string& f : quoted) fields.emplace_back(f);
    return;
  }
  for (std::size_t i = 0;;) {
    const std::size_t end = line.find(delimiter, i);
    if (end == std::string_view::npos) {
      fields.push_back(line.substr(i));
      return;
    }
    fields.push_back(line.substr(i, end - i));
    i = end + 1;
  }
}

std::string why_not_a_number(std::string_view cell) {
  const std::string_view field = trim(cell);
  if (field.empty()) return "is empty";
  std::string lower(field.substr(0, 64));
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
    return "is not finite (NaN and Inf are not allowed)";
  double value = 0.0;
  const auto result =
      std::from_chars(field.data(), field.data() + field.size(), value, std::chars_format::general);
  if (result.ec == std::errc::result_out_of_range && result.ptr == field.data() + field.size())
    return "is beyond a double's range (magnitude above 1.8e308)";
  return "is not a number";
}

std::string format_number(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

void append_number(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

std::string quote(std::string_view field, char delimiter) {
  std::string out;
  append_quoted(out, field, delimiter);
  return out;
}

void append_quoted(std::string& out, std::string_view field, char delimiter) {
  // One pass over the field's bytes, not a find per character that needs quotes.
  bool needs = !field.empty() && (field.front() == ' ' || field.back() == ' ');
  for (std::size_t i = 0; i < field.size() && !needs; ++i) {
    const char ch = field[i];
    needs = ch == delimiter || ch == '"' || ch == '\n' || ch == '\r';
  }
  if (!needs) {
    out += field;
    return;
  }
  out += '"';
  for (char ch : field) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
}

std::string excerpt(std::string_view field) {
  constexpr std::size_t kShown = 40;
  // Control bytes (a NUL, a terminal escape) shown as \xNN: a message is one line of text that
  // a NUL would cut short before its rule.
  std::string shown;
  for (const char c : field.substr(0, kShown)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f)
      shown += fmt::format("\\x{:02x}", byte);
    else
      shown += c;
  }
  if (field.size() <= kShown) return shown;
  return fmt::format("{}…({} characters)", shown, field.size());
}

bool LineReader::refill() {
  std::streambuf* in = in_.rdbuf();
  if (buffer_.size() < block_) buffer_.resize(block_);
  begin_ = end_ = 0;
  std::streamsize ready = in->in_avail();
  if (ready <= 0) {
    using traits = std::char_traits<char>;
    const int c = in->sbumpc();  // waits for input
    if (traits::eq_int_type(c, traits::eof())) return false;
    buffer_[end_++] = traits::to_char_type(c);
    ready = in->in_avail();
  }
  if (ready > 0)
    end_ += static_cast<std::size_t>(
        in->sgetn(buffer_.data() + end_,
                  std::min<std::streamsize>(ready, static_cast<std::streamsize>(block_ - end_))));
  return true;
}

bool LineReader::next(std::string& line) {
  line.clear();
  bool any = false;
  for (;;) {
    if (begin_ == end_ && !refill()) {
      in_.setstate(std::ios::eofbit);
      break;
    }
    if (after_cr_) {
      after_cr_ = false;
      if (buffer_[begin_] == '\n') {  // the LF of a CRLF
        ++begin_;
        continue;
      }
    }
    const char* data = buffer_.data();
    const std::size_t at = line_end(data, begin_, end_);
    any = true;
    line.append(data + begin_, at - begin_);
    if (at < end_) {
      after_cr_ = data[at] == '\r';
      begin_ = at + 1;
      break;
    }
    begin_ = end_;
  }
  if (first_ && any) {
    first_ = false;
    if (line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
  }
  return any;
}

}  // namespace fogdrift::csv
