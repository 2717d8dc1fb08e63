#include "fogdrift/io/import.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/io/timestamp.hpp"

namespace fogdrift {
namespace {

// Rows that hold a time and nothing else (a sheet's schedule filled in ahead of its readings) are
// padding too: dropped and counted in the table's notes, never read as empty readings.
void drop_time_only_rows(csv::Table& table, const ImportOptions& options) {
  const auto mapped = options.columns.find("time_s");
  const auto time = table.find(mapped == options.columns.end() ? "time_s" : mapped->second);
  if (!time) return;
  auto blank = [](const std::string& cell) {
    return cell.find_first_not_of(" \t") == std::string::npos;
  };
  std::size_t kept = 0, dropped = 0, first_line = 0, last_line = 0;
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const std::vector<std::string>& row = table.rows[i];
    bool time_only = !blank(row[*time]) && row.size() > 1;
    for (std::size_t c = 0; c < row.size() && time_only; ++c)
      time_only = c == *time || blank(row[c]);
    if (time_only) {
      if (dropped++ == 0) first_line = table.row_line[i];
      last_line = table.row_line[i];
      continue;
    }
    if (kept != i) {
      table.rows[kept] = std::move(table.rows[i]);
      table.row_line[kept] = table.row_line[i];
    }
    ++kept;
  }
  table.rows.resize(kept);
  table.row_line.resize(kept);
  if (dropped > 0)
    table.notes.push_back(fmt::format("dropped {} row(s) with a time and no values (lines {}..{})",
                                      dropped, first_line, last_line));
}

bool starts_with(std::string_view s, std::string_view p) {
  return s.substr(0, p.size()) == p;
}

bool is_fogdrift_column(std::string_view name) {
  for (const auto& n : required_columns())
    if (n == name) return true;
  for (const auto& n : optional_columns())
    if (n == name) return true;
  return false;
}

bool is_target(std::string_view name) {
  return is_fogdrift_column(name) || is_channel_column(name);
}

}  // namespace

