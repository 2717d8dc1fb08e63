// A recording: one logger file of a north-finding system (NFS), one row per sample.
//
// File format (docs/formats.md): CSV with a header row. Required columns, in any order:
//   time_s          seconds since power-on, strictly increasing
//   gyro_dph        FOG rate output, °/h
//   temp_fog_degc   FOG built-in thermometer, °C (a unit with one thermometer logs it here)
// Thermometers the unit may lack (docs/logs.md, "Fewer thermometers"):
//   temp_acc1_degc  accelerometer 1 built-in thermometer, °C
//   temp_acc2_degc  accelerometer 2 built-in thermometer, °C
// In memory an absent thermometer is an empty column. Other optional columns: accel_x_g,
// accel_y_g (accelerometers, g), table_deg (turntable angle, °), chamber_degc (chamber air, °C,
// for reference only). Any other column is kept verbatim and ignored by the method.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fogdrift {

/// A column fogdrift does not interpret, kept as text so that a round trip loses nothing.
struct ExtraColumn {
  std::string name;
  std::vector<std::string> cells;
};

struct Recording {
  std::vector<double> time_s;
  std::vector<double> gyro_dph;
  std::vector<double> temp_fog_degc;
  std::vector<double> temp_acc1_degc;  ///< empty when the unit has no such thermometer
  std::vector<double> temp_acc2_degc;  ///< empty when the unit has no such thermometer
  std::optional<std::vector<double>> accel_x_g;
  std::optional<std::vector<double>> accel_y_g;
  std::optional<std::vector<double>> table_deg;
  std::optional<std::vector<double>> chamber_degc;
  std::vector<ExtraColumn> extra;
  /// Where the recording was read from (for messages); empty for one made in memory.
  std::string source;
  /// A log to join into a recording (docs/logs.md, "Temperatures from another file"), such as a
  /// chamber sheet: gyro_dph and temp_fog_degc may be absent (empty) and time may be negative,
  /// counted from an instant the user chose. Made by import and read_log(); read_recording()
  /// never makes one.
  bool partial = false;

  std::size_t size() const { return time_s.size(); }

  /// Column `name` as numbers: a known column, or an extra one parsed strictly.
  /// Throws InputError (file, line, column) if an extra cell is not a finite number, and
  /// std::out_of_range naming the column if there is no such column.
  std::vector<double> numeric_column(std::string_view name) const;
  bool has_column(std::string_view name) const;
};

/// The known numeric column `name` of `recording` (time_s, gyro_dph, a thermometer or an optional
/// column); nullptr for any other name and for a column the recording lacks. With `create`, a
/// missing optional column or thermometer is created empty and returned.
std::vector<double>* known_column(Recording& recording, std::string_view name, bool create = false);
const std::vector<double>* known_column(const Recording& recording, std::string_view name);

/// A further channel a unit logs, named by what it is so that its unit is known: another gyro
/// axis (gyro_NAME_dph), thermometer (temp_NAME_degc), accelerometer (accel_NAME_g) or
/// scale-factor channel (sf_NAME_ppm, the unit's estimate of its scale-factor error), NAME of
/// lower-case letters, digits and '_'; not one of fogdrift's own columns. Kept as an extra column
/// of numbers (docs/logs.md, "Further channels").
bool is_channel_column(std::string_view name);

/// The cells of an extra column as numbers; nothing when one is not a finite number (a column
/// of text).
std::optional<std::vector<double>> numbers_of(const ExtraColumn& column);

/// The required and optional column names, in the order fogdrift writes them.
const std::vector<std::string>& required_columns();
const std::vector<std::string>& optional_columns();

/// The median of the steps between consecutive times, s (0 for fewer than 2 samples).
double median_time_step_s(const std::vector<double>& time_s);

/// Reads a recording, strictly: throws InputError naming file, line and column for a missing
/// required column, a non-number, NaN or Inf in a known column, a time that does not strictly
/// increase, a negative time, fewer than 2 samples, and every CSV-level fault of csv::read.
Recording read_recording(const std::filesystem::path& path);
/// The same, holding of the columns beyond the known ones only those named in `keep_extra`:
/// every other is checked as the CSV is, and left on disk (a kilohertz log's text columns cost
/// a string a sample; compensate copies them from the file as they are).
Recording read_recording(const std::filesystem::path& path,
                         const std::vector<std::string>& keep_extra);

/// Reads a log to join (Recording::partial): time_s is the one required column, and it may be
/// negative; everything else read_recording() checks is checked the same way.
Recording read_log(const std::filesystem::path& path);

/// The known columns a partial log lacks of the required ones (gyro_dph, temp_fog_degc); empty
/// for a whole recording.
std::vector<std::string> missing_required(const Recording& recording);

/// Checks the invariants read_recording() enforces on a recording built in memory (equal column
/// lengths, finite values, strictly increasing time). Throws InputError naming `source`.
void validate(const Recording& recording);

/// Samples [begin, end) of `recording`, every column (extras too); source is kept.
/// Throws std::out_of_range when the range is not inside the recording.
Recording slice(const Recording& recording, std::size_t begin, std::size_t end);

/// Writes the recording atomically: known columns in the canonical order, then the extras (a
/// partial log without the required columns it lacks).
void write_recording(const std::filesystem::path& path, const Recording& recording);

/// The recording as CSV text (what write_recording() writes).
std::string to_csv(const Recording& recording);

}  // namespace fogdrift
