// The channel a model compensates, its target: a gyro axis, an accelerometer axis or a
// scale-factor channel, each named by what it is and its unit so that every output and message
// can say which (docs/logs.md, "Other targets"):
//
//   gyro_dph, gyro_NAME_dph   a gyro axis, °/h; its drift is what north-finding needs removed
//   accel_x_g, accel_y_g,     an accelerometer axis, g; its drift is the bias the temperature
//   accel_NAME_g              moves
//   sf_NAME_ppm               a scale-factor channel the unit logs (its estimate of its own
//                             scale-factor error, or a rate table's), ppm
//
// A model's target is the channel minus a reference: the input the channel sensed (a gyro's
// input rate, an accelerometer's share of gravity, a scale factor's nominal), or else its mean
// (dataset.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift {

enum class TargetKind : std::uint8_t { gyro, accelerometer, scale_factor };

struct Target {
  TargetKind kind = TargetKind::gyro;
  std::string column;  ///< gyro_dph, gyro_y_dph, accel_x_g, sf_fog_ppm
  /// The axis as output columns and C symbols carry it: "gyro" for gyro_dph, NAME for
  /// gyro_NAME_dph, the column less its unit for the others (accel_x, sf_fog).
  std::string axis;

  std::string_view unit() const;    ///< the column's unit suffix: dph, g, ppm
  std::string_view symbol() const;  ///< the unit as printed: °/h, g, ppm
  std::string_view what() const;    ///< gyro, accelerometer, scale-factor channel
  /// A value in this unit as reports print it: four decimals for °/h (a gyro's drift is tenths to
  /// hundreds), four significant digits for the others (an accelerometer's bias is 1e-5 g).
  std::string format(double value) const;
  /// The columns compensate and stream add: the predicted drift (drift_dph, drift_y_dph,
  /// drift_accel_x_g, drift_sf_fog_ppm) and the channel less it (gyro_comp_dph,
  /// gyro_y_comp_dph, accel_x_comp_g, sf_fog_comp_ppm).
  std::string drift_column() const;
  std::string compensated_column() const;
  /// The reference as a campaign gives it: --reference COLUMN=VALUE, and for a gyro
  /// --input-rate-dph.
  std::string reference_hint() const;
};

/// The target `column` names; nothing when it names none of the kinds above.
std::optional<Target> parse_target(std::string_view column);

/// parse_target(column), or OptionError(option) naming the kinds a target may be.
Target target_of(std::string_view column, const std::string& option = "--targets");

/// Whether `name` can be a model's target column (parse_target).
bool is_target_column(std::string_view name);

/// The axis a target column names (Target::axis).
std::string axis_name(std::string_view target_column);

/// Checks the targets of one model (train --targets, and export-c again for a model file): each a
/// target, none twice, and their axes unique C identifiers that C does not reserve, since each is
/// a member of the C header's state and a part of its names (gyro_dph and gyro_gyro_dph are both
/// axis gyro; gyro_1_dph is axis 1; gyro_int_dph is axis int). OptionError(option) naming them.
void check_targets(const std::vector<std::string>& target_columns, const std::string& option);

/// The largest magnitude a reference may have, in its target's unit (a manifest's, a flag's, a
/// keyword's).
inline constexpr double kReferenceLimit = 1e7;

/// Checks one reference: `column` a target column and `value` a finite number within
/// ±kReferenceLimit; OptionError(option) naming the rule otherwise.
void check_reference(std::string_view column, double value, const std::string& option);

/// The readings of target `column` in `recording`: gyro_dph, accel_x_g, accel_y_g, or the
/// further channel `column`. Throws InputError naming the recording when it lacks the column or
/// a cell is not a number.
std::vector<double> target_values(const Recording& recording, const std::string& column);

/// `recording` with gyro_dph taken from `column` (target_values), so that every path written for
/// gyro_dph serves another target; the recording itself for gyro_dph.
Recording with_target(const Recording& recording, const std::string& column);

}  // namespace fogdrift
