// Every axis of a model set in one C header: each axis's own header under its own prefix, and one
// update that runs them all (c_header.hpp).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "fogdrift/c_header.hpp"
#include "fogdrift/error.hpp"

namespace fogdrift {

std::string to_c_header(const ModelSet& set, const std::string& prefix, double stream_dt_s,
                        const FaultPolicy& faults, CPrecision precision) {
  if (set.models.empty()) throw OptionError("targets", "a model set needs at least one model");
  if (set.models.size() == 1)
    return to_c_header(set.models.front(), prefix, stream_dt_s, faults, precision);
  const std::string upper = c_macro_prefix(prefix);
  const std::size_t n = set.models.size();
  const std::vector<std::string> columns = set.thermometer_columns();  // every axis's, once
  std::string names, axes;
  for (std::size_t k = 0; k < n; ++k) {
    names += fmt::format("{}\"{}\"", k ? ", " : "", set.models[k].dataset.target_column);
    axes += fmt::format("{}{}", k ? ", " : "", axis_name(set.models[k].dataset.target_column));
  }
  std::string h = fmt::format(
      "/* {0}.h: fogdrift compensation models of {1} gyro axes ({2}) for C99 firmware.\n"
      " * Each axis's model is below under its own prefix, {0}_AXIS for AXIS in {3};",
      prefix, n, fmt::join(set.targets(), ", "), axes);
  h += stream_dt_s > 0 ? fmt::format(
                             "\n * one update runs them all on the same thermometer samples:\n"
                             " *   {0}_state s; {0}_reset(&s);   at power-on\n"
                             " *   {0}_update(&s, time_s, {2}, drift_dph);\n"
                             " *   {0}_compensated_dph(&s, gyro_dph, gyro_compensated_dph);\n"
                             " * with arrays of {1}_N_AXES values in {0}_axis_names order. */\n",
                             prefix, upper, fmt::join(columns, ", "))
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
  h += fmt::format("static const char* const {}_axis_names[{}] = {{{}}};\n\n", prefix, n, names);
  if (stream_dt_s > 0) {
    const std::string first = prefix + "_" + axis_name(set.models.front().dataset.target_column);
    h += fmt::format("typedef {}_real {}_real;\n\n", first, prefix);
    h += "typedef struct {\n";
    for (const CompensationModel& model : set.models) {
      const std::string axis = axis_name(model.dataset.target_column);
      h += fmt::format("  {}_{}_state {};\n", prefix, axis, axis);
    }
    h += fmt::format("}} {}_state;\n\n", prefix);
    std::string reset, update, compensated;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string axis = axis_name(set.models[k].dataset.target_column);
      reset += fmt::format("  {0}_{1}_reset(&s->{1});\n", prefix, axis);
      update +=
          fmt::format("  drift_dph[{2}] = {0}_{1}_update(&s->{1}, time_s, {3});\n", prefix, axis, k,
                      fmt::join(set.models[k].dataset.features.thermometer_columns(), ", "));
      compensated += fmt::format(
          "  gyro_compensated_dph[{2}] = {0}_{1}_compensated_dph(&s->{1}, gyro_dph[{2}]);\n",
          prefix, axis, k);
    }
    h += fmt::format("static inline void {0}_reset({0}_state* s) {{\n{1}}}\n\n", prefix, reset);
    std::string params;
    for (const std::string& column : columns) params += fmt::format("{}_real {}, ", prefix, column);
    h += fmt::format(
        "/* Every axis's predicted drift, deg/h, for the newest sample; each axis's fault flags\n"
        " * are in its own state's flags (s->AXIS.flags). */\n"
        "static inline void {0}_update({0}_state* s, double time_s, {2}\n"
        "                                {0}_real drift_dph[{1}_N_AXES]) {{\n{3}}}\n\n",
        prefix, upper, params, update);
    h += fmt::format(
        "/* Every axis's gyro minus its last drift (each as AXIS_compensated_dph). */\n"
        "static inline void {0}_compensated_dph({0}_state* s, const {0}_real "
        "gyro_dph[{1}_N_AXES],\n"
        "                                         {0}_real gyro_compensated_dph[{1}_N_AXES]) "
        "{{\n{2}}}\n\n",
        prefix, upper, compensated);
  }
  h += fmt::format("#endif /* {}_H */\n", upper);
  return h;
}

}  // namespace fogdrift
