// Every axis of a model set in one C header: each axis's own header under its own prefix, and one
// update that runs them all (c_header.hpp).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "base/c_text.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/io/target.hpp"

namespace fogdrift {

std::string to_c_header(const ModelSet& set, const std::string& prefix, double stream_dt_s,
                        const FaultPolicy& faults, CPrecision precision) {
  if (set.models.empty()) throw OptionError("targets", "a model set needs at least one model");
  if (set.models.size() == 1)
    return to_c_header(set.models.front(), prefix, stream_dt_s, faults, precision);
  const std::string upper = c_macro_prefix(prefix);
  const std::size_t n = set.models.size();
  check_targets(set.targets(), "targets");
  const std::vector<std::string> columns = set.thermometer_columns();  // every axis's, once
  std::string names, axes, units;
  bool gyros = true;  // every axis a gyro: the arrays are named in °/h
  for (std::size_t k = 0; k < n; ++k) {
    const Target target = target_of(set.models[k].dataset.target_column);
    gyros = gyros && target.kind == TargetKind::gyro;
    names += fmt::format("{}{}", k ? ", " : "", detail::c_string_literal(target.column));
    axes += fmt::format("{}{}", k ? ", " : "", target.axis);
    units += fmt::format(
        "{}{}", k ? ", " : "",
        detail::c_string_literal(target.kind == TargetKind::gyro ? std::string_view("deg/h")
                                                                 : target.unit()));
  }
  // Axes of other targets (target.hpp) share arrays whose values are each in its axis's unit.
  const std::string drift = gyros ? "drift_dph" : "drift";
  const std::string compensate = gyros ? prefix + "_compensated_dph" : prefix + "_compensated";
  const std::string reading = gyros ? "gyro_dph" : "reading";
  const std::string compensated = gyros ? "gyro_compensated_dph" : "compensated";
  std::string h = fmt::format(
      "/* {0}.h: fogdrift compensation models of {1} {4} ({2}) for C99 firmware.\n"
      " * Each axis's model is below under its own prefix, {0}_AXIS for AXIS in {3};",
      prefix, n, fmt::join(set.targets(), ", "), axes, gyros ? "gyro axes" : "axes");
  h += stream_dt_s > 0
           ? fmt::format(
                 "\n * one update runs them all on the same thermometer samples:\n"
                 " *   {0}_state s; {0}_reset(&s);   at power-on\n"
                 " *   {0}_update(&s, time_s, {2}, {3});\n"
                 " *   {4}(&s, {5}, {6});\n"
                 " * with arrays of {1}_N_AXES values in {0}_axis_names order{7}. */\n",
                 prefix, upper, fmt::join(columns, ", "), drift, compensate, reading, compensated,
                 gyros ? "" : fmt::format(", each in {}_axis_units", prefix))
           : std::string(
                 " no streaming part (export-c --stream-rate-hz adds one update for "
                 "all). */\n");
  h += fmt::format("#ifndef {0}_H\n#define {0}_H\n\n", upper);
  for (const CompensationModel& model : set.models) {
    const std::string axis = prefix + "_" + axis_name(model.dataset.target_column);
    try {
      h += to_c_header(model, axis, stream_dt_s, faults, precision);
    } catch (const OptionError& e) {
      if (e.option() == "prefix")
        throw OptionError("prefix", fmt::format("'{}' is not a C identifier", axis));
      throw;
    }
    h += "\n";
  }
  h += fmt::format("#define {}_N_AXES {}\n", upper, n);
  h += fmt::format("static const char* const {}_axis_names[{}] = {{{}}};\n", prefix, n, names);
  if (!gyros)
    h += fmt::format("static const char* const {}_axis_units[{}] = {{{}}};\n", prefix, n, units);
  h += "\n";
  if (stream_dt_s > 0) {
    const std::string first = prefix + "_" + axis_name(set.models.front().dataset.target_column);
    h += fmt::format("typedef {}_real {}_real;\n\n", first, prefix);
    h += "typedef struct {\n";
    for (const CompensationModel& model : set.models) {
      const std::string axis = axis_name(model.dataset.target_column);
      h += fmt::format("  {}_{}_state {};\n", prefix, axis, axis);
    }
    h += fmt::format("}} {}_state;\n\n", prefix);
    std::string reset, update, compensate_calls;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string axis = axis_name(set.models[k].dataset.target_column);
      reset += fmt::format("  {0}_{1}_reset(&s->{1});\n", prefix, axis);
      const std::string_view unit = target_of(set.models[k].dataset.target_column).unit();
      update +=
          fmt::format("  {4}[{2}] = {0}_{1}_update(&s->{1}, time_s, {3});\n", prefix, axis, k,
                      fmt::join(set.models[k].dataset.features.thermometer_columns(), ", "), drift);
      compensate_calls += fmt::format("  {3}[{2}] = {0}_{1}_compensated_{4}(&s->{1}, {5}[{2}]);\n",
                                      prefix, axis, k, compensated, unit, reading);
    }
    h += fmt::format("static inline void {0}_reset({0}_state* s) {{\n{1}}}\n\n", prefix, reset);
    std::string params;
    for (const std::string& column : columns) params += fmt::format("{}_real {}, ", prefix, column);
    h += fmt::format(
        "/* Every axis's predicted drift, {5}, for the newest sample; each axis's fault flags\n"
        " * are in its own state's flags (s->AXIS.flags). */\n"
        "static inline void {0}_update({0}_state* s, double time_s, {2}\n"
        "                                {0}_real {4}[{1}_N_AXES]) {{\n{3}}}\n\n",
        prefix, upper, params, update, drift,
        gyros ? "deg/h" : fmt::format("in {}_axis_units", prefix));
    const std::string indent(41, ' ');  // as gyro sets have always been laid out, byte for byte
    h += fmt::format(
        "/* Every axis's {5} minus its last drift (each as AXIS_compensated_{6}). */\n"
        "static inline void {0}({1}_state* s, const {1}_real {2}[{3}_N_AXES],\n"
        "{7}{1}_real {4}[{3}_N_AXES]) {{\n{8}}}\n\n",
        compensate, prefix, reading, upper, compensated, gyros ? "gyro" : "reading",
        gyros ? "dph" : "UNIT", indent, compensate_calls);
  }
  h += fmt::format("#endif /* {}_H */\n", upper);
  return h;
}

}  // namespace fogdrift
