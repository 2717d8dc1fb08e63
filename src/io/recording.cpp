#include "fogdrift/io/recording.hpp"

#include <fmt/format.h>
#include <algorithm>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/csv_rows.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift {

std::vector<double>* known_column(Recording& r, std::string_view name, bool create) {
  auto opt = [&](std::optional<std::vector<double>>& col) -> std::vector<double>* {
    if (!col && create) col.emplace();
    return col ? &*col : nullptr;
  };
  if (name == "time_s") return &r.time_s;
  if (name == "gyro_dph") return &r.gyro_dph;
  if (name == "temp_fog_degc") return &r.temp_fog_degc;
  // The second and third thermometers may be absent: an empty column (recording.hpp).
  if (name == "temp_acc1_degc")
    return create || !r.temp_acc1_degc.empty() ? &r.temp_acc1_degc : nullptr;
  if (name == "temp_acc2_degc")
    return create || !r.temp_acc2_degc.empty() ? &r.temp_acc2_degc : nullptr;
  if (name == "accel_x_g") return opt(r.accel_x_g);
  if (name == "accel_y_g") return opt(r.accel_y_g);
  if (name == "table_deg") return opt(r.table_deg);
  if (name == "chamber_degc") return opt(r.chamber_degc);
  return nullptr;
}

const std::vector<double>* known_column(const Recording& r, std::string_view name) {
  return known_column(const_cast<Recording&>(r), name, false);
}

namespace {

bool is_known(std::string_view name) {
  for (const auto& n : required_columns())
    if (n == name) return true;
  for (const auto& n : optional_columns())
    if (n == name) return true;
  return false;
}

void check_time(const std::vector<double>& time_s, const std::string& file,
                const std::vector<std::size_t>* lines, std::size_t column, bool partial) {
  auto line_of = [&](std::size_t i) { return lines ? (*lines)[i] : i + 2; };
  if (!partial && !time_s.empty() && time_s[0] < 0.0) {
    throw InputError(file, line_of(0), column,
                     fmt::format("time_s = {} is negative (time is seconds since power-on)",
                                 csv::format_number(time_s[0])));
  }
  for (std::size_t i = 1; i < time_s.size(); ++i) {
    if (!(time_s[i] > time_s[i - 1])) {
      throw InputError(
          file, line_of(i), column,
          fmt::format("time_s = {} does not increase (previous row: {}); time must "
                      "strictly increase",
                      csv::format_number(time_s[i]), csv::format_number(time_s[i - 1])));
    }
  }
}

// The range a known column's readings must lie in (docs/formats.md): wide enough for any
// instrument and chamber, narrow enough that nothing computed from a reading (rates, gradients,
// sums of squares) can overflow a double. A temperature of 1e308 °C is finite, and turned a
// compensation into inf before the rule.
struct Plausible {
  double min, max;
  const char* rule;
};

std::optional<Plausible> plausible_range(std::string_view name) {
  if (name == "time_s") return Plausible{-1e12, 1e12, "is beyond ±1e12 s"};
  if (name.ends_with("_degc"))
    return Plausible{-273.15, 1000, "is not a temperature from -273.15 to 1000 °C"};
  if (name == "gyro_dph") return Plausible{-1e9, 1e9, "is beyond ±1e9 °/h"};
  if (name.ends_with("_g")) return Plausible{-1e4, 1e4, "is beyond ±1e4 g"};
  if (name == "table_deg") return Plausible{-1e9, 1e9, "is beyond ±1e9°"};
  return std::nullopt;
}

}  // namespace

const std::vector<std::string>& required_columns() {
  static const std::vector<std::string> names = {"time_s", "gyro_dph", "temp_fog_degc"};
  return names;
}

const std::vector<std::string>& optional_columns() {
  static const std::vector<std::string> names = {
      "temp_acc1_degc", "temp_acc2_degc", "accel_x_g", "accel_y_g", "table_deg", "chamber_degc"};
  return names;
}

