#include "fogdrift/model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "fogdrift/atomic_file.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/text_file.hpp"

namespace fogdrift {

using ojson = nlohmann::ordered_json;

std::string to_string(Method method) {
  switch (method) {
    case Method::ssa_svr:
      return "ssa-svr";
    case Method::pso_svr:
      return "pso-svr";
    case Method::gwo_svr:
      return "gwo-svr";
    case Method::svr:
      return "svr";
    case Method::bp:
      return "bp";
    case Method::poly:
      return "poly";
  }
  return "?";
}

Method parse_method(const std::string& text, const std::string& option) {
  for (Method m :
       {Method::ssa_svr, Method::pso_svr, Method::gwo_svr, Method::svr, Method::bp, Method::poly})
    if (text == to_string(m)) return m;
  throw OptionError(option, fmt::format("'{}' is not a method (ssa-svr, pso-svr, gwo-svr, svr, "
                                        "bp, poly)",
                                        text));
}

DriftPrediction CompensationModel::predict(std::span<const double> features,
                                           std::span<double> work) const {
  const std::size_t d = inputs();
  for (std::size_t k = 0; k < d; ++k)
    work[k] = (features[k] - x_scaler.mean[k]) / x_scaler.scale[k];
  const double z = std::visit([&](const auto& r) { return r.predict(work.data()); }, regressor);
  DriftPrediction out;
  out.drift_dph = z * y_scaler.scale[0] + y_scaler.mean[0];
  if (guard.empty()) {
    out.novelty = std::numeric_limits<double>::quiet_NaN();
  } else {
    out.novelty = guard.novelty(work.first(d));
    out.target_weight = guard.target_weight(out.novelty);
  }
  return out;
}

double CompensationModel::predict_dph(std::span<const double> features,
                                      std::span<double> work) const {
  return predict(features, work).drift_dph;
}

double CompensationModel::guarded_dph(double drift_dph, double weight) const noexcept {
  // w = 0 gives ȳ exactly, also for a drift that is not a number (inputs that were not).
  return weight == 0.0 ? y_scaler.mean[0]
                       : y_scaler.mean[0] + weight * (drift_dph - y_scaler.mean[0]);
}

std::vector<double> CompensationModel::predict_dph(const Dataset& data, bool guarded) const {
  if (data.feature_names != feature_names)
    throw OptionError(
        "features", fmt::format("the data has features {} but the model expects {}",
                                fmt::join(data.feature_names, ","), fmt::join(feature_names, ",")));
  std::vector<double> out(data.rows), work(inputs());
  GuardFilter filter;
  for (std::size_t i = 0; i < data.rows; ++i) {
    const DriftPrediction p = predict(data.row(i), work);
    out[i] = p.drift_dph;
    if (guarded && !guard.empty()) {
      if (i == 0 || data.group[i] != data.group[i - 1]) filter.reset();
      const double w = filter.update(data.time_s[i], p.target_weight, guard.settings.recover_s);
      out[i] = guarded_dph(p.drift_dph, w);
    }
  }
  return out;
}

std::vector<double> CompensationModel::predict_dph(const Recording& recording, bool guarded) const {
  return predict(recording, guarded).drift_dph;
}

RecordingPrediction CompensationModel::predict(const Recording& recording, bool guarded) const {
  FeatureOptions options = dataset.preprocessing;
  options.block.block_s = sample_interval_s(recording);
  const FeatureTable table = compute_features(recording, dataset.features, options);
  if (table.names != feature_names)
    throw InputError(recording.source, 0, 0,
                     fmt::format("gives features {} but the model expects {}",
                                 fmt::join(table.names, ","), fmt::join(feature_names, ",")));
  RecordingPrediction out;
  out.drift_dph.resize(table.rows);
  out.model_drift_dph.resize(table.rows);
  out.novelty.resize(table.rows);
  out.weight.resize(table.rows);
  std::vector<double> work(inputs());
  const std::size_t d = inputs();
  GuardFilter filter;
  for (std::size_t i = 0; i < table.rows; ++i) {
    const DriftPrediction p = predict(std::span<const double>(table.x.data() + i * d, d), work);
    out.model_drift_dph[i] = p.drift_dph;
    out.novelty[i] = p.novelty;
    out.weight[i] = 1.0;
    out.drift_dph[i] = p.drift_dph;
    if (guarded && !guard.empty()) {
      out.weight[i] = filter.update(table.time_s[i], p.target_weight, guard.settings.recover_s);
      out.drift_dph[i] = guarded_dph(p.drift_dph, out.weight[i]);
    }
  }
  return out;
}

namespace {

/// The temperature arguments a model reads, e.g. "temp_fog_degc" (docs/logs.md, "Fewer
/// thermometers").
std::string thermometers_read(const CompensationModel& model) {
  std::string out;
  const auto plan = model.dataset.features.columns();
  for (Thermometer k : {Thermometer::fog, Thermometer::acc1, Thermometer::acc2}) {
    if (std::none_of(plan.begin(), plan.end(), [k](const FeatureColumn& c) { return c.reads(k); }))
      continue;
    out += (out.empty() ? "" : ", ") + std::string(column_name(k));
  }
  return out.empty() ? std::string("none") : out;
}

ojson regressor_json(const std::variant<svr::Model, Mlp, Poly>& regressor) {
  if (const auto* m = std::get_if<svr::Model>(&regressor)) {
    ojson j = ojson::parse(svr::to_json(*m));
    ojson out;
    out["type"] = "svr";
    for (auto& [k, v] : j.items()) out[k] = v;
    return out;
  }
  if (const auto* m = std::get_if<Mlp>(&regressor)) {
    return ojson{{"type", "mlp"},       {"activation", "tanh"}, {"inputs", m->inputs},
                 {"hidden", m->hidden}, {"w1", m->w1},          {"b1", m->b1},
                 {"w2", m->w2},         {"b2", m->b2}};
  }
  const Poly& p = std::get<Poly>(regressor);
  ojson exps = ojson::array();
  for (std::size_t t = 0; t < p.terms(); ++t)
    exps.push_back(
        std::vector<int>(p.exponents.begin() + static_cast<std::ptrdiff_t>(t * p.inputs),
                         p.exponents.begin() + static_cast<std::ptrdiff_t>((t + 1) * p.inputs)));
  return ojson{{"type", "poly"},
               {"inputs", p.inputs},
               {"degree", p.degree},
               {"exponents", exps},
               {"coef", p.coef}};
}

}  // namespace

std::string to_json(const CompensationModel& m) {
  ojson j;
  j["format"] = "fogdrift-compensation-model";
  j["version"] = kCompensationModelVersion;
  const DatasetOptions& d = m.dataset;
  j["features"] = {
      {"spec", d.features.to_string()},
      {"names", m.feature_names},
      {"differentiator",
       {{"window_s", d.preprocessing.rates.window_s},
        {"poly_order", d.preprocessing.rates.poly_order},
        {"causality", std::string(signal::to_string(d.preprocessing.rates.causality))}}},
      {"block_s", d.preprocessing.block.block_s}};
  j["target"] = {{"denoise", d.denoise_target},
                 {"wavelet", d.denoise.wavelet},
                 {"level", d.denoise.level ? ojson(*d.denoise.level) : ojson("max")},
                 {"threshold", std::string(signal::to_string(d.denoise.threshold))},
                 {"mode", std::string(signal::to_string(d.denoise.shrinkage))},
                 {"extension", std::string(signal::to_string(d.denoise.extension))}};
  j["scalers"] = {{"features", {{"mean", m.x_scaler.mean}, {"scale", m.x_scaler.scale}}},
                  {"drift_dph", {{"mean", m.y_scaler.mean[0]}, {"scale", m.y_scaler.scale[0]}}}};
  j["regressor"] = regressor_json(m.regressor);
  if (!m.guard.empty())
    j["guard"] = {{"full_at", m.guard.settings.full_at},
                  {"zero_at", m.guard.settings.zero_at},
                  {"recover_s", m.guard.settings.recover_s},
                  {"radius", m.guard.radius},
                  {"prototypes", m.guard.size()},
                  {"points", m.guard.prototypes}};
  const Provenance& p = m.provenance;
  ojson hyper = ojson::object();
  for (const auto& [k, v] : p.hyperparameters) hyper[k] = v;
  ojson files = ojson::array();
  for (const auto& f : p.files) files.push_back({{"path", f.path}, {"sha256", f.sha256}});
  j["provenance"] = {{"method", to_string(p.method)},
                     {"fitness", p.fitness},
                     {"fitness_rmse", p.fitness_value},
                     {"cv", p.cv},
                     {"hyperparameters", hyper},
                     {"seed", p.seed},
                     {"population", p.population},
                     {"iterations", p.iterations},
                     {"training_rows", p.training_rows},
                     {"files", files},
                     {"fogdrift_version", p.fogdrift_version}};
  return j.dump(1) + "\n";
}

CompensationModel compensation_model_from_json(const std::string& text, const std::string& source) {
  ojson doc;
  try {
    doc = ojson::parse(text);
  } catch (const ojson::parse_error& e) {
    throw_json_syntax_error(source, text, e.byte, e.what());
  }
  auto fail = [&](const std::string& where, const std::string& rule) {
    throw InputError(source, 0, 0, fmt::format("{}: {}", where, rule));
  };
  if (!doc.is_object()) fail("(top level)", "must be a JSON object");
  if (!doc.contains("format") || doc["format"] != "fogdrift-compensation-model")
    fail("format",
         "must be \"fogdrift-compensation-model\" (is this a model written by "
         "`fogdrift train`?)");
  if (!doc.contains("version") || !doc["version"].is_number_integer())
    fail("version", "required integer field is missing");
  const int version = doc["version"].get<int>();
  if (version < 1 || version > kCompensationModelVersion)
    fail("version", fmt::format("model format version {} is not supported (this fogdrift reads "
                                "versions 1 to {}{})",
                                version, kCompensationModelVersion,
                                version > kCompensationModelVersion
                                    ? "; written by a newer fogdrift, upgrade to read it"
                                    : ""));
  CompensationModel m;
  std::string where = "features";
  try {
    const ojson& f = doc.at("features");
    m.dataset.features = FeatureSpec::parse(f.at("spec").get<std::string>());
    m.feature_names = f.at("names").get<std::vector<std::string>>();
    const ojson& dif = f.at("differentiator");
    m.dataset.preprocessing.rates.window_s = dif.at("window_s").get<double>();
    m.dataset.preprocessing.rates.poly_order = dif.at("poly_order").get<int>();
    m.dataset.preprocessing.rates.causality =
        signal::parse_causality(dif.at("causality").get<std::string>(), "causality");
    m.dataset.preprocessing.block.block_s = f.at("block_s").get<double>();
    where = "target";
    const ojson& t = doc.at("target");
    m.dataset.denoise_target = t.at("denoise").get<bool>();
    m.dataset.denoise.wavelet = t.at("wavelet").get<std::string>();
    if (t.at("level").is_number_integer()) m.dataset.denoise.level = t.at("level").get<int>();
    m.dataset.denoise.threshold =
        signal::parse_threshold_rule(t.at("threshold").get<std::string>());
    m.dataset.denoise.shrinkage = signal::parse_shrinkage(t.at("mode").get<std::string>());
    m.dataset.denoise.extension = signal::parse_extension(t.at("extension").get<std::string>());
    where = "scalers";
    const ojson& s = doc.at("scalers");
    m.x_scaler.names = m.feature_names;
    m.x_scaler.mean = s.at("features").at("mean").get<std::vector<double>>();
    m.x_scaler.scale = s.at("features").at("scale").get<std::vector<double>>();
    m.y_scaler.names = {"drift_dph"};
    m.y_scaler.mean = {s.at("drift_dph").at("mean").get<double>()};
    m.y_scaler.scale = {s.at("drift_dph").at("scale").get<double>()};
    where = "regressor";
    const ojson& r = doc.at("regressor");
    const std::string type = r.at("type").get<std::string>();
    if (type == "svr") {
      ojson svr_doc = r;
      svr_doc.erase("type");
      m.regressor = svr::model_from_json(svr_doc.dump(), source + " (regressor)");
    } else if (type == "mlp") {
      Mlp n;
      n.inputs = r.at("inputs").get<std::size_t>();
      n.hidden = r.at("hidden").get<std::size_t>();
      n.w1 = r.at("w1").get<std::vector<double>>();
      n.b1 = r.at("b1").get<std::vector<double>>();
      n.w2 = r.at("w2").get<std::vector<double>>();
      n.b2 = r.at("b2").get<double>();
      if (n.w1.size() != n.hidden * n.inputs || n.b1.size() != n.hidden || n.w2.size() != n.hidden)
        fail("regressor",
             fmt::format("weights do not match {} inputs and {} hidden units", n.inputs, n.hidden));
      m.regressor = std::move(n);
    } else if (type == "poly") {
      Poly p;
      p.inputs = r.at("inputs").get<std::size_t>();
      p.degree = r.at("degree").get<std::size_t>();
      p.coef = r.at("coef").get<std::vector<double>>();
      const auto exps = r.at("exponents").get<std::vector<std::vector<int>>>();
      if (exps.size() != p.coef.size())
        fail("regressor.exponents", "must hold one row per coefficient");
      for (const auto& e : exps) {
        if (e.size() != p.inputs)
          fail("regressor.exponents", "each row needs one exponent per input");
        for (int v : e) {
          if (v < 0 || v > static_cast<int>(p.degree))
            fail("regressor.exponents", fmt::format("exponent {} is outside 0 … degree", v));
          p.exponents.push_back(static_cast<std::uint8_t>(v));
        }
      }
      m.regressor = std::move(p);
    } else {
      fail("regressor.type", fmt::format("'{}' is not svr, mlp or poly", type));
    }
    if (version >= 2) {
      where = "guard";
      const ojson& g = doc.at("guard");
      m.guard.settings.full_at = g.at("full_at").get<double>();
      m.guard.settings.zero_at = g.at("zero_at").get<double>();
      m.guard.settings.recover_s = g.at("recover_s").get<double>();
      m.guard.settings.prototypes = g.at("prototypes").get<std::size_t>();
      m.guard.radius = g.at("radius").get<double>();
      m.guard.prototypes = g.at("points").get<std::vector<double>>();
      m.guard.dims = m.feature_names.size();
      validate(m.guard.settings);
    }
    where = "provenance";
    const ojson& p = doc.at("provenance");
    m.provenance.method = parse_method(p.at("method").get<std::string>());
    m.provenance.fitness = p.at("fitness").get<std::string>();
    m.provenance.fitness_value = p.at("fitness_rmse").get<double>();
    m.provenance.cv = p.at("cv").get<std::string>();
    for (const auto& [k, v] : p.at("hyperparameters").items())
      m.provenance.hyperparameters.emplace_back(k, v.get<double>());
    m.provenance.seed = p.at("seed").get<std::uint64_t>();
    m.provenance.population = p.at("population").get<std::size_t>();
    m.provenance.iterations = p.at("iterations").get<std::size_t>();
    m.provenance.training_rows = p.at("training_rows").get<std::size_t>();
    for (const auto& f : p.at("files"))
      m.provenance.files.push_back(
          {f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
    m.provenance.fogdrift_version = p.at("fogdrift_version").get<std::string>();
  } catch (const ojson::exception& e) {
    fail(where, fmt::format("missing or mistyped field ({})", e.what()));
  } catch (const OptionError& e) {
    fail(where, e.what());
  }
  const std::size_t d = m.feature_names.size();
  if (m.x_scaler.mean.size() != d || m.x_scaler.scale.size() != d)
    fail("scalers.features", fmt::format("needs {} means and scales, one per feature", d));
  for (double s : m.x_scaler.scale)
    if (!(s > 0) || !std::isfinite(s)) fail("scalers.features.scale", "must be finite and > 0");
  if (!(m.y_scaler.scale[0] > 0) || !std::isfinite(m.y_scaler.scale[0]))
    fail("scalers.drift_dph.scale", "must be finite and > 0");
  if (version >= 2) {
    if (m.guard.prototypes.size() != m.guard.settings.prototypes * d || m.guard.prototypes.empty())
      fail("guard.points", fmt::format("must hold prototypes × {} features numbers", d));
    if (!(m.guard.radius > 0) || !std::isfinite(m.guard.radius))
      fail("guard.radius", "must be finite and > 0");
    for (double v : m.guard.prototypes)
      if (!std::isfinite(v)) fail("guard.points", "must be finite numbers");
  }
  const std::size_t regressor_inputs = std::visit(
      [](const auto& r) -> std::size_t {
        if constexpr (std::is_same_v<std::decay_t<decltype(r)>, svr::Model>)
          return r.dims;
        else
          return r.inputs;
      },
      m.regressor);
  if (regressor_inputs != d)
    fail("regressor",
         fmt::format("takes {} inputs but the model has {} features", regressor_inputs, d));
  return m;
}

void save(const CompensationModel& model, const std::filesystem::path& path) {
  write_text_atomically(path, to_json(model));
}

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

CompensationModel load_compensation_model(const std::filesystem::path& path) {
  return compensation_model_from_json(read_text_file(path), path.string());
}

}  // namespace fogdrift
