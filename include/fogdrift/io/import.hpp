// Importing a foreign logger CSV into a fogdrift recording: column mapping and unit conversion.
//
// Real loggers name their columns their own way and log rates in rad/s or °/s, time in ms, and
// temperatures as raw sensor counts. Every conversion here is linear, value = raw·scale + offset,
// and is given per fogdrift column by a unit name (docs/formats.md lists them all):
//   time_s          s | ms | us | iso8601 (date and time) | clock (time of day, HH:MM[:SS[.f]]),
//                   counted from the first stamp or from ImportOptions::time_zero
//   gyro_dph        deg/h | deg/s | rad/s | mrad/s | arcsec/s
//   temp_*_degc, chamber_degc   degC | K | degF
//   any column      counts:SCALE:OFFSET (value = counts·SCALE + OFFSET in the column's unit)
//                   | intN:SCALE:OFFSET (an N-bit two's complement register, N = 8, 12, 16, 24,
//                     32, logged signed or as its unsigned bit pattern)
//   accel_*_g       g | mg | m/s2
//   sf_*_ppm        ppm | % | ppb
//   table_deg       deg | rad
// Besides fogdrift's own columns, a unit's further channels are mapped by names that say what they
// are: gyro_NAME_dph (another gyro axis, rate units), temp_NAME_degc (another thermometer),
// accel_NAME_g (another accelerometer) and sf_NAME_ppm (a scale-factor channel). They are kept as
// numeric extra columns, in fogdrift units, and put on a grid like the known ones (regrid.hpp).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/io/recording.hpp"
#include "fogdrift/signal/hampel.hpp"

namespace fogdrift {

/// value_in_fogdrift_units = raw·scale + offset, where raw is first read as an N-bit two's
/// complement integer when signed_bits = N > 0 (so 65535 is −1 for N = 16).
struct LinearConversion {
  double scale = 1.0;
  double offset = 0.0;
  int signed_bits = 0;    ///< 0: the raw value as it is; N: an N-bit signed register
  bool datetime = false;  ///< time_s only: an ISO 8601 date and time, read as seconds
  /// time_s only: a time of day, read as seconds since midnight; a stamp more than 12 h before
  /// the one above it is on the next day (a log through midnight).
  bool clock = false;
};

/// The conversion named by `unit` for fogdrift column `column` (e.g. "gyro_dph", "rad/s").
/// Throws OptionError naming "--unit COLUMN=UNIT" and the units that column accepts.
LinearConversion parse_unit(std::string_view column, std::string_view unit);

struct ImportOptions {
  /// fogdrift column or further channel -> foreign column name. A fogdrift column not in the map
  /// is taken from a foreign column of the same name, if there is one.
  std::map<std::string, std::string> columns;
  /// fogdrift column -> conversion; columns not listed are already in fogdrift units.
  std::map<std::string, LinearConversion> conversions;
  char delimiter = ',';         ///< ',' | ';' | '\t'
  bool decimal_comma = false;   ///< numbers written "1,5" (needs a delimiter other than ',')
  bool time_from_zero = false;  ///< subtract the first time stamp (loggers that count from boot)
  std::size_t skip_lines = 0;   ///< lines before the header to skip (a logger's preamble)
  /// A file with no time column: time_s = row index / this rate, Hz (0: the file has time_s).
  double time_from_rate_hz = 0;
  /// With iso8601 or clock stamps: the instant time_s counts from, in the column's form (a date
  /// and time, or a time of day, taken within 12 h of the first stamp), instead of the first
  /// stamp. Two logs of one test imported with the same time zero share a time axis; a log that
  /// starts before it has negative times, which only a log to join may have.
  std::string time_zero;
  /// A file with no gyro column or no FOG thermometer is imported as a log to join
  /// (Recording::partial; fogdrift join) instead of being refused.
  bool allow_partial = false;
  char comment = 0;  ///< lines starting with this character are skipped; 0: none
  /// An empty cell in a mapped column takes the value of the row before (channels logged slower
  /// than the others); without this it is an error.
  bool hold_empty = false;
  bool keep_extra = true;  ///< keep unmapped foreign columns as extra columns
  /// A time stamp smaller than the one before is a power cycle (a logger counting from its own
  /// boot) and starts a new recording, its times as logged (time_from_zero applies to each);
  /// without this it is an error. Only import_recordings() accepts it.
  bool split_at_reset = false;
  /// Spike removal (signal/hampel.hpp) on the columns in outlier_columns, after unit conversion;
  /// none when empty.
  std::optional<signal::HampelOptions> outliers;
  /// fogdrift columns the spike removal looks at; every one must be in the recording. Empty:
  /// gyro_dph and every thermometer the recording has.
  std::vector<std::string> outlier_columns;
};

/// What import changed besides units: the samples the spike removal replaced, per column.
struct ImportReport {
  struct Replaced {
    std::string column;
    std::vector<std::size_t> lines;  ///< the file lines of the replaced samples
    std::vector<double> was, now;    ///< their values before and after, fogdrift units
  };
  std::vector<Replaced> outliers;  ///< one entry per column looked at, in outlier_columns order
  /// With hold_empty: per fogdrift column, the number of empty cells that took the value before.
  std::map<std::string, std::size_t> held;
  /// What the CSV reading dropped (a spreadsheet's empty columns and rows), one sentence each.
  std::vector<std::string> notes;
  /// With allow_partial: the required columns the file lacks (the log is then one to join).
  std::vector<std::string> missing;
};

/// Reads the foreign file `path` and returns a validated recording. Throws InputError naming the
/// file, line and column for bad cells and non-increasing time, and OptionError for a mapping to a
/// column the file does not have or an impossible option combination.
/// When `report` is given it receives what the spike removal replaced.
Recording import_recording(const std::filesystem::path& path, const ImportOptions& options,
                           ImportReport* report = nullptr);

/// The same for a log that may hold several power cycles (options.split_at_reset): one recording
/// per cycle, in file order. Spikes are looked for within each cycle.
std::vector<Recording> import_recordings(const std::filesystem::path& path,
                                         const ImportOptions& options,
                                         ImportReport* report = nullptr);

}  // namespace fogdrift