bool is_channel_column(std::string_view name) {
  if (is_known(name) || name.empty()) return false;
  for (char ch : name)
    if (!((ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_')) return false;
  auto between = [&](std::string_view prefix, std::string_view suffix) {
    return name.size() > prefix.size() + suffix.size() && name.starts_with(prefix) &&
           name.ends_with(suffix);
  };
  return between("gyro_", "_dph") || between("temp_", "_degc") || between("accel_", "_g") ||
         between("sf_", "_ppm");
}

std::optional<std::vector<double>> numbers_of(const ExtraColumn& column) {
  std::vector<double> values;
  values.reserve(column.cells.size());
  for (const std::string& cell : column.cells) {
    const auto v = csv::parse_number(cell);
    if (!v) return std::nullopt;
    values.push_back(*v);
  }
  return values;
}

bool Recording::has_column(std::string_view name) const {
  if (known_column(*this, name) != nullptr) return true;
  for (const auto& e : extra)
    if (e.name == name) return true;
  return false;
}

std::vector<double> Recording::numeric_column(std::string_view name) const {
  if (const auto* col = known_column(*this, name)) return *col;
  for (std::size_t c = 0; c < extra.size(); ++c) {
    if (extra[c].name != name) continue;
    std::vector<double> values;
    values.reserve(extra[c].cells.size());
    for (std::size_t i = 0; i < extra[c].cells.size(); ++i) {
      const auto v = csv::parse_number(extra[c].cells[i]);
      if (!v) {
        throw InputError(source, i + 2, 0,
                         fmt::format("column '{}': '{}' {}", name, csv::excerpt(extra[c].cells[i]),
                                     csv::why_not_a_number(extra[c].cells[i])));
      }
      values.push_back(*v);
    }
    return values;
  }
  throw std::out_of_range(fmt::format("{}: no column '{}'", source, name));
}

namespace {

/// `keep_extra`: the columns beyond the known ones to hold; null: every one.
Recording read_table(const std::filesystem::path& path, bool partial,
                     const std::vector<std::string>* keep_extra = nullptr) {
  // Row by row: a kilohertz log costs its numbers, not a string per field (csv_rows.hpp).
  std::ifstream in = open_text_file(path);
  csv::RowReader table(in, path.string());
  const std::string& file = table.file();
  for (const auto& name : required_columns()) {
    if (partial && name != "time_s") continue;
    if (!table.find(name)) {
      throw InputError(file, 1, 0,
                       fmt::format("missing required column '{}' (required: time_s, gyro_dph, "
                                   "temp_fog_degc; temp_acc1_degc and temp_acc2_degc when the "
                                   "unit has them; use 'fogdrift import' for other names or "
                                   "units, and 'fogdrift join' to add columns from a log of "
                                   "their own)",
                                   name));
    }
  }

  Recording rec;
  rec.source = path.string();
  rec.partial = partial;
  // Each column's destination: a known column's numbers, or an extra column's text.
  const std::vector<std::string>& header = table.header();
  std::vector<std::vector<double>*> numbers(header.size(), nullptr);
  std::vector<std::optional<Plausible>> ranges(header.size());
  std::vector<std::size_t> extra_of(header.size(), 0);
  std::vector<char> left(header.size(), 0);  // an extra column not held
  for (std::size_t c = 0; c < header.size(); ++c) {
    numbers[c] = known_column(rec, header[c], true);
    if (numbers[c]) {
      ranges[c] = plausible_range(header[c]);
    } else if (keep_extra &&
               std::find(keep_extra->begin(), keep_extra->end(), header[c]) == keep_extra->end()) {
      left[c] = 1;
    } else {
      extra_of[c] = rec.extra.size();
      rec.extra.push_back({header[c], {}});
    }
  }
  // The simulator's true drift is the one extra column fogdrift computes with (the floor of
  // northfind and paper): it must be numbers from the start, not when it is first used.
  const std::optional<std::size_t> true_drift = table.find("drift_true_dph");
  std::vector<std::size_t> row_line;
  std::vector<std::string_view> fields;
  std::size_t line = 0;
  // A log's size over its first rows' length: the rows to hold, reserved once, so that a
  // kilohertz log's columns are not copied as they grow (reserved, never-written memory costs
  // no pages). The rest of the file is assumed no shorter a row than the first rows.
  std::error_code size_error;
  const std::uintmax_t file_bytes = std::filesystem::file_size(path, size_error);
  std::size_t sampled_bytes = 0;
  constexpr std::size_t kSampledRows = 256;
  while (table.next(fields, line)) {
    if (row_line.size() < kSampledRows) {
      sampled_bytes += table.row_text().size() + 1;
      if (row_line.size() + 1 == kSampledRows && !size_error) {
        const auto rows = static_cast<std::size_t>(
            static_cast<double>(file_bytes) / static_cast<double>(sampled_bytes) * kSampledRows);
        try {
          row_line.reserve(rows);
          for (std::vector<double>* column : numbers)
            if (column) column->reserve(rows);
        } catch (const std::bad_alloc&) {
          // An estimate the address space refuses (ulimit -v): the columns grow as they fill.
        }
      }
    }
    row_line.push_back(line);
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string_view cell = fields[c];
      if (left[c]) continue;
      if (numbers[c] == nullptr) {
        if (true_drift == c && !csv::parse_number(cell))
          throw InputError(file, line, c + 1,
                           fmt::format("column 'drift_true_dph': '{}' is not a finite number",
                                       csv::excerpt(cell)));
        rec.extra[extra_of[c]].cells.emplace_back(cell);
        continue;
      }
      const auto v = csv::parse_number(cell);
      if (!v)
        throw InputError(file, line, c + 1,
                         fmt::format("column '{}': value '{}' {}", header[c], csv::excerpt(cell),
                                     csv::why_not_a_number(cell)));
      const std::optional<Plausible>& range = ranges[c];
      if (range && !(*v >= range->min && *v <= range->max))
        throw InputError(
            file, line, c + 1,
            fmt::format("column '{}': value '{}' {}", header[c], csv::excerpt(cell), range->rule));
      numbers[c]->push_back(*v);
    }
  }
  if (row_line.size() < 2) {
    throw InputError(
        file, 0, 0,
        fmt::format("has {} data rows; a recording needs at least 2 samples", row_line.size()));
  }
  check_time(rec.time_s, file, &row_line, *table.find("time_s") + 1, partial);
  return rec;
}

}  // namespace

Recording read_recording(const std::filesystem::path& path) {
  return read_table(path, false);
}

Recording read_recording(const std::filesystem::path& path,
                         const std::vector<std::string>& keep_extra) {
  return read_table(path, false, &keep_extra);
}

Recording read_log(const std::filesystem::path& path) {
  return read_table(path, true);
}

std::vector<std::string> missing_required(const Recording& r) {
  std::vector<std::string> missing;
  for (const auto& name : required_columns())
    if (known_column(r, name)->empty()) missing.push_back(name);
  return missing;
}

Recording slice(const Recording& r, std::size_t begin, std::size_t end) {
  if (begin > end || end > r.size()) throw std::out_of_range("slice: range outside the recording");
  const auto b = static_cast<std::ptrdiff_t>(begin), e = static_cast<std::ptrdiff_t>(end);
  Recording out;
  for (const auto* names : {&required_columns(), &optional_columns()}) {
    for (const auto& name : *names) {
      const std::vector<double>* col = known_column(r, name);  // absent stays absent
      if (col && !col->empty())
        *known_column(out, name, true) = std::vector<double>(col->begin() + b, col->begin() + e);
    }
  }
  for (const auto& x : r.extra)
    out.extra.push_back(
        {x.name, std::vector<std::string>(x.cells.begin() + b, x.cells.begin() + e)});
  out.source = r.source;
  out.partial = r.partial;
  return out;
}

void validate(const Recording& r) {
  const std::string file = r.source.empty() ? std::string("<recording>") : r.source;
  const std::size_t n = r.size();
  if (n < 2) throw InputError(file, 0, 0, "a recording needs at least 2 samples");
  auto check = [&](const std::string& name, const std::vector<double>& col) {
    if (col.size() != n) {
      throw InputError(
          file, 0, 0,
          fmt::format("column '{}' has {} values but time_s has {}", name, col.size(), n));
    }
    const std::optional<Plausible> range = plausible_range(name);
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(col[i])) {
        throw InputError(file, i + 2, 0, fmt::format("column '{}' is not finite", name));
      }
      if (range && !(col[i] >= range->min && col[i] <= range->max))
        throw InputError(file, i + 2, 0,
                         fmt::format("column '{}': value {} {}", name, col[i], range->rule));
    }
  };
  for (const auto& name : required_columns()) {
    const std::vector<double>& col = *known_column(r, name);
    if (r.partial && name != "time_s" && col.empty()) continue;  // a log to join may lack it
    check(name, col);
  }
  for (const auto& name : optional_columns()) {
    if (const auto* col = known_column(r, name)) check(name, *col);
  }
  for (const auto& e : r.extra) {
    if (is_known(e.name)) {
      throw InputError(file, 0, 0, fmt::format("extra column '{}' shadows a known column", e.name));
    }
    if (e.cells.size() != n) {
      throw InputError(
          file, 0, 0,
          fmt::format("column '{}' has {} values but time_s has {}", e.name, e.cells.size(), n));
    }
  }
  check_time(r.time_s, file, nullptr, 0, r.partial);
}

