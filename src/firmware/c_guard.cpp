// The novelty guard of the C header (c_parts.hpp, guard.hpp).
#include <fmt/format.h>

#include "base/c_text.hpp"
#include "firmware/c_parts.hpp"

namespace fogdrift::detail {

std::string c_guard_part(const CompensationModel& model, const std::string& prefix,
                         const std::string& upper) {
  if (model.guard.empty()) return "";
  const GuardSettings& g = model.guard.settings;
  std::string h = fmt::format(
      "/* Novelty guard (fogdrift docs/field.md): nu = distance of the standardised features to\n"
      " * the nearest of {2} prototypes of the training rows, in units of the spacing between\n"
      " * the calibration temperatures (a start-up like the calibration's at a new temperature\n"
      " * has nu of about 1). The correction is applied in full up to nu = {3}, to none from\n"
      " * nu = {4}; streaming, the weight falls at once and {5}. */\n"
      "#define {1}_N_GUARD {2}\n",
      prefix, upper, model.guard.size(), c_number(g.full_at), c_number(g.zero_at),
      g.recover_s > 0 ? fmt::format("recovers over {} s", c_number(g.recover_s))
                      : fmt::format("stays at its lowest until the next {}_reset", prefix));
  h += fmt::format("static const @REAL@ {}_guard_points[{}] = {{{}}};\n", prefix,
                   model.guard.prototypes.size(), c_array(model.guard.prototypes));
  h += fmt::format(
      "static const @REAL@ {0}_guard_radius = {1};\n"
      "static const @REAL@ {0}_guard_full_at = {2};\n"
      "static const @REAL@ {0}_guard_zero_at = {3};\n"
      "static const @REAL@ {0}_guard_recover_s = {4};\n\n",
      prefix, c_number(model.guard.radius), c_number(g.full_at), c_number(g.zero_at),
      c_number(g.recover_s));
  std::string warmup;
  for (std::size_t k = 0; k < model.guard.dims; ++k)
    warmup += fmt::format("{}{}", k ? ", " : "",
                          k < model.guard.warmup_inputs.size() ? model.guard.warmup_inputs[k] : 1);
  h += fmt::format("static const unsigned char {}_guard_warmup_inputs[{}] = {{{}}};\n\n", prefix,
                   model.guard.dims, warmup);
  h += fmt::format(
      "/* nu for one row of features in their own units; while the rate window fills (warming),\n"
      " * over the features that read no rate only (fogdrift docs/field.md, \"The guard at\n"
      " * power-on\"). */\n"
      "static inline @REAL@ {0}_novelty_of(const @REAL@ features[{1}_N_FEATURES], int warming) {{\n"
      "  @REAL@ x[{1}_N_FEATURES], best = HUGE_VAL;\n"
      "  int i, k;\n"
      "  for (k = 0; k < {1}_N_FEATURES; ++k)\n"
      "    x[k] = (features[k] - {0}_feature_mean[k]) / {0}_feature_scale[k];\n"
      "  for (i = 0; i < {1}_N_GUARD; ++i) {{\n"
      "    const @REAL@* p = {0}_guard_points + i * {1}_N_FEATURES;\n"
      "    @REAL@ s = 0.0;\n"
      "    for (k = 0; k < {1}_N_FEATURES; ++k) {{\n"
      "      const @REAL@ e = (warming && !{0}_guard_warmup_inputs[k]) ? 0.0 : x[k] - p[k];\n"
      "      s += e * e;\n"
      "    }}\n"
      "    if (s < best) best = s;\n"
      "  }}\n"
      "  return sqrt@F@(best) / {0}_guard_radius;\n"
      "}}\n\n"
      "/* nu for one row of features whose rates come from a full window. */\n"
      "static inline @REAL@ {0}_novelty(const @REAL@ features[{1}_N_FEATURES]) {{\n"
      "  return {0}_novelty_of(features, 0);\n"
      "}}\n\n"
      "/* The share of the correction a sample of novelty nu asks for (0 when nu is not a number). "
      "*/\n"
      "static inline @REAL@ {0}_target_weight(@REAL@ nu) {{\n"
      "  if (nu != nu) return 0.0;\n"
      "  if (nu <= {0}_guard_full_at) return 1.0;\n"
      "  if (nu >= {0}_guard_zero_at) return 0.0;\n"
      "  return ({0}_guard_zero_at - nu) / ({0}_guard_zero_at - {0}_guard_full_at);\n"
      "}}\n\n",
      prefix, upper);
  return h;
}

}  // namespace fogdrift::detail
