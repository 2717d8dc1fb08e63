#include "fogdrift/model/model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

#include "base/json_number.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/sha256.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift {

using ojson = nlohmann::ordered_json;

namespace {

// A batch prediction never writes a drift that is not finite (docs/reliability.md, "Finite
// values"): readings inside the reader's ranges and a model as fogdrift writes it cannot give one,
// so an edited model (--allow-edited) or data that bypassed the reader did.
/// The model file's name for the target's scaler: drift_ and the target's unit.
std::string drift_scaler_name(const std::string& target_column) {
  return fmt::format("drift_{}", target_of(target_column).unit());
}

std::string non_finite_drift(double drift_dph, double time_s) {
  return fmt::format(
      "at time_s {} the model gives no drift it can stand by ({}: not a number, or more than "
      "{:g} of its training drift's standard deviations from their mean): its coefficients or "
      "these readings are beyond what it can compute with",
      time_s, drift_dph, kDriftLimitScales);
}

}  // namespace

DriftPrediction CompensationModel::predict(std::span<const double> features, std::span<double> work,
                                           bool warming) const {
  const std::size_t d = inputs();
  for (std::size_t k = 0; k < d; ++k)
    work[k] = (features[k] - x_scaler.mean[k]) / x_scaler.scale[k];
  const double z = fogdrift::predict(regressor, work.data());
  DriftPrediction out;
  // Beyond kDriftLimitScales training STDs, the drift is not one (model.hpp).
  out.drift_dph = std::abs(z) <= kDriftLimitScales ? z * y_scaler.scale[0] + y_scaler.mean[0]
                                                   : std::numeric_limits<double>::quiet_NaN();
  if (guard.empty()) {
    out.novelty = std::numeric_limits<double>::quiet_NaN();
  } else {
    out.novelty = guard.novelty(work.first(d), warming);
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
  std::size_t in_group = 0;  // the row's place in its recording
  for (std::size_t i = 0; i < data.rows; ++i) {
    in_group = (i == 0 || data.group[i] != data.group[i - 1]) ? 0 : in_group + 1;
    const bool warming = in_group < data.groups[data.group[i]].warm_rows;
    const DriftPrediction p = predict(data.row(i), work, warming);
    if (!std::isfinite(p.drift_dph))
      throw InputError(data.groups[data.group[i]].file, 0, 0,
                       non_finite_drift(p.drift_dph, data.time_s[i]));
    out[i] = p.drift_dph;
    if (guarded && !guard.empty()) {
      if (in_group == 0) filter.reset();
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
  // Data faster than the model's interval: its blocks, one prediction each, held (decimate.hpp).
  std::size_t k = 1;
  try {
    k = decimation_factor(dataset.preprocessing, sample_interval_s(recording), "rate");
  } catch (const OptionError& e) {
    throw InputError(recording.source, 0, 0, e.message());
  }
  if (k > 1) {
    const RecordingPrediction blocks = predict(decimate(recording, k), guarded);
    const auto held = [&](const std::vector<double>& per_block) {  // sized once: a kHz log
      std::vector<double> v(recording.size());
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = per_block[i / k];
      return v;
    };
    return {held(blocks.drift_dph), held(blocks.model_drift_dph), held(blocks.novelty),
            held(blocks.weight)};
  }
  FeatureOptions options = dataset.preprocessing;
  options.block.block_s = sample_interval_s(recording);
  const FeatureTable table = compute_features(recording, dataset.features, options);
  // The table's names are the spec's, so a difference is the model's own: names that are not
  // its spec's, a file edited or corrupted (with --allow-edited), not the recording's fault.
  if (table.names != feature_names)
    throw OptionError("model",
                      fmt::format("its feature names ({}) are not those of its own spec '{}' ({}): "
                                  "the model file was edited or is corrupt",
                                  fmt::join(feature_names, ","), dataset.features.to_string(),
                                  fmt::join(table.names, ",")));
  RecordingPrediction out;
  out.drift_dph.resize(table.rows);
  out.model_drift_dph.resize(table.rows);
  out.novelty.resize(table.rows);
  out.weight.resize(table.rows);
  std::vector<double> work(inputs());
  const std::size_t d = inputs();
  GuardFilter filter;
  for (std::size_t i = 0; i < table.rows; ++i) {
    const DriftPrediction p =
        predict(std::span<const double>(table.x.data() + i * d, d), work, i < table.warm_rows);
    if (!std::isfinite(p.drift_dph))
      throw InputError(recording.source, 0, 0, non_finite_drift(p.drift_dph, table.time_s[i]));
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

// SHA-256 of the text a model file's checksum covers, carriage returns left out (a file whose
// line ends were changed to CRLF in transit is the same model).
std::string checksum_of(std::string_view text) {
  std::string lf;
  lf.reserve(text.size());
  for (char c : text)
    if (c != '\r') lf += c;
  return sha256_hex(lf);
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
  if (d.preprocessing.sample_interval_s > 0)
    j["features"]["sample_interval_s"] = d.preprocessing.sample_interval_s;
  j["target"] = {{"denoise", d.denoise_target},
                 {"wavelet", d.denoise.wavelet},
                 {"level", d.denoise.level ? ojson(*d.denoise.level) : ojson("max")},
                 {"threshold", std::string(signal::to_string(d.denoise.threshold))},
                 {"mode", std::string(signal::to_string(d.denoise.shrinkage))},
                 {"extension", std::string(signal::to_string(d.denoise.extension))}};
  // Another axis names its column; a gyro_dph model's file stays as it was (its checksum too).
  if (d.target_column != "gyro_dph") j["target"]["column"] = d.target_column;
  // The target's scaler is named by its unit: drift_dph for a gyro, drift_g, drift_ppm.
  j["scalers"] = {{"features", {{"mean", m.x_scaler.mean}, {"scale", m.x_scaler.scale}}},
                  {drift_scaler_name(d.target_column),
                   {{"mean", m.y_scaler.mean[0]}, {"scale", m.y_scaler.scale[0]}}}};
  j["regressor"] = ojson::parse(to_json(m.regressor));
  if (!m.guard.empty())
    j["guard"] = {{"full_at", m.guard.settings.full_at},
                  {"zero_at", m.guard.settings.zero_at},
                  {"recover_s", m.guard.settings.recover_s},
                  {"radius", m.guard.radius},
                  {"prototypes", m.guard.size()},
                  {"points", m.guard.prototypes}};
  if (m.baselines.has_ranges()) {
    j["baselines"] = {{"input_min", m.baselines.input_min}, {"input_max", m.baselines.input_max}};
    if (m.baselines.line)
      j["baselines"]["line"] = {{"input", m.baselines.line->input},
                                {"intercept", m.baselines.line->intercept},
                                {"slope", m.baselines.line->slope}};
  }
  const Provenance& p = m.provenance;
  ojson hyper = ojson::object();
  for (const auto& [k, v] : p.hyperparameters) hyper[k] = v;
  ojson files = ojson::array();
  for (const auto& f : p.files) files.push_back({{"path", f.path}, {"sha256", f.sha256}});
  j["provenance"] = {{"method", p.method},
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
  if (!p.search.empty()) j["provenance"]["search"] = p.search;
  // The checksum covers the text before it (model.hpp): every field as written, in file order.
  std::string text = j.dump(1);
  text.resize(text.size() - 2);  // the closing "\n}"
  return text + ",\n \"checksum\": \"sha256:" + checksum_of(text) + "\"\n}\n";
}

CompensationModel compensation_model_from_json(const std::string& text, const std::string& source,
                                               const ModelLoadOptions& options) {
  check_json_nesting(source, text);
  ojson doc;
  try {
    doc = ojson::parse(text);
  } catch (const ojson::parse_error& e) {
    throw_json_syntax_error(source, text, e.byte, e.what());
  } catch (const ojson::out_of_range& e) {
    throw_json_number_error(source, text, e.what());
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
  int version = 0;
  try {
    version = fogdrift::detail::whole_number<int>(doc["version"]);
  } catch (const ojson::exception&) {
    fail("version", fmt::format("{} is not a format version", doc["version"].dump()));
  }
  if (version < 1 || version > kCompensationModelVersion)
    fail("version", fmt::format("model format version {} is not supported (this fogdrift reads "
                                "versions 1 to {}{})",
                                version, kCompensationModelVersion,
                                version > kCompensationModelVersion
                                    ? "; written by a newer fogdrift, upgrade to read it"
                                    : ""));
  if (version < 3 && !options.allow_old_format && !doc.contains("checksum"))
    fail("version",
         fmt::format("format version {} carries no checksum{}, so nothing shows whether the file "
                     "was edited since it was written. Train the model again, or load it with "
                     "--allow-old-format",
                     version,
                     version == 1 ? " and no novelty guard (it compensates unguarded)" : ""));
  CompensationModel m;
  std::string where = "features";
  try {
    const ojson& f = doc.at("features");
    m.dataset.features = FeatureSpec::parse(f.at("spec").get<std::string>());
    m.feature_names = f.at("names").get<std::vector<std::string>>();
    // The names are what firmware authors wire their inputs by: they must be the spec's own, in
    // its order, or a header would label one input with another's name.
    if (const std::vector<std::string> expected = m.dataset.features.names();
        m.feature_names != expected)
      fail(
          "features.names",
          fmt::format("'{}' are not the names spec '{}' gives its features, in order ('{}'); "
                      "the file was edited: train the model again",
                      csv::excerpt(fmt::format("{}", fmt::join(m.feature_names, ","))),
                      m.dataset.features.to_string(), fmt::format("{}", fmt::join(expected, ","))));
    const ojson& dif = f.at("differentiator");
    m.dataset.preprocessing.rates.window_s = dif.at("window_s").get<double>();
    m.dataset.preprocessing.rates.poly_order =
        fogdrift::detail::whole_number<int>(dif.at("poly_order"));
    m.dataset.preprocessing.rates.causality =
        signal::parse_causality(dif.at("causality").get<std::string>(), "causality");
    m.dataset.preprocessing.block.block_s = f.at("block_s").get<double>();
    if (f.contains("sample_interval_s")) {
      m.dataset.preprocessing.sample_interval_s = f.at("sample_interval_s").get<double>();
      if (!(m.dataset.preprocessing.sample_interval_s > 0) ||
          !std::isfinite(m.dataset.preprocessing.sample_interval_s))
        fail("features.sample_interval_s", "must be a finite interval > 0 s");
    }
    where = "target";
    const ojson& t = doc.at("target");
    m.dataset.denoise_target = t.at("denoise").get<bool>();
    m.dataset.denoise.wavelet = t.at("wavelet").get<std::string>();
    if (t.at("level").is_number_integer())
      m.dataset.denoise.level = fogdrift::detail::whole_number<int>(t.at("level"));
    m.dataset.denoise.threshold =
        signal::parse_threshold_rule(t.at("threshold").get<std::string>());
    m.dataset.denoise.shrinkage = signal::parse_shrinkage(t.at("mode").get<std::string>());
    m.dataset.denoise.extension = signal::parse_extension(t.at("extension").get<std::string>());
    if (t.contains("column")) {
      m.dataset.target_column = t.at("column").get<std::string>();
      if (!is_target_column(m.dataset.target_column))
        fail("target.column",
             fmt::format("'{}' is not a target column (gyro_NAME_dph, accel_NAME_g, sf_NAME_ppm)",
                         csv::excerpt(m.dataset.target_column)));
    }
    where = "scalers";
    const ojson& s = doc.at("scalers");
    m.x_scaler.names = m.feature_names;
    m.x_scaler.mean = s.at("features").at("mean").get<std::vector<double>>();
    m.x_scaler.scale = s.at("features").at("scale").get<std::vector<double>>();
    const std::string drift = drift_scaler_name(m.dataset.target_column);
    m.y_scaler.names = {drift};
    m.y_scaler.mean = {s.at(drift).at("mean").get<double>()};
    m.y_scaler.scale = {s.at(drift).at("scale").get<double>()};
    where = "regressor";
    const ojson& r = doc.at("regressor");
    const std::string type = r.at("type").get<std::string>();
    ojson own = r;  // the regressor's own JSON, without its type
    own.erase("type");
    if (!is_regressor_type(type))
      fail("regressor.type", fmt::format("'{}' is not {}", type, regressor_types()));
    m.regressor = regressor_from_json(type, own.dump(), source + " (regressor)");
    if (version >= 2) {
      where = "guard";
      const ojson& g = doc.at("guard");
      m.guard.settings.full_at = g.at("full_at").get<double>();
      m.guard.settings.zero_at = g.at("zero_at").get<double>();
      m.guard.settings.recover_s = g.at("recover_s").get<double>();
      m.guard.settings.prototypes = fogdrift::detail::whole_number<std::size_t>(g.at("prototypes"));
      m.guard.radius = g.at("radius").get<double>();
      m.guard.prototypes = g.at("points").get<std::vector<double>>();
      m.guard.dims = m.feature_names.size();
      m.guard.set_warmup_inputs(m.dataset.features.rate_inputs());
      validate(m.guard.settings);
    }
    if (doc.contains("baselines")) {
      where = "baselines";
      const ojson& b = doc.at("baselines");
      m.baselines.input_min = b.at("input_min").get<std::vector<double>>();
      m.baselines.input_max = b.at("input_max").get<std::vector<double>>();
      if (b.contains("line"))
        m.baselines.line = BaselineLine{b.at("line").at("input").get<std::string>(),
                                        b.at("line").at("intercept").get<double>(),
                                        b.at("line").at("slope").get<double>()};
    }
    where = "provenance";
    const ojson& p = doc.at("provenance");
    m.provenance.method = p.at("method").get<std::string>();
    if (m.provenance.method.empty()) fail("provenance.method", "must name the method");
    m.provenance.fitness = p.at("fitness").get<std::string>();
    m.provenance.fitness_value = p.at("fitness_rmse").get<double>();
    m.provenance.cv = p.at("cv").get<std::string>();
    for (const auto& [k, v] : p.at("hyperparameters").items())
      m.provenance.hyperparameters.emplace_back(k, v.get<double>());
    m.provenance.seed = fogdrift::detail::whole_number<std::uint64_t>(p.at("seed"));
    m.provenance.population = fogdrift::detail::whole_number<std::size_t>(p.at("population"));
    m.provenance.iterations = fogdrift::detail::whole_number<std::size_t>(p.at("iterations"));
    m.provenance.training_rows = fogdrift::detail::whole_number<std::size_t>(p.at("training_rows"));
    for (const auto& f : p.at("files"))
      m.provenance.files.push_back(
          {f.at("path").get<std::string>(), f.at("sha256").get<std::string>()});
    m.provenance.fogdrift_version = p.at("fogdrift_version").get<std::string>();
    if (p.contains("search")) m.provenance.search = p.at("search").get<std::string>();
  } catch (const ojson::exception& e) {
    fail(where, fmt::format("missing or mistyped field ({})", json_error_text(e)));
  } catch (const OptionError& e) {
    fail(where, e.what());
  }
  const std::size_t d = m.feature_names.size();
  if (m.x_scaler.mean.size() != d || m.x_scaler.scale.size() != d)
    fail("scalers.features", fmt::format("needs {} means and scales, one per feature", d));
  // Bounds on every number (model.hpp), so that no finite input makes a non-finite or absurd
  // standardised value, novelty or drift.
  const std::string drift_scaler = "scalers." + drift_scaler_name(m.dataset.target_column);
  auto within = [&](double v, double limit) { return std::abs(v) <= limit; };
  for (double s : m.x_scaler.scale)
    if (!(s >= kModelSmallestScale && s <= kModelScalerLimit))
      fail("scalers.features.scale", fmt::format("{} is not a scale in [{:g}, {:g}]", s,
                                                 kModelSmallestScale, kModelScalerLimit));
  for (double v : m.x_scaler.mean)
    if (!within(v, kModelScalerLimit))
      fail("scalers.features.mean",
           fmt::format("{} is not a finite mean of magnitude at most {:g}", v, kModelScalerLimit));
  if (!(m.y_scaler.scale[0] > 0) || !within(m.y_scaler.scale[0], kModelScalerLimit))
    fail(drift_scaler + ".scale",
         fmt::format("{} is not a scale in (0, {:g}]", m.y_scaler.scale[0], kModelScalerLimit));
  if (!within(m.y_scaler.mean[0], kModelScalerLimit))
    fail(drift_scaler + ".mean", fmt::format("{} is not a finite mean of magnitude at most {:g}",
                                             m.y_scaler.mean[0], kModelScalerLimit));
  {
    // Every number of the regressor, whatever its type, within kModelRegressorLimit.
    std::string at;
    std::function<bool(const ojson&, const std::string&)> bounded = [&](const ojson& j,
                                                                        const std::string& path) {
      if (j.is_number_float() || j.is_number_integer()) {
        if (!within(j.get<double>(), kModelRegressorLimit)) return at = path, false;
        return true;
      }
      if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i)
          if (!bounded(j[i], path)) return false;
        return true;
      }
      if (j.is_object()) {
        for (const auto& [key, value] : j.items())
          if (!bounded(value, path + "." + key)) return false;
      }
      return true;
    };
    if (doc.contains("regressor") && !bounded(doc["regressor"], "regressor"))
      fail(at, fmt::format("holds a number of magnitude beyond {:g}: no model fogdrift trains "
                           "has one; the file was edited or is corrupt",
                           kModelRegressorLimit));
  }
  if (version >= 2) {
    if (m.guard.prototypes.size() != m.guard.settings.prototypes * d || m.guard.prototypes.empty())
      fail("guard.points", fmt::format("must hold prototypes × {} features numbers", d));
    if (!(m.guard.radius > 0) || !within(m.guard.radius, kModelScalerLimit))
      fail("guard.radius", fmt::format("must be in (0, {:g}]", kModelScalerLimit));
    for (double v : m.guard.prototypes)
      if (!within(v, kModelScalerLimit))
        fail("guard.points",
             fmt::format("must be finite numbers of magnitude at most {:g}", kModelScalerLimit));
  }
  if (m.baselines.has_ranges()) {
    if (m.baselines.input_min.size() != d || m.baselines.input_max.size() != d)
      fail("baselines", fmt::format("needs {} input minima and maxima, one per feature", d));
    for (std::size_t k = 0; k < d; ++k)
      if (!(m.baselines.input_min[k] <= m.baselines.input_max[k]) ||
          !within(m.baselines.input_min[k], kModelScalerLimit) ||
          !within(m.baselines.input_max[k], kModelScalerLimit))
        fail("baselines.input_min",
             fmt::format("feature {}: [{}, {}] is not a finite range of magnitude at most {:g}",
                         k + 1, m.baselines.input_min[k], m.baselines.input_max[k],
                         kModelScalerLimit));
    if (const auto& line = m.baselines.line) {
      if (std::find(m.feature_names.begin(), m.feature_names.end(), line->input) ==
          m.feature_names.end())
        fail("baselines.line.input",
             fmt::format("'{}' is not one of the model's features", csv::excerpt(line->input)));
      if (!within(line->intercept, kModelRegressorLimit) ||
          !within(line->slope, kModelRegressorLimit))
        fail("baselines.line", fmt::format("needs a finite intercept and slope of magnitude at "
                                           "most {:g}",
                                           kModelRegressorLimit));
    }
  }
  const std::size_t regressor_inputs = input_count(m.regressor);
  if (regressor_inputs != d)
    fail("regressor",
         fmt::format("takes {} inputs but the model has {} features", regressor_inputs, d));
  // The content must be what fogdrift wrote (checked last, so that a field that is wrong is
  // named first). A checksum is checked whatever version the file claims: lowering the version
  // of an edited file must not let the edit through.
  if (version >= 3 || doc.contains("checksum")) {
    const std::size_t key = text.rfind("\"checksum\"");
    if (!doc.contains("checksum") || !doc["checksum"].is_string() || key == std::string::npos)
      fail("checksum", "required field is missing (every version-3 model file carries one)");
    std::string_view covered = std::string_view(text).substr(0, key);
    while (!covered.empty() && std::isspace(static_cast<unsigned char>(covered.back())))
      covered.remove_suffix(1);
    if (!covered.empty() && covered.back() == ',') covered.remove_suffix(1);
    const std::string written = doc["checksum"].get<std::string>();
    if (written != "sha256:" + checksum_of(covered) && !options.allow_edited)
      fail("checksum",
           "the content does not match its checksum: the file was edited or corrupted after "
           "fogdrift wrote it. Train the model again, or, if the edit was deliberate, load it "
           "with --allow-edited");
  }
  return m;
}

void save(const CompensationModel& model, const std::filesystem::path& path) {
  write_text_atomically(path, to_json(model));
}

CompensationModel load_compensation_model(const std::filesystem::path& path,
                                          const ModelLoadOptions& options) {
  return compensation_model_from_json(read_text_file(path), path.string(), options);
}

}  // namespace fogdrift