LinearConversion parse_unit(std::string_view column, std::string_view unit) {
  const std::string option = fmt::format("--unit {}={}", column, unit);
  constexpr double kRadToDeg = 180.0 / std::numbers::pi;
  auto unknown = [&](std::string_view accepted) -> LinearConversion {
    throw OptionError(
        option, fmt::format("unknown unit '{}' for {} (accepted: {})", unit, column, accepted));
  };
  if (!is_target(column))
    throw OptionError(option,
                      fmt::format("'{}' is not a fogdrift column, nor a channel named "
                                  "gyro_NAME_dph, temp_NAME_degc, accel_NAME_g or sf_NAME_ppm",
                                  column));
  // Raw counts and signed registers, for any column: value = raw·SCALE + OFFSET in the column's
  // own unit (°/h, °C, g, °, s).
  if (starts_with(unit, "counts:")) {
    const std::string_view rest = unit.substr(7);
    const auto colon = rest.find(':');
    if (colon == std::string_view::npos) {
      throw OptionError(option,
                        "counts needs a scale and an offset: counts:SCALE:OFFSET, "
                        "meaning value = counts·SCALE + OFFSET in the column's unit");
    }
    const auto scale = csv::parse_number(rest.substr(0, colon));
    const auto offset = csv::parse_number(rest.substr(colon + 1));
    if (!scale || !offset || *scale == 0.0) {
      throw OptionError(option, "counts:SCALE:OFFSET needs finite numbers and a non-zero SCALE");
    }
    return {*scale, *offset};
  }
  if (starts_with(unit, "int")) {
    const std::string_view rest = unit.substr(3);
    const auto c1 = rest.find(':');
    const auto c2 = c1 == std::string_view::npos ? c1 : rest.find(':', c1 + 1);
    const std::string_view bits = rest.substr(0, c1);
    int n = 0;
    for (int b : {8, 12, 16, 24, 32})
      if (bits == std::to_string(b)) n = b;
    if (n == 0 || c2 == std::string_view::npos) {
      throw OptionError(
          option,
          "a signed register is intN:SCALE:OFFSET with N = 8, 12, 16, 24 or 32, "
          "meaning value = register·SCALE + OFFSET in the column's unit, e.g. int16:0.0078125:0");
    }
    const auto scale = csv::parse_number(rest.substr(c1 + 1, c2 - c1 - 1));
    const auto offset = csv::parse_number(rest.substr(c2 + 1));
    if (!scale || !offset || *scale == 0.0) {
      throw OptionError(option, "intN:SCALE:OFFSET needs finite numbers and a non-zero SCALE");
    }
    return {*scale, *offset, n};
  }
  if (column == "time_s") {
    if (unit == "s") return {1.0, 0.0};
    if (unit == "ms") return {1e-3, 0.0};
    if (unit == "us") return {1e-6, 0.0};
    if (unit == "iso8601" || unit == "clock") {
      LinearConversion c;
      (unit == "clock" ? c.clock : c.datetime) = true;
      return c;
    }
    return unknown(
        "s, ms, us, iso8601 (2024-03-01 12:00:00.125), clock (15:45 or 15:45:30.5, a time of "
        "day); stamps count from the first one, or from --time-zero");
  }
  if (column == "gyro_dph" || starts_with(column, "gyro_")) {
    if (unit == "deg/h") return {1.0, 0.0};
    if (unit == "deg/s") return {3600.0, 0.0};
    if (unit == "rad/s") return {kRadToDeg * 3600.0, 0.0};
    if (unit == "mrad/s") return {kRadToDeg * 3.6, 0.0};
    if (unit == "arcsec/s") return {1.0, 0.0};  // 1″/s = (1/3600)°/s = 1 °/h
    return unknown("deg/h, deg/s, rad/s, mrad/s, arcsec/s");
  }
  if (starts_with(column, "temp_") || column == "chamber_degc") {
    if (unit == "degC") return {1.0, 0.0};
    if (unit == "K") return {1.0, -273.15};
    if (unit == "degF") return {5.0 / 9.0, -32.0 * 5.0 / 9.0};
    return unknown("degC, K, degF, counts:SCALE:OFFSET, intN:SCALE:OFFSET");
  }
  if (starts_with(column, "accel_")) {
    if (unit == "g") return {1.0, 0.0};
    if (unit == "mg") return {1e-3, 0.0};
    if (unit == "m/s2") return {1.0 / 9.80665, 0.0};
    return unknown("g, mg, m/s2");
  }
  if (starts_with(column, "sf_")) {
    if (unit == "ppm") return {1.0, 0.0};
    if (unit == "%") return {1e4, 0.0};
    if (unit == "ppb") return {1e-3, 0.0};
    return unknown("ppm, %, ppb");
  }
  if (column == "table_deg") {
    if (unit == "deg") return {1.0, 0.0};
    if (unit == "rad") return {kRadToDeg, 0.0};
    return unknown("deg, rad");
  }
  throw OptionError(option, fmt::format("'{}' is not a fogdrift column", column));
}

