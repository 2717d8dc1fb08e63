#include "fogdrift/firmware/c_header.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "base/c_text.hpp"
#include "firmware/c_parts.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift {
using detail::c_array;
using detail::c_comment_text;
using detail::c_number;
using detail::c_string_literal;
using detail::fill_template;

std::string c_macro_prefix(const std::string& prefix) {
  // Every symbol is PREFIX_… and the include guard PREFIX_H: a prefix starting with '_' would
  // name identifiers C reserves and could take a standard header's guard (_MATH_H hides
  // <math.h>), so it is refused with the rest (docs/firmware.md).
  const bool identifier = !prefix.empty() && !std::isdigit(static_cast<unsigned char>(prefix[0])) &&
                          std::all_of(prefix.begin(), prefix.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                          });
  if (!identifier) throw OptionError("prefix", fmt::format("'{}' is not a C identifier", prefix));
  if (prefix.front() == '_')
    throw OptionError("prefix", fmt::format("'{}' starts with '_': C reserves such names (and "
                                            "_NAME_H may be a standard header's guard); start "
                                            "with a letter",
                                            prefix));
  std::string upper = prefix;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return upper;
}

FloatPrecisionCheck check_float_precision(const CompensationModel& model) {
  const std::size_t d = model.inputs();
  const std::vector<double>& mean = model.x_scaler.mean;
  const std::vector<double>& scale = model.x_scaler.scale;
  std::vector<std::vector<double>> rows;
  if (!model.guard.empty()) {
    const std::size_t n = model.guard.prototypes.size() / d;
    for (std::size_t p = 0; p < n; ++p) {
      std::vector<double> row(d);
      for (std::size_t k = 0; k < d; ++k)
        row[k] = model.guard.prototypes[p * d + k] * scale[k] + mean[k];
      rows.push_back(std::move(row));
    }
  } else {
    rows.push_back(mean);
    for (std::size_t k = 0; k < d; ++k)
      for (const double side : {-1.0, 1.0}) {
        std::vector<double> row = mean;
        row[k] += side * scale[k];
        rows.push_back(std::move(row));
      }
  }
  FloatPrecisionCheck check;
  check.drift_std = model.y_scaler.scale[0];
  std::vector<double> work(d), x(d);
  const auto y_scale = static_cast<float>(model.y_scaler.scale[0]);
  const auto y_mean = static_cast<float>(model.y_scaler.mean[0]);
  for (const std::vector<double>& row : rows) {
    const double exact = model.predict(row, work).drift_dph;
    if (!std::isfinite(exact)) continue;
    // The header's float steps: x[j] = (features[j] - mean[j]) / scale[j]; z * scale + mean.
    for (std::size_t k = 0; k < d; ++k)
      x[k] = static_cast<double>((static_cast<float>(row[k]) - static_cast<float>(mean[k])) /
                                 static_cast<float>(scale[k]));
    const double z = predict(model.regressor, x.data());
    const float drift = static_cast<float>(z) * y_scale + y_mean;
    check.max_error = std::max(check.max_error, std::abs(static_cast<double>(drift) - exact));
    ++check.inputs;
  }
  return check;
}

