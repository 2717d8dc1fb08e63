#include "fogdrift/c_header.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "fogdrift/error.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift {
namespace {

/// The temperature arguments a model reads, e.g. "temp_fog_degc" (docs/logs.md, "Fewer
/// thermometers").
std::string thermometers_read(const CompensationModel& model) {
  std::vector<std::string_view> read;
  for (Thermometer k : {Thermometer::fog, Thermometer::acc1, Thermometer::acc2})
    if (model.dataset.features.reads(k)) read.push_back(column_name(k));
  return read.empty() ? std::string("none") : fmt::format("{}", fmt::join(read, ", "));
}

}  // namespace

namespace {

std::string c_number(double v) {
  return fmt::format("{:.17g}", v);
}

std::string c_array(std::span<const double> values, std::size_t per_line = 4) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i % per_line == 0) out += "\n    ";
    out += c_number(values[i]);
    if (i + 1 < values.size()) out += ", ";
  }
  return out;
}

}  // namespace

namespace {

// The header's streaming part: the causal differentiator (taps of every start-up window length,
// a buffer of 2W samples per thermometer) and the features in compute_features()'s order, as
// StreamingCompensator::update() computes them.
// The novelty guard (guard.hpp) in C: its tables, PREFIX_novelty(features) and
// PREFIX_target_weight(nu), the same operations in the same order as NoveltyGuard.
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
  h += fmt::format("static const double {}_guard_points[{}] = {{{}}};\n", prefix,
                   model.guard.prototypes.size(), c_array(model.guard.prototypes));
  h += fmt::format(
      "static const double {0}_guard_radius = {1};\n"
      "static const double {0}_guard_full_at = {2};\n"
      "static const double {0}_guard_zero_at = {3};\n"
      "static const double {0}_guard_recover_s = {4};\n\n",
      prefix, c_number(model.guard.radius), c_number(g.full_at), c_number(g.zero_at),
      c_number(g.recover_s));
  h += fmt::format(
      "/* nu for one row of features in their own units. */\n"
      "static inline double {0}_novelty(const double features[{1}_N_FEATURES]) {{\n"
      "  double x[{1}_N_FEATURES], best = HUGE_VAL;\n"
      "  int i, k;\n"
      "  for (k = 0; k < {1}_N_FEATURES; ++k)\n"
      "    x[k] = (features[k] - {0}_feature_mean[k]) / {0}_feature_scale[k];\n"
      "  for (i = 0; i < {1}_N_GUARD; ++i) {{\n"
      "    const double* p = {0}_guard_points + i * {1}_N_FEATURES;\n"
      "    double s = 0.0;\n"
      "    for (k = 0; k < {1}_N_FEATURES; ++k) {{\n"
      "      const double e = x[k] - p[k];\n"
      "      s += e * e;\n"
      "    }}\n"
      "    if (s < best) best = s;\n"
      "  }}\n"
      "  return sqrt(best) / {0}_guard_radius;\n"
      "}}\n\n"
      "/* The share of the correction a sample of novelty nu asks for (0 when nu is not a number). "
      "*/\n"
      "static inline double {0}_target_weight(double nu) {{\n"
      "  if (nu != nu) return 0.0;\n"
      "  if (nu <= {0}_guard_full_at) return 1.0;\n"
      "  if (nu >= {0}_guard_zero_at) return 0.0;\n"
      "  return ({0}_guard_zero_at - nu) / ({0}_guard_zero_at - {0}_guard_full_at);\n"
      "}}\n\n",
      prefix, upper);
  return h;
}