std::vector<Recording> import_recordings(const std::filesystem::path& path,
                                         const ImportOptions& options, ImportReport* report) {
  if (options.decimal_comma && options.delimiter == ',') {
    throw OptionError("--decimal-comma", "needs a delimiter other than ',' (use --delimiter ';')");
  }
  for (const auto& [target, source] : options.columns) {
    if (!is_target(target)) {
      throw OptionError(
          fmt::format("--map {}={}", target, source),
          fmt::format("'{}' is not a fogdrift column (known: time_s, gyro_dph, "
                      "temp_fog_degc, temp_acc1_degc, temp_acc2_degc, accel_x_g, "
                      "accel_y_g, table_deg, chamber_degc), nor a further channel "
                      "(gyro_NAME_dph, temp_NAME_degc, accel_NAME_g, sf_NAME_ppm: lower case, "
                      "digits and _)",
                      target));
    }
  }
  for (const auto& [target, conversion] : options.conversions) {
    if (!is_target(target)) {
      throw OptionError(fmt::format("--unit {}", target), "not a fogdrift column");
    }
    if (is_channel_column(target) && !options.columns.count(target)) {
      throw OptionError(
          fmt::format("--unit {}", target),
          fmt::format("a further channel needs its column too: --map {}=COLUMN", target));
    }
  }

  const auto time_conv = options.conversions.find("time_s");
  const bool stamps = time_conv != options.conversions.end() &&
                      (time_conv->second.datetime || time_conv->second.clock);
  std::optional<double> zero;  // the instant the stamps count from, when given
  if (!options.time_zero.empty()) {
    if (!stamps)
      throw OptionError("--time-zero",
                        "needs stamps: --unit time_s=iso8601 or --unit time_s=clock");
    if (time_conv->second.datetime) {
      zero = parse_datetime(options.time_zero);
      if (!zero)
        throw OptionError("--time-zero",
                          fmt::format("'{}' is not a date and time (YYYY-MM-DD HH:MM[:SS[.fff]]), "
                                      "as the time column's iso8601 stamps are",
                                      csv::excerpt(options.time_zero)));
    } else {
      zero = parse_clock(options.time_zero);
      if (!zero)
        throw OptionError("--time-zero",
                          fmt::format("'{}' is not a time of day (HH:MM[:SS[.fff]]), as the time "
                                      "column's clock stamps are",
                                      csv::excerpt(options.time_zero)));
    }
  }

  // A spreadsheet's padding (nameless empty columns, rows of empty cells) is dropped with a note.
  csv::Table table =
      csv::read(path.string(), {options.delimiter, options.skip_lines, options.comment, true});
  const std::string& file = table.file;
  drop_time_only_rows(table, options);
  if (report) report->notes = table.notes;
  std::string available;
  for (const auto& h : table.header) available += (available.empty() ? "'" : ", '") + h + "'";

  Recording rec;
  rec.source = path.string();
  std::set<std::size_t> used;
  auto column_for = [&](const std::string& target) -> std::optional<std::size_t> {
    const auto it = options.columns.find(target);
    if (it == options.columns.end()) return table.find(target);
    const auto index = table.find(it->second);
    if (!index) {
      throw OptionError(
          fmt::format("--map {}={}", target, it->second),
          fmt::format("{} has no column '{}' (columns: {})", file, it->second, available));
    }
    return index;
  };
  auto convert = [&](const std::string& target, std::size_t c) {
    const auto conv_it = options.conversions.find(target);
    const LinearConversion conv =
        conv_it == options.conversions.end() ? LinearConversion{} : conv_it->second;
    std::vector<double> values;
    values.reserve(table.rows.size());
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
      const std::string& cell = table.rows[i][c];
      if (options.hold_empty && !values.empty() &&
          cell.find_first_not_of(" \t") == std::string::npos) {
        values.push_back(values.back());  // a channel logged slower than the others
        if (report) ++report->held[target];
        continue;
      }
      if (conv.datetime) {
        const auto seconds = parse_datetime(cell);
        if (!seconds) {
          throw InputError(file, table.row_line[i], c + 1,
                           fmt::format("column '{}' (for {}): '{}' is not a date and time "
                                       "(YYYY-MM-DD HH:MM[:SS[.fff]], T allowed, Z or ±HH:MM; "
                                       "a time of day alone is --unit {}=clock)",
                                       table.header[c], target, csv::excerpt(cell), target));
        }
        values.push_back(*seconds);
        continue;
      }
      if (conv.clock) {
        const auto seconds = parse_clock(cell);
        if (!seconds) {
          throw InputError(file, table.row_line[i], c + 1,
                           fmt::format("column '{}' (for {}): '{}' is not a time of day "
                                       "(HH:MM, HH:MM:SS or HH:MM:SS.fff; a date and time is "
                                       "--unit {}=iso8601)",
                                       table.header[c], target, csv::excerpt(cell), target));
        }
        // A log through midnight: a stamp more than 12 h before the one above is the next day.
        double day = values.empty() ? 0.0 : std::floor(values.back() / 86400.0) * 86400.0;
        if (!values.empty() && day + *seconds < values.back() - 43200.0) day += 86400.0;
        values.push_back(day + *seconds);
        continue;
      }
      const auto v = csv::parse_number(cell, options.decimal_comma);
      if (!v) {
        throw InputError(file, table.row_line[i], c + 1,
                         fmt::format("column '{}' (for {}): '{}' is not a finite number",
                                     table.header[c], target, csv::excerpt(cell)));
      }
      double raw = *v;
      if (conv.signed_bits > 0) {
        const double range = std::ldexp(1.0, conv.signed_bits);  // 2^N
        if (raw != std::floor(raw) || raw < -range / 2 || raw >= range) {
          throw InputError(file, table.row_line[i], c + 1,
                           fmt::format("column '{}' (for {}): '{}' is not an int{} register value "
                                       "(a whole number in [{}, {}])",
                                       table.header[c], target, csv::excerpt(cell),
                                       conv.signed_bits, -range / 2, range - 1));
        }
        if (raw >= range / 2) raw -= range;  // the unsigned bit pattern of a negative value
      }
      values.push_back(raw * conv.scale + conv.offset);
    }
    used.insert(c);
    return values;
  };

  for (const auto& [target, source] : options.columns) column_for(target);  // mapped columns exist
  const bool synthetic_time = options.time_from_rate_hz != 0;
  if (synthetic_time) {
    if (!(options.time_from_rate_hz > 0) || !std::isfinite(options.time_from_rate_hz))
      throw OptionError("--time-from-rate-hz",
                        fmt::format("{} Hz is not a positive rate", options.time_from_rate_hz));
    if (options.columns.count("time_s"))
      throw OptionError("--time-from-rate-hz", "the file's time column is mapped too; give one");
  }
  std::vector<std::string> missing;
  for (const auto& target : required_columns()) {
    if (target == "time_s" && synthetic_time) continue;
    const auto c = column_for(target);
    if (!c && options.allow_partial && target != "time_s") {
      missing.push_back(target);
      continue;
    }
    if (!c) {
      throw OptionError(
          fmt::format("--map {}=COLUMN", target),
          fmt::format("{} has no column '{}'; say which column holds it (columns: "
                      "{}){}",
                      file, target, available,
                      target == "time_s" ? "; a file without time stamps takes them from its "
                                           "sample rate with --time-from-rate-hz R"
                                         : "; a log without it (a chamber sheet, a separate "
                                           "thermometer logger) imports with --partial and is "
                                           "joined into a recording with 'fogdrift join'"));
    }
  }
  if (report) report->missing = missing;
  if (table.rows.size() < 2) {
    throw InputError(
        file, 0, 0,
        fmt::format("has {} data rows; a recording needs at least 2 samples", table.rows.size()));
  }
  if (synthetic_time) {
    for (std::size_t i = 0; i < table.rows.size(); ++i)
      rec.time_s.push_back(static_cast<double>(i) / options.time_from_rate_hz);
  } else {
    rec.time_s = convert("time_s", *column_for("time_s"));
  }
  rec.partial = !missing.empty();
  if (const auto c = column_for("gyro_dph")) rec.gyro_dph = convert("gyro_dph", *c);
  if (const auto c = column_for("temp_fog_degc")) rec.temp_fog_degc = convert("temp_fog_degc", *c);
  for (const auto& name : optional_columns())  // the second and third thermometers among them
    if (auto c = column_for(name)) *known_column(rec, name, true) = convert(name, *c);

  // Further channels (another gyro axis, thermometer, accelerometer or scale-factor channel):
  // numbers in their units.
  for (const auto& [target, source] : options.columns) {
    if (!is_channel_column(target)) continue;
    ExtraColumn channel{target, {}};
    for (double v : convert(target, *column_for(target)))
      channel.cells.push_back(csv::format_number(v));
    rec.extra.push_back(std::move(channel));
  }
  if (options.keep_extra) {
    for (std::size_t c = 0; c < table.header.size(); ++c) {
      if (used.count(c)) continue;
      ExtraColumn extra;
      extra.name = is_fogdrift_column(table.header[c]) || options.columns.count(table.header[c])
                       ? "source_" + table.header[c]
                       : table.header[c];
      extra.cells.reserve(table.rows.size());
      for (const auto& row : table.rows) extra.cells.push_back(row[c]);
      rec.extra.push_back(std::move(extra));
    }
  }

  if (rec.partial && rec.temp_fog_degc.empty() && rec.gyro_dph.empty() && rec.extra.empty() &&
      std::none_of(optional_columns().begin(), optional_columns().end(),
                   [&](const std::string& name) { return known_column(rec, name) != nullptr; })) {
    throw OptionError(
        "--partial",
        fmt::format("{} has no column to join besides the time (columns: {})", file, available));
  }

  // Power cycles: a time smaller than the one before starts a new recording.
  const std::size_t time_col = synthetic_time ? 0 : *column_for("time_s") + 1;
  std::vector<std::size_t> starts = {0};
  for (std::size_t i = 1; i < rec.time_s.size(); ++i) {
    if (rec.time_s[i] > rec.time_s[i - 1]) continue;
    if (rec.time_s[i] < rec.time_s[i - 1] && options.split_at_reset) {
      starts.push_back(i);
      continue;
    }
    throw InputError(file, table.row_line[i], time_col,
                     rec.time_s[i] == rec.time_s[i - 1]
                         ? "time does not strictly increase (the same stamp twice)"
                         : "time goes backwards; if the logger was power-cycled here, import "
                           "with --split-at-reset (one recording per power cycle)");
  }
  starts.push_back(rec.time_s.size());

  if (zero && time_conv->second.clock) {
    // The time of day within 12 h of the first stamp (a zero just before midnight, or after).
    const double first = rec.time_s.front();
    *zero += std::floor(first / 86400.0) * 86400.0;
    if (*zero < first - 43200.0) *zero += 86400.0;
    if (*zero > first + 43200.0) *zero -= 86400.0;
  }
  std::vector<Recording> cycles;
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    const std::size_t first = starts[k];
    Recording cycle = slice(rec, first, starts[k + 1]);
    if (cycle.size() < 2) {
      throw InputError(file, table.row_line[first], time_col,
                       "a power cycle of a single sample; a recording needs at least 2");
    }
    if (options.outliers) {
      std::vector<std::string> columns = options.outlier_columns;
      if (columns.empty()) {
        for (const char* name : {"gyro_dph", "temp_fog_degc"})
          if (!known_column(cycle, name)->empty()) columns.emplace_back(name);
        if (!cycle.temp_acc1_degc.empty()) columns.emplace_back("temp_acc1_degc");
        if (!cycle.temp_acc2_degc.empty()) columns.emplace_back("temp_acc2_degc");
      }
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const std::string& name = columns[c];
        // A signal the cycle has: not the time or the turntable position.
        std::vector<double>* x =
            name == "time_s" || name == "table_deg" ? nullptr : known_column(cycle, name);
        if (!x || x->empty()) {
          throw OptionError("--outlier-columns",
                            fmt::format("'{}' is not a signal column of {} (gyro_dph, "
                                        "temp_*_degc, and chamber_degc or accel_*_g when present)",
                                        name, file));
        }
        signal::HampelResult h;
        try {
          h = signal::hampel(*x, *options.outliers);
        } catch (const OptionError& e) {
          throw OptionError(e.option() == "half_window" ? "--hampel-half-window" : "--hampel-sigma",
                            e.message());
        }
        if (report) {
          if (k == 0) report->outliers.push_back({name, {}, {}, {}});
          ImportReport::Replaced& r = report->outliers[c];
          for (std::size_t i : h.replaced) {
            r.lines.push_back(table.row_line[first + i]);
            r.was.push_back((*x)[i]);
            r.now.push_back(h.signal[i]);
          }
        }
        *x = std::move(h.signal);
      }
    }
    if (options.time_from_zero || stamps) {  // dates and times count from the first stamp
      const double t0 = zero ? *zero : cycle.time_s.front();
      for (double& t : cycle.time_s) t -= t0;
    }
    if (cycle.time_s.front() < 0.0 && !cycle.partial) {
      throw InputError(file, table.row_line[first], time_col,
                       zero ? "the first stamp is before --time-zero; a recording's time counts "
                              "from power-on (only a log to join, --partial, may start before)"
                            : "time is negative after conversion (use --time-from-zero for "
                              "loggers that do not count from power-on)");
    }
    validate(cycle);
    cycles.push_back(std::move(cycle));
  }
  return cycles;
}

Recording import_recording(const std::filesystem::path& path, const ImportOptions& options,
                           ImportReport* report) {
  ImportOptions one = options;
  one.split_at_reset = false;
  return std::move(import_recordings(path, one, report).front());
}

}  // namespace fogdrift