std::string to_c_header(const CompensationModel& model, const std::string& prefix,
                        double stream_dt_s, const FaultPolicy& faults, CPrecision precision) {
  const std::string upper = c_macro_prefix(prefix);
  const std::size_t d = model.inputs();
  const Provenance& p = model.provenance;
  std::string h;
  h += fmt::format(
      "/* {prefix}.h: a fogdrift compensation model ({method}) for C99 firmware.\n"
      " * Written by fogdrift {version}; features '{spec}', trained on {rows} rows.\n"
      " * drift_@UNIT@ = {prefix}_predict_@UNIT@(features); @READING_COMP@ = @READING@ - "
      "drift_@UNIT@.\n"
      " * Features, in order (units in the names):\n",
      fmt::arg("prefix", prefix), fmt::arg("method", c_comment_text(p.method)),
      fmt::arg("version", c_comment_text(p.fogdrift_version)),
      fmt::arg("spec", c_comment_text(model.dataset.features.to_string())),
      fmt::arg("rows", p.training_rows));
  for (std::size_t k = 0; k < d; ++k)
    h += fmt::format(" *   [{}] {}\n", k, c_comment_text(model.feature_names[k]));
  h += fmt::format(
      " * Temperature rates: {} Savitzky-Golay derivative over {} s (degree {}).\n"
      " * No heap, no state: the function may be called from any context. */\n",
      signal::to_string(model.dataset.preprocessing.rates.causality),
      c_number(model.dataset.preprocessing.rates.window_s),
      model.dataset.preprocessing.rates.poly_order);
  h += fmt::format("#ifndef {0}_H\n#define {0}_H\n\n#include <math.h>\n\n", upper);
  const bool single = precision == CPrecision::single;
  h += fmt::format(
      "/* Arithmetic in {1} precision{2}; times in seconds are double\n"
      " * throughout (a float second count loses 10 ms after a day). */\n"
      "typedef {1} {0}_real;\n\n",
      prefix, single ? "float" : "double",
      single ? " (export-c --precision float): the tables are the model's numbers rounded\n"
               " * to float, for a processor whose FPU has 32 bits, e.g. a Cortex-M4F"
             : " (export-c --precision double)");
  h += fmt::format("#define {}_N_FEATURES {}\n\n", upper, d);
  h += fmt::format("static const char* const {}_feature_names[{}] = {{", prefix, d);
  for (std::size_t k = 0; k < d; ++k)
    h += fmt::format("{}{}", k ? ", " : "", c_string_literal(model.feature_names[k]));
  h += "};\n";
  h += fmt::format("static const @REAL@ {}_feature_mean[{}] = {{{}}};\n", prefix, d,
                   c_array(model.x_scaler.mean));
  h += fmt::format("static const @REAL@ {}_feature_scale[{}] = {{{}}};\n", prefix, d,
                   c_array(model.x_scaler.scale));
  h += fmt::format("static const @REAL@ {}_drift_mean_@UNIT@ = {};\n", prefix,
                   c_number(model.y_scaler.mean[0]));
  h += fmt::format("static const @REAL@ {}_drift_scale_@UNIT@ = {};\n\n", prefix,
                   c_number(model.y_scaler.scale[0]));

  // The regressor's tables, and `body`, which computes `z` (standardised prediction) from `x`
  // (standardised features).
  const CRegressor regressor = to_c(model.regressor, {prefix, upper});
  h += regressor.tables;
  const std::string& body = regressor.body;
  h += fmt::format(
      "/* Predicted drift, @UNIT_TEXT@, for one row of features in their own units. */\n"
      "static inline @REAL@ {0}_predict_@UNIT@(const @REAL@ features[{1}_N_FEATURES]) {{\n"
      "  @REAL@ x[{1}_N_FEATURES];\n"
      "  int j;\n"
      "  for (j = 0; j < {1}_N_FEATURES; ++j)\n"
      "    x[j] = (features[j] - {0}_feature_mean[j]) / {0}_feature_scale[j];\n"
      "  {{\n{2}"
      "  return z * {0}_drift_scale_@UNIT@ + {0}_drift_mean_@UNIT@;\n"
      "  }}\n"
      "}}\n\n",
      prefix, upper, body);
  h += detail::c_guard_part(model, prefix, upper);
  if (stream_dt_s > 0)
    h += detail::c_streaming_part(model, prefix, upper, stream_dt_s, faults, single);
  h += fmt::format("#endif /* {}_H */\n", upper);
  // The arithmetic type and <math.h>'s functions for it (expf, sqrtf, tanhf, fabsf in float);
  // the names of the target's drift and reading, in its unit (target.hpp).
  const Target target = target_of(model.dataset.target_column);
  const bool gyro = target.kind == TargetKind::gyro;
  const std::string unit(target.unit());
  return fill_template(std::move(h), {{"@REAL@", prefix + "_real"},
                                      {"@F@", single ? "f" : ""},
                                      {"@UNIT@", unit},
                                      {"@UNIT_TEXT@", gyro ? std::string("deg/h") : unit},
                                      {"@READING_COMP@", gyro ? std::string("gyro_compensated_dph")
                                                              : target.compensated_column()},
                                      {"@READING_WORD@", gyro ? "gyro reading" : "reading"},
                                      {"@READING@", gyro ? std::string("gyro_dph") : target.column},
                                      {"@LIMIT@", gyro ? std::string("GYRO_LIMIT_DPH")
                                                       : "READING_LIMIT_" + c_macro_prefix(unit)}});
}

}  // namespace fogdrift
