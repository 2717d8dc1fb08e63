#include "fogdrift/io/target.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

#include "base/c_text.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

/// Whether `name` is PREFIX NAME SUFFIX with a non-empty NAME.
bool between(std::string_view name, std::string_view prefix, std::string_view suffix) {
  return name.size() > prefix.size() + suffix.size() && name.starts_with(prefix) &&
         name.ends_with(suffix);
}

/// Per TargetKind, in its order: the column's unit suffix, the unit as printed, what it is.
struct KindNames {
  std::string_view unit, symbol, what;
};
constexpr std::array<KindNames, 3> kKinds = {
    {{"dph", "°/h", "gyro"}, {"g", "g", "accelerometer"}, {"ppm", "ppm", "scale-factor channel"}}};

}  // namespace

std::string_view Target::unit() const {
  return kKinds[static_cast<std::size_t>(kind)].unit;
}
std::string_view Target::symbol() const {
  return kKinds[static_cast<std::size_t>(kind)].symbol;
}
std::string_view Target::what() const {
  return kKinds[static_cast<std::size_t>(kind)].what;
}

std::string Target::format(double value) const {
  return kind == TargetKind::gyro ? fmt::format("{:.4f}", value) : fmt::format("{:.4g}", value);
}

std::string Target::drift_column() const {
  if (column == "gyro_dph") return "drift_dph";
  return fmt::format("drift_{}_{}", axis, unit());
}

std::string Target::compensated_column() const {
  const std::string_view stem(column.data(), column.size() - unit().size() - 1);
  return fmt::format("{}_comp_{}", stem, unit());
}

std::string Target::reference_hint() const {
  const std::string given =
      fmt::format("fogdrift campaign --reference {}=VALUE ({})", column, symbol());
  return kind == TargetKind::gyro ? given + " or --input-rate-dph" : given;
}

std::optional<Target> parse_target(std::string_view column) {
  const std::string name(column);
  if (name == "gyro_dph") return Target{TargetKind::gyro, name, "gyro"};
  if (name == "accel_x_g" || name == "accel_y_g")
    return Target{TargetKind::accelerometer, name, name.substr(0, name.size() - 2)};
  if (!is_channel_column(name)) return std::nullopt;
  if (between(name, "gyro_", "_dph"))
    return Target{TargetKind::gyro, name, name.substr(5, name.size() - 9)};
  if (between(name, "accel_", "_g"))
    return Target{TargetKind::accelerometer, name, name.substr(0, name.size() - 2)};
  if (between(name, "sf_", "_ppm"))
    return Target{TargetKind::scale_factor, name, name.substr(0, name.size() - 4)};
  return std::nullopt;
}

Target target_of(std::string_view column, const std::string& option) {
  if (auto t = parse_target(column)) return *t;
  throw OptionError(option,
                    fmt::format("'{}' is not a target: a gyro (gyro_dph, gyro_NAME_dph), an "
                                "accelerometer (accel_x_g, accel_y_g, accel_NAME_g) or a "
                                "scale-factor channel (sf_NAME_ppm), NAME of lower-case letters, "
                                "digits and '_' (docs/logs.md, \"Other targets\")",
                                column));
}

void check_reference(std::string_view column, double value, const std::string& option) {
  const Target target = target_of(column, option);
  if (!(std::abs(value) <= kReferenceLimit))
    throw OptionError(option, fmt::format("{}: {} is not a number of magnitude at most {}, {}",
                                          column, value, kReferenceLimit, target.symbol()));
}

bool is_target_column(std::string_view name) {
  return parse_target(name).has_value();
}

std::string axis_name(std::string_view target_column) {
  return target_of(target_column).axis;
}

void check_targets(const std::vector<std::string>& columns, const std::string& option) {
  if (columns.empty()) throw OptionError(option, "names no column to compensate");
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const Target t = target_of(columns[i], option);
    if (!detail::is_plain_c_identifier(t.axis))
      throw OptionError(option,
                        fmt::format("'{}' names axis '{}', which is not a C identifier the C "
                                    "header can use (letters, digits and '_', starting with a "
                                    "letter, not a C keyword); rename the column, e.g. at import "
                                    "with --map",
                                    columns[i], t.axis));
    if (t.axis == "comp" || t.axis.ends_with("_comp"))
      throw OptionError(option,
                        fmt::format("'{}' is the name compensate and stream give a compensated "
                                    "output column, not a sensor's reading; name the raw "
                                    "reading's column",
                                    columns[i]));
    for (std::size_t j = 0; j < i; ++j) {
      if (columns[j] == columns[i])
        throw OptionError(option, fmt::format("'{}' is named twice", columns[i]));
      if (target_of(columns[j], option).axis == t.axis)
        throw OptionError(option,
                          fmt::format("'{}' and '{}' both name axis '{}', and each axis needs a "
                                      "name of its own in the C header; rename one column, e.g. "
                                      "at import with --map",
                                      columns[j], columns[i], t.axis));
    }
  }
}

std::vector<double> target_values(const Recording& recording, const std::string& column) {
  if (column == "gyro_dph") return recording.gyro_dph;
  const Target target = target_of(column);
  if (const std::vector<double>* known = known_column(recording, column)) return *known;
  if (!recording.has_column(column)) {
    throw InputError(recording.source, 1, 0,
                     fmt::format("has no column '{}', the {} the model compensates (import it "
                                 "with --map {}=COLUMN)",
                                 column, target.what(), column));
  }
  return recording.numeric_column(column);
}

Recording with_target(const Recording& recording, const std::string& column) {
  if (column == "gyro_dph") return recording;
  Recording out = recording;
  out.gyro_dph = target_values(recording, column);
  return out;
}

}  // namespace fogdrift