std::string c_streaming_part(const CompensationModel& model, const std::string& prefix,
                             const std::string& upper, double dt_s) {
  if (!std::isfinite(dt_s)) throw OptionError("stream_dt_s", "must be a finite interval");
  signal::CausalDifferentiator diff(model.dataset.preprocessing.rates, dt_s);
  const std::size_t w = diff.window();
  std::vector<double> taps;
  for (std::size_t k = 1; k <= w; ++k) {
    const auto& t = diff.taps(k);
    taps.insert(taps.end(), t.begin(), t.end());
  }
  std::string h;
  h += fmt::format(
      "/* Streaming: the features computed causally, one sample every {2} s.\n"
      " *   {0}_state s; {0}_reset(&s);   at power-on\n"
      " *   drift_dph = {0}_update(&s, time_s, temp_fog_degc, temp_acc1_degc, temp_acc2_degc);\n"
      " * Temperature rates: causal Savitzky-Golay derivative over the last {1} samples (fewer\n"
      " * during the first {1}); the taps for k + 1 samples start at k(k + 1)/2 in the table.\n"
      " * Thermometers this model reads: {4}; pass 0 for the others.{3} "
      "*/\n",
      prefix, w, c_number(dt_s),
      model.dataset.preprocessing.rates.causality == signal::Causality::causal
          ? ""
          : "\n * NOTE: this model was trained with centred rates; streaming applies causal ones, "
            "which\n * lag. Train with --differentiator causal for firmware.",
      thermometers_read(model));
  h += fmt::format("#define {}_RATE_WINDOW {}\n", upper, w);
  if (!model.guard.empty())
    h += fmt::format(
        "#ifndef {0}_GUARD\n#define {0}_GUARD 1 /* 0: full correction always */\n"
        "#endif\n",
        upper);
  h += fmt::format("static const double {}_dt_s = {};\n", prefix, c_number(dt_s));
  h += fmt::format("static const double {}_rate_taps[{}] = {{{}}};\n\n", prefix, taps.size(),
                   c_array(taps));
  h += fmt::format(
      "typedef struct {{\n"
      "  double buffer[3][2 * {1}_RATE_WINDOW]; /* fog, acc1, acc2; newest at size - 1 */\n"
      "  long size;                             /* samples in the buffer */\n"
      "  long count;                            /* samples since power-on */\n"
      "  double weight;                         /* the guard's weight w, 1 at power-on */\n"
      "  double last_time_s;                    /* time of the previous sample */\n"
      "  double novelty;                        /* nu of the last sample (0 without a guard) */\n"
      "}} {0}_state;\n\n"
      "static inline void {0}_reset({0}_state* s) {{\n  s->size = 0;\n  s->count = 0;\n"
      "  s->weight = 1.0;\n  s->last_time_s = 0.0;\n  s->novelty = 0.0;\n}}\n\n",
      prefix, upper);
  // With a guard, the weight's recursion (GuardFilter); define PREFIX_GUARD 0 to switch it off.
  std::string guard;
  if (!model.guard.empty())
    guard = fmt::format(
        "#if {1}_GUARD\n"
        "  {{\n"
        "    const double drift = {0}_predict_dph(f);\n"
        "    const double dt = s->count > 1 ? (time_s - s->last_time_s > 0.0 ? time_s - "
        "s->last_time_s : 0.0) : 0.0;\n"
        "    const double v = {0}_target_weight(s->novelty = {0}_novelty(f));\n"
        "    const double up =\n"
        "        s->weight + ({0}_guard_recover_s > 0 ? dt / {0}_guard_recover_s : 0.0);\n"
        "    s->weight = up < v ? up : v;\n"
        "    s->last_time_s = time_s;\n"
        "    if (s->weight == 0.0) return {0}_drift_mean_dph;\n"
        "    return {0}_drift_mean_dph + s->weight * (drift - {0}_drift_mean_dph);\n"
        "  }}\n"
        "#endif\n",
        prefix, upper);
  // Feature assignments: FeatureColumn::value() written out in C.
  std::string f;
  const std::vector<FeatureColumn> columns = model.dataset.features.columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const auto a = static_cast<std::size_t>(columns[c].a);
    const auto b = static_cast<std::size_t>(columns[c].b);
    std::string value;
    switch (columns[c].term) {
      case FeatureTerm::temp:
        value = fmt::format("temp[{}]", a);
        break;
      case FeatureTerm::rate:
        value = fmt::format("rate[{}]", a);
        break;
      case FeatureTerm::gradient:
        value = fmt::format("temp[{}] - temp[{}]", a, b);
        break;
      case FeatureTerm::gradient_rate:
        value = fmt::format("rate[{}] - rate[{}]", a, b);
        break;
      case FeatureTerm::time:
        value = "time_s";
        break;
      case FeatureTerm::temp_rate_product:
        value = fmt::format("temp[{}] * rate[{}]", a, a);
        break;
    }
    f += fmt::format("  f[{}] = {};\n", c, value);
  }
  h += fmt::format(
      "/* Predicted drift, deg/h, for the newest sample (every dt_s seconds since power-on). */\n"
      "static inline double {0}_update({0}_state* s, double time_s, double temp_fog_degc,\n"
      "                                 double temp_acc1_degc, double temp_acc2_degc) {{\n"
      "  const double temp[3] = {{temp_fog_degc, temp_acc1_degc, temp_acc2_degc}};\n"
      "  double rate[3], f[{1}_N_FEATURES];\n"
      "  const double* taps;\n"
      "  long used, j;\n"
      "  int k;\n"
      "  if (s->size == 2 * {1}_RATE_WINDOW) {{ /* keep the newest window - 1 at the front */\n"
      "    for (k = 0; k < 3; ++k)\n"
      "      for (j = 0; j < {1}_RATE_WINDOW - 1; ++j)\n"
      "        s->buffer[k][j] = s->buffer[k][{1}_RATE_WINDOW + 1 + j];\n"
      "    s->size = {1}_RATE_WINDOW - 1;\n"
      "  }}\n"
      "  for (k = 0; k < 3; ++k) s->buffer[k][s->size] = temp[k];\n"
      "  ++s->size;\n"
      "  ++s->count;\n"
      "  used = s->count < {1}_RATE_WINDOW ? s->count : {1}_RATE_WINDOW;\n"
      "  taps = {0}_rate_taps + (used - 1) * used / 2;\n"
      "  for (k = 0; k < 3; ++k) {{\n"
      "    const double* x = s->buffer[k] + (s->size - used);\n"
      "    double sum = 0.0;\n"
      "    for (j = 0; j < used; ++j) sum += taps[j] * x[j];\n"
      "    rate[k] = sum / {0}_dt_s;\n"
      "  }}\n"
      "{2}"
      "{3}"
      "  (void)time_s;\n"
      "  (void)rate;\n"
      "  return {0}_predict_dph(f);\n"
      "}}\n\n",
      prefix, upper, f, guard);
  return h;
}

}  // namespace

