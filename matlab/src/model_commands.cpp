// fogdrift.Model's methods: a model travels through Octave/MATLAB as its file's text, checked
// again (checksum included) at every call, so a model object is a value like any other and
// saving it writes the bytes `fogdrift train -o` writes (docs/matlab.md).
#include <fmt/format.h>

#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/model/compensate_file.hpp"
#include "fogdrift/model/compensate_option_table.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_load_option_table.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/stream/compensator.hpp"

namespace fogdrift::matlab {
namespace {

CompensationModel model_of(const Args& args) {
  return compensation_model_from_json(text_of(args.at(0, "model"), "model"), "model", {});
}

/// The options of predict and compensate (compensate_option_table.hpp), from argument `first` on.
CompensateOptions compensate_options_of(const Args& args, std::size_t first) {
  const auto& table = compensate_option_table();
  CompensateOptions o;
  for (const auto& [name, value] : apply_options(table, o, name_values(args, first)))
    unknown_option(args.function, name, {}, specs_of(table));
  return o;
}

}  // namespace

void model_load(const Args& args, Results& out) {
  const std::string path = text_of(args.at(0, "path"), "path");
  std::optional<std::string> target;
  const auto& table = model_load_option_table();
  ModelLoadOptions load;
  for (const auto& [name, value] : apply_options(table, load, name_values(args, 1))) {
    if (name != "target") unknown_option(args.function, name, {"target"}, specs_of(table));
    target = text_of(value, "target");
  }
  const ModelSet set = load_model_set(path, load);
  out.values.push_back(text(to_json(choose_model(set, target, "target"))));
}

void model_info(const Args& args, Results& out) {
  const CompensationModel m = model_of(args);
  nlohmann::ordered_json j;
  j["method"] = m.provenance.method;
  j["target"] = m.dataset.target_column;
  j["feature_names"] = m.feature_names;
  j["hyperparameters"] = nlohmann::ordered_json::object();
  for (const auto& [k, v] : m.provenance.hyperparameters) j["hyperparameters"][k] = v;
  j["fitness"] = m.provenance.fitness;
  j["fitness_value"] = m.provenance.fitness_value;
  j["training_rows"] = m.provenance.training_rows;
  j["causal"] = m.dataset.preprocessing.rates.causality == signal::Causality::causal;
  out.values.push_back(to_mx(j));
}

void model_predict(const Args& args, Results& out) {
  const CompensationModel m = model_of(args);
  const mxArray* r = args.at(1, "recording");
  const Recording recording = mxIsChar(r) ? fogdrift::read_recording(text_of(r, "recording"))
                                          : recording_of(r, "recording");
  const RecordingPrediction p = m.predict(recording, compensate_options_of(args, 2).guarded);
  // Fields in the target's unit: drift_dph for a gyro, drift_g, drift_ppm (target.hpp).
  const std::string unit(target_of(m.dataset.target_column).unit());
  nlohmann::ordered_json names = {"drift_" + unit, "model_drift_" + unit, "novelty",
                                  "guard_weight"};
  const std::vector<const std::vector<double>*> values = {&p.drift_dph, &p.model_drift_dph,
                                                          &p.novelty, &p.weight};
  std::vector<std::string> fields;
  std::vector<const char*> c;
  for (const auto& n : names) fields.push_back(n.get<std::string>());
  for (const auto& f : fields) c.push_back(f.c_str());
  MxPtr s(mxCreateStructMatrix(1, 1, static_cast<int>(c.size()), c.data()));
  for (std::size_t k = 0; k < c.size(); ++k)
    mxSetField(s.get(), 0, c[k], column(*values[k]).release());
  out.values.push_back(std::move(s));
}

void model_save(const Args& args, Results&) {
  const CompensationModel m = model_of(args);
  save(m, text_of(args.at(1, "path"), "path"));
}

void model_export_c(const Args& args, Results& out) {
  const CompensationModel m = model_of(args);
  const std::string path = text_of(args.at(1, "path"), "path");
  const auto& table = export_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  ExportOptions o;
  o.faults = fault_policy_of(m);  // the timings fitted to the model, as export-c fits them
  for (const auto& [name, value] :
       in_keywords_of(specs, [&] { return apply_options(table, o, name_values(args, 2)); }))
    unknown_option(args.function, name, {}, specs);
  in_keywords_of(specs, [&] { validate(o.faults); });
  const std::string header = in_keywords_of(specs, [&] {
    return to_c_header(m, o.prefix, o.stream_rate_hz > 0 ? 1.0 / o.stream_rate_hz : 0.0, o.faults,
                       o.precision);
  });
  if (o.precision == CPrecision::single) {
    const FloatPrecisionCheck check = check_float_precision(m);
    if (check.share() > kFloatShareLimit) {
      const std::string what = fmt::format(
          "in float, the drift departs from the model's by up to {:.3g} {} on its own training "
          "inputs, {:.3g} of the drift's STD (the limit is {:g}): float keeps too few digits of "
          "these inputs (docs/firmware.md, \"Float\")",
          check.max_error, target_of(m.dataset.target_column).unit(), check.share(),
          kFloatShareLimit);
      if (!o.force_float)
        throw OptionError("precision", what +
                                           "; use 'precision', 'double', or 'force_float', "
                                           "true to write it anyway");
      out.warnings.push_back(what + "; written anyway (force_float)");
    }
  }
  if (o.stream_rate_hz > 0 && m.dataset.preprocessing.rates.causality != signal::Causality::causal)
    out.warnings.push_back(
        "the model was trained with centred temperature rates; the header's update computes "
        "causal ones, so its drift differs from predict's (train with 'differentiator', "
        "'causal' for firmware)");
  write_text_atomically(path, header);
}

void compensate(const Args& args, Results& out) {
  const CompensationModel m = model_of(args);
  const std::string input = text_of(args.at(1, "input"), "input");
  const std::string output = text_of(args.at(2, "output"), "output");
  const CompensateOptions options = compensate_options_of(args, 3);
  check_output_not_among(output, {input}, "output");
  ModelSet set;
  set.models.push_back(m);
  const CompensatedAxis axis = compensate_file(set, input, output, options).front();
  nlohmann::ordered_json j;
  j["samples"] = axis.prediction.drift_dph.size();
  j["columns"] = axis.columns;
  j["novelty"] = axis.novelty.line();
  out.values.push_back(to_mx(j));
}

void read_recording(const Args& args, Results& out) {
  out.values.push_back(to_struct(fogdrift::read_recording(text_of(args.at(0, "path"), "path"))));
}

}  // namespace fogdrift::matlab
