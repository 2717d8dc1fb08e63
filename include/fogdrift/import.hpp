// Importing a foreign logger CSV into a fogdrift recording: column mapping and unit conversion.
//
// Real loggers name their columns their own way and log rates in rad/s or °/s, time in ms, and
// temperatures as raw sensor counts. Every conversion here is linear, value = raw·scale + offset,
// and is given per fogdrift column by a unit name (docs/formats.md lists them all):
//   time_s          s | ms | us
//   gyro_dph        deg/h | deg/s | rad/s | mrad/s | arcsec/s
//   temp_*_degc, chamber_degc   degC | K | degF | counts:SCALE:OFFSET  (°C = counts·SCALE + OFFSET)
//   accel_*_g       g | mg | m/s2
//   table_deg       deg | rad
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "fogdrift/recording.hpp"

namespace fogdrift {

/// value_in_fogdrift_units = raw·scale + offset
struct LinearConversion {
  double scale = 1.0;
  double offset = 0.0;
};

/// The conversion named by `unit` for fogdrift column `column` (e.g. "gyro_dph", "rad/s").
/// Throws OptionError naming "--unit COLUMN=UNIT" and the units that column accepts.
LinearConversion parse_unit(std::string_view column, std::string_view unit);

struct ImportOptions {
  /// fogdrift column -> foreign column name. A fogdrift column not in the map is taken from a
  /// foreign column of the same name, if there is one.
  std::map<std::string, std::string> columns;
  /// fogdrift column -> conversion; columns not listed are already in fogdrift units.
  std::map<std::string, LinearConversion> conversions;
  char delimiter = ',';         ///< ',' | ';' | '\t'
  bool decimal_comma = false;   ///< numbers written "1,5" (needs a delimiter other than ',')
  bool time_from_zero = false;  ///< subtract the first time stamp (loggers that count from boot)
  bool keep_extra = true;       ///< keep unmapped foreign columns as extra columns
};

/// Reads the foreign file `path` and returns a validated recording. Throws InputError naming the
/// file, line and column for bad cells and non-increasing time, and OptionError for a mapping to a
/// column the file does not have or an impossible option combination.
Recording import_recording(const std::filesystem::path& path, const ImportOptions& options);

}  // namespace fogdrift