std::string to_c_header(const CompensationModel& model, const std::string& prefix,
                        double stream_dt_s) {
  const bool identifier = !prefix.empty() && !std::isdigit(static_cast<unsigned char>(prefix[0])) &&
                          std::all_of(prefix.begin(), prefix.end(), [](char c) {
                            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                          });
  if (!identifier) throw OptionError("prefix", fmt::format("'{}' is not a C identifier", prefix));
  std::string upper = prefix;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::size_t d = model.inputs();
  const Provenance& p = model.provenance;
  std::string h;
  h += fmt::format(
      "/* {prefix}.h: a fogdrift compensation model ({method}) for C99 firmware.\n"
      " * Written by fogdrift {version}; features '{spec}', trained on {rows} rows.\n"
      " * drift_dph = {prefix}_predict_dph(features); gyro_compensated_dph = gyro_dph - "
      "drift_dph.\n"
      " * Features, in order (units in the names):\n",
      fmt::arg("prefix", prefix), fmt::arg("method", to_string(p.method)),
      fmt::arg("version", p.fogdrift_version), fmt::arg("spec", model.dataset.features.to_string()),
      fmt::arg("rows", p.training_rows));
  for (std::size_t k = 0; k < d; ++k) h += fmt::format(" *   [{}] {}\n", k, model.feature_names[k]);
  h += fmt::format(
      " * Temperature rates: {} Savitzky-Golay derivative over {} s (degree {}).\n"
      " * No heap, no state: the function may be called from any context. */\n",
      signal::to_string(model.dataset.preprocessing.rates.causality),
      c_number(model.dataset.preprocessing.rates.window_s),
      model.dataset.preprocessing.rates.poly_order);
  h += fmt::format("#ifndef {0}_H\n#define {0}_H\n\n#include <math.h>\n\n", upper);
  h += fmt::format("#define {}_N_FEATURES {}\n\n", upper, d);
  h += fmt::format("static const char* const {}_feature_names[{}] = {{", prefix, d);
  for (std::size_t k = 0; k < d; ++k)
    h += fmt::format("{}\"{}\"", k ? ", " : "", model.feature_names[k]);
  h += "};\n";
  h += fmt::format("static const double {}_feature_mean[{}] = {{{}}};\n", prefix, d,
                   c_array(model.x_scaler.mean));
  h += fmt::format("static const double {}_feature_scale[{}] = {{{}}};\n", prefix, d,
                   c_array(model.x_scaler.scale));
  h += fmt::format("static const double {}_drift_mean_dph = {};\n", prefix,
                   c_number(model.y_scaler.mean[0]));
  h += fmt::format("static const double {}_drift_scale_dph = {};\n\n", prefix,
                   c_number(model.y_scaler.scale[0]));

  std::string body;  // computes `z` (standardised prediction) from `x` (standardised features)
  if (const auto* m = std::get_if<svr::Model>(&model.regressor)) {
    const std::size_t n = m->size();
    h += fmt::format("#define {}_N_SV {}\n", upper, n);
    h += fmt::format("static const double {}_sv[{}] = {{{}}};\n", prefix,
                     std::max<std::size_t>(1, n * d), n ? c_array(m->support_vectors) : "0");
    h += fmt::format("static const double {}_coef[{}] = {{{}}};\n", prefix,
                     std::max<std::size_t>(1, n), n ? c_array(m->coef) : "0");
    h += fmt::format("static const double {}_gamma = {};\nstatic const double {}_rho = {};\n\n",
                     prefix, c_number(m->kernel.gamma), prefix, c_number(m->rho));
    const bool rbf = m->kernel.type == svr::KernelType::rbf;
    body = fmt::format(
        "  double z = -{0}_rho;\n"
        "  int i, k;\n"
        "  for (i = 0; i < {1}_N_SV; ++i) {{\n"
        "    const double* s = {0}_sv + i * {1}_N_FEATURES;\n"
        "    double acc = 0.0;\n"
        "    for (k = 0; k < {1}_N_FEATURES; ++k) {{\n"
        "{2}"
        "    }}\n"
        "    z += {0}_coef[i] * {3};\n"
        "  }}\n",
        prefix, upper,
        rbf ? "      const double e = x[k] - s[k];\n      acc += e * e;\n"
            : "      acc += x[k] * s[k];\n",
        rbf ? fmt::format("exp(-{}_gamma * acc)", prefix) : "acc");
  } else if (const auto* m = std::get_if<Mlp>(&model.regressor)) {
    h += fmt::format("#define {}_N_HIDDEN {}\n", upper, m->hidden);
    h += fmt::format("static const double {}_w1[{}] = {{{}}};\n", prefix, m->w1.size(),
                     c_array(m->w1));
    h += fmt::format("static const double {}_b1[{}] = {{{}}};\n", prefix, m->b1.size(),
                     c_array(m->b1));
    h += fmt::format("static const double {}_w2[{}] = {{{}}};\n", prefix, m->w2.size(),
                     c_array(m->w2));
    h += fmt::format("static const double {}_b2 = {};\n\n", prefix, c_number(m->b2));
    body = fmt::format(
        "  double z = {0}_b2;\n"
        "  int h, k;\n"
        "  for (h = 0; h < {1}_N_HIDDEN; ++h) {{\n"
        "    double a = {0}_b1[h];\n"
        "    for (k = 0; k < {1}_N_FEATURES; ++k) a += {0}_w1[h * {1}_N_FEATURES + k] * x[k];\n"
        "    z += {0}_w2[h] * tanh(a);\n"
        "  }}\n",
        prefix, upper);
  } else {
    const Poly& poly = std::get<Poly>(model.regressor);
    h += fmt::format("#define {}_N_TERMS {}\n", upper, poly.terms());
    h += fmt::format("static const unsigned char {}_exponents[{}] = {{", prefix,
                     poly.exponents.size());
    for (std::size_t i = 0; i < poly.exponents.size(); ++i)
      h += fmt::format("{}{}{}", i % 20 == 0 ? "\n    " : "", poly.exponents[i],
                       i + 1 < poly.exponents.size() ? ", " : "");
    h += "};\n";
    h += fmt::format("static const double {}_poly_coef[{}] = {{{}}};\n\n", prefix, poly.terms(),
                     c_array(poly.coef));
    body = fmt::format(
        "  double z = 0.0;\n"
        "  int t, k, e;\n"
        "  for (t = 0; t < {1}_N_TERMS; ++t) {{\n"
        "    double term = {0}_poly_coef[t];\n"
        "    for (k = 0; k < {1}_N_FEATURES; ++k)\n"
        "      for (e = {0}_exponents[t * {1}_N_FEATURES + k]; e > 0; --e) term *= x[k];\n"
        "    z += term;\n"
        "  }}\n",
        prefix, upper);
  }
  h += fmt::format(
      "/* Predicted drift, deg/h, for one row of features in their own units. */\n"
      "static inline double {0}_predict_dph(const double features[{1}_N_FEATURES]) {{\n"
      "  double x[{1}_N_FEATURES];\n"
      "  int j;\n"
      "  for (j = 0; j < {1}_N_FEATURES; ++j)\n"
      "    x[j] = (features[j] - {0}_feature_mean[j]) / {0}_feature_scale[j];\n"
      "  {{\n{2}"
      "  return z * {0}_drift_scale_dph + {0}_drift_mean_dph;\n"
      "  }}\n"
      "}}\n\n",
      prefix, upper, body);
  h += c_guard_part(model, prefix, upper);
  if (stream_dt_s > 0) h += c_streaming_part(model, prefix, upper, stream_dt_s);
  h += fmt::format("#endif /* {}_H */\n", upper);
  return h;
}

}  // namespace fogdrift