std::string to_csv(const Recording& r) {
  validate(r);
  std::vector<std::pair<std::string, const std::vector<double>*>> numeric;
  for (const auto& name : required_columns())
    if (!known_column(r, name)->empty()) numeric.emplace_back(name, known_column(r, name));
  for (const auto& name : optional_columns()) {
    if (const auto* col = known_column(r, name)) numeric.emplace_back(name, col);
  }
  std::string out;
  out.reserve(r.size() * 16 * (numeric.size() + r.extra.size()));
  for (std::size_t c = 0; c < numeric.size(); ++c) {
    if (c) out += ',';
    out += numeric[c].first;
  }
  for (const auto& e : r.extra) {
    out += ',';
    out += csv::quote(e.name);
  }
  out += '\n';
  for (std::size_t i = 0; i < r.size(); ++i) {
    for (std::size_t c = 0; c < numeric.size(); ++c) {
      if (c) out += ',';
      out += csv::format_number((*numeric[c].second)[i]);
    }
    for (const auto& e : r.extra) {
      out += ',';
      out += csv::quote(e.cells[i]);
    }
    out += '\n';
  }
  return out;
}

void write_recording(const std::filesystem::path& path, const Recording& recording) {
  const std::string text = to_csv(recording);
  write_text_atomically(path, text);
}

double median_time_step_s(const std::vector<double>& time_s) {
  if (time_s.size() < 2) return 0.0;
  std::vector<double> steps(time_s.size() - 1);
  for (std::size_t i = 0; i + 1 < time_s.size(); ++i) steps[i] = time_s[i + 1] - time_s[i];
  const auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), mid, steps.end());
  return *mid;
}

}  // namespace fogdrift
