// fogdrift.evaluate, fogdrift.northfind, fogdrift.allan_deviation and fogdrift.noise_terms: a
// model's Table 2 and Table 3, and the gyro's noise terms (eval/evaluation.hpp,
// eval/findings.hpp, eval/allan.hpp; docs/python.md).
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/allan.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/eval/evaluation.hpp"
#include "fogdrift/eval/findings.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/campaign_option_table.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/report/evaluation_figures.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

using Array = py::array_t<double, py::array::forcecast>;

bool is_path(const py::object& o) {
  return py::isinstance<py::str>(o) || py::hasattr(o, "__fspath__");
}

// A campaign folder or its campaign.json (not a recording CSV).
bool is_campaign(const py::object& o) {
  if (!is_path(o)) return false;
  const auto p = o.cast<std::filesystem::path>();
  return std::filesystem::is_directory(p) || p.extension() == ".json";
}

py::object evaluate(const CompensationModel& model, const py::object& data,
                    const std::optional<std::filesystem::path>& figures, const py::kwargs& kwargs) {
  // What the recordings' channels sensed (sensed_option_table, as `evaluate --input-rate-dph`
  // and `--reference`), then the evaluation's own options.
  py::kwargs sensed_kwargs, evaluation_kwargs;
  for (const auto& [key, value] : kwargs)
    (find_option(sensed_option_table(), key.cast<std::string>()) ? sensed_kwargs
                                                                 : evaluation_kwargs)[key] = value;
  SensedOptions sensed;
  apply_keywords(sensed_option_table(), sensed, sensed_kwargs, "evaluate");
  eval::EvaluationOptions options;
  std::vector<std::string> own{"model", "data", "figures"};
  for (const auto& o : sensed_option_table()) own.push_back(o.spec.keyword);
  apply_keywords(eval::evaluation_option_table(), options, evaluation_kwargs, "evaluate", own);
  options.series = figures.has_value();
  const std::optional<double>& input_rate_dph = sensed.input_rate_dph;
  const std::map<std::string, double>& references = sensed.references;
  eval::Evaluation e;
  std::string source;
  if (is_held_campaign(data)) {
    // A campaign in memory (what fogdrift.simulate returns, what train takes): its calibration
    // recordings with role test, each with its manifest's input.
    if (input_rate_dph || !references.empty())
      throw OptionError(input_rate_dph ? "input_rate_dph" : "references",
                        "applies to recordings; a campaign says its input in its manifest");
    const HeldCampaign held = held_campaign(data);
    const std::vector<RecordingInput> inputs =
        recording_inputs(held.campaign, held.recordings, Role::test);
    if (inputs.empty())
      throw InputError("campaign", 0, 0, "has no calibration recordings with role test");
    source = "campaign (recordings with role \"test\")";
    py::gil_scoped_release release;
    e = eval::evaluate(model, inputs, options);
  } else if (is_campaign(data)) {
    if (input_rate_dph || !references.empty())
      throw OptionError(input_rate_dph ? "input_rate_dph" : "references",
                        "applies to recordings; a campaign says its input in campaign.json "
                        "(fogdrift campaign --input-rate-dph, --reference)");
    const Campaign campaign = read_campaign(data.cast<std::filesystem::path>());
    py::gil_scoped_release release;
    e = eval::evaluate(model, campaign, options);
    source = campaign.dir.string() + " (recordings with role \"test\")";
  } else {
    // One recording (a path or a mapping of columns) or a list of them.
    std::vector<py::object> items;
    if (is_path(data) || py::hasattr(data, "keys"))
      items.push_back(data);
    else
      for (const py::handle item : data) items.push_back(py::reinterpret_borrow<py::object>(item));
    std::vector<RecordingInput> inputs;
    for (std::size_t i = 0; i < items.size(); ++i) {
      RecordingInput in;
      in.info.file = is_path(items[i]) ? items[i].cast<std::filesystem::path>().string()
                                       : "recording " + std::to_string(i + 1);
      // Another axis than gyro_dph is a column fogdrift does not know: keep it.
      in.recording =
          to_recording(items[i], in.info.file, model.dataset.target_column != "gyro_dph");
      in.input_rate_dph = input_rate_dph;
      in.references = references;
      inputs.push_back(std::move(in));
    }
    if (inputs.empty()) throw OptionError("data", "no recordings to evaluate on");
    source = std::to_string(inputs.size()) + " recording" + (inputs.size() == 1 ? "" : "s");
    {
      py::gil_scoped_release release;
      e = eval::evaluate(model, inputs, options);
    }
    // Recordings have no campaign to give a reference in: the hint names this call's keywords.
    const Target t = target_of(model.dataset.target_column);
    const std::string command = fmt::format("(give it with {})", t.reference_hint());
    const std::string keywords =
        t.kind == TargetKind::gyro
            ? std::string("(give it as input_rate_dph=VALUE, °/h)")
            : fmt::format("(give it as references={{'{}': VALUE}}, {})", t.column, t.symbol());
    for (std::string& w : e.warnings)
      if (const auto at = w.find(command); at != std::string::npos)
        w.replace(at, command.size(), keywords);
  }
  py::dict out = from_json(eval::to_json(e, "model", source)).cast<py::dict>();
  out.attr("pop")("model");
  if (figures) {
    // As `fogdrift evaluate --figures`: PNG and JSON, the folder whole or not at all.
    const std::vector<report::Figure> drawn = report::evaluation_figures(
        e, model.baselines, model.feature_names,
        model.dataset.target_column == "gyro_dph" ? "" : model.dataset.target_column + "_");
    std::vector<std::string> problems;
    {
      py::gil_scoped_release release;
      fill_directory_atomically(*figures, false, [&](const std::filesystem::path& dir) {
        problems = report::write_figures(drawn, dir);
      });
    }
    py::list names;
    for (const report::Figure& f : drawn) names.append(f.name);
    out["figures"] = names;
    for (const std::string& p : problems) warn(("no PNG: " + p).c_str());
  }
  // What the command prints as warnings (a lost turn-on bias, …) is a Python warning too.
  for (const py::handle w : out["warnings"]) warn(w.cast<std::string>().c_str());
  // So is the harm the model does, and a model no better than its baselines: out["verdict"].
  const std::string unit(target_of(e.target).symbol());
  for (const eval::RecordingEvaluation& r : e.recordings) {
    for (const std::string& h : r.baselines.harms)
      warn(fmt::format("the model harms {}: {}", r.info.file, eval::with_unit(h, unit)).c_str());
    if (!r.baselines.no_better_than.empty())
      warn(fmt::format("the model is no better than {} on {}",
                       fmt::join(r.baselines.no_better_than, " and "), r.info.file)
               .c_str());
  }
  return out;
}

py::object northfind(const py::object& campaign_path, const CompensationModel* model,
                     const py::kwargs& kwargs) {
  eval::FindingOptions options;
  apply_keywords(eval::finding_option_table(), options, kwargs, "northfind", {"campaign", "model"});
  eval::CampaignFindings f;
  std::string label;
  if (is_held_campaign(campaign_path)) {
    // A campaign in memory, what fogdrift.simulate returns.
    const HeldCampaign held = held_campaign(campaign_path);
    label = "campaign";
    py::gil_scoped_release release;
    f = eval::find_north(held.campaign, held.recordings, model, options);
  } else {
    if (!is_campaign(campaign_path))
      throw OptionError("campaign",
                        "must be a campaign folder, its campaign.json, or a campaign in memory "
                        "(what fogdrift.simulate returns)");
    const Campaign campaign = read_campaign(campaign_path.cast<std::filesystem::path>());
    label = campaign.dir.string();
    py::gil_scoped_release release;
    f = eval::find_north(campaign, model, options);
  }
  py::dict out = from_json(eval::to_json(f, label, "model")).cast<py::dict>();
  if (out.contains("model")) out.attr("pop")("model");
  return out;
}

// Every four-position finding of one recording: the field's case, a unit on its turntable with
// no manifest and no truth.
py::list find_north(const py::object& recording, double latitude_deg,
                    const CompensationModel* model, const py::kwargs& kwargs) {
  eval::FindingOptions o;
  apply_keywords(eval::finding_option_table(), o, kwargs, "find_north",
                 {"recording", "latitude_deg", "model"});
  const bool guarded = o.guarded;
  if (!(latitude_deg >= -90 && latitude_deg <= 90))
    throw OptionError("latitude_deg", "must be within [-90, 90]");
  const Recording r = to_recording(recording, "(recording)");
  if (!r.table_deg || !r.accel_x_g || !r.accel_y_g)
    throw InputError(r.source.empty() ? "(recording)" : r.source, 0, 0,
                     "four-position north-finding needs the columns table_deg, accel_x_g and "
                     "accel_y_g");
  const eval::SegmentationOptions& options = o.segmentation;
  std::vector<eval::FourPositionReadings> findings;
  std::vector<eval::FourPositionSolution> solutions;
  {
    py::gil_scoped_release release;
    std::vector<double> gyro;
    if (model != nullptr) {
      gyro = model->predict_dph(r, guarded);
      for (std::size_t i = 0; i < gyro.size(); ++i) gyro[i] = r.gyro_dph[i] - gyro[i];
    }
    findings = eval::segment_findings(r, options, model != nullptr ? &gyro : nullptr);
    for (const auto& f : findings) solutions.push_back(eval::solve_four_position(f, latitude_deg));
  }
  py::list out;
  for (std::size_t k = 0; k < findings.size(); ++k) {
    py::dict d;
    d["azimuth_deg"] = solutions[k].azimuth_deg;
    d["pitch_deg"] = solutions[k].pitch_deg;
    d["roll_deg"] = solutions[k].roll_deg;
    d["horizontal_rate_dph"] = solutions[k].horizontal_rate_dph;
    d["start_s"] = findings[k].start_s[0];
    d["end_s"] = findings[k].end_s[3];
    d["gyro_dph"] =
        py::cast(std::vector<double>(findings[k].gyro_dph.begin(), findings[k].gyro_dph.end()));
    out.append(d);
  }
  return out;
}

// A rate signal: 1-D and finite (allan.hpp leaves that check to its caller).
Array rate_signal(const py::object& rate) {
  const auto x = Array::ensure(rate);
  if (!x || x.ndim() != 1) throw OptionError("rate", "must be a 1-D array of numbers");
  for (py::ssize_t i = 0; i < x.shape(0); ++i)
    if (!std::isfinite(x.at(i)))
      throw OptionError("rate", "sample " + std::to_string(i) + " is not a finite number");
  return x;
}

py::tuple allan_deviation(const py::object& rate, double dt_s, std::size_t points_per_decade) {
  const Array x = rate_signal(rate);
  eval::AllanDeviation a;
  {
    py::gil_scoped_release release;
    a = eval::allan_deviation({x.data(), static_cast<std::size_t>(x.shape(0))}, dt_s,
                              points_per_decade);
  }
  py::array_t<std::int64_t> m(static_cast<py::ssize_t>(a.m.size()));
  for (std::size_t i = 0; i < a.m.size(); ++i) m.mutable_at(i) = static_cast<std::int64_t>(a.m[i]);
  return py::make_tuple(to_array(std::move(a.tau_s)), to_array(std::move(a.adev)), m);
}

py::dict noise_terms(const py::object& rate, double dt_s) {
  const Array x = rate_signal(rate);
  eval::NoiseTerms t;
  {
    py::gil_scoped_release release;
    t = eval::noise_terms(
        eval::allan_deviation({x.data(), static_cast<std::size_t>(x.shape(0))}, dt_s, 10));
  }
  py::dict out;
  out["arw_deg_per_rt_h"] = t.arw_deg_per_rt_h;
  out["bias_instability_dph"] = t.bias_instability_dph;
  out["rrw_dph_per_rt_h"] = t.rrw_dph_per_rt_h;
  out["arw_tau_s"] = t.arw_tau_s;
  out["bias_instability_tau_s"] = t.bias_instability_tau_s;
  out["rrw_tau_s"] = t.rrw_tau_s;
  return out;
}

}  // namespace

void bind_eval(py::module_& m) {
  m.def(
      "sensed_options", [] { return describe_options(sensed_option_table()); },
      "What the channels of fogdrift.evaluate's recordings sensed (input_rate_dph, "
      "references), one dict each: the descriptions `fogdrift evaluate --input-rate-dph` and "
      "`--reference` come from (docs/options.md).");
  m.def(
      "evaluate_options", [] { return describe_options(eval::evaluation_option_table()); },
      "The options of fogdrift.evaluate, one dict each (keyword, type, default, unit, doc, flag): "
      "the descriptions `fogdrift evaluate`'s flags come from (docs/options.md).");
  m.def(
      "northfind_options", [] { return describe_options(eval::finding_option_table()); },
      "The options of fogdrift.northfind and fogdrift.find_north, one dict each (keyword, type, "
      "default, unit, doc, flag): the descriptions `fogdrift northfind`'s flags come from "
      "(docs/options.md).");
  m.def("evaluate", &evaluate, py::arg("model"), py::arg("data"), py::kw_only(),
        py::arg("figures") = py::none(),
        "The paper's Table 2 view of a Model on test data, as `fogdrift evaluate --json` prints "
        "it: data is a campaign folder (its recordings with role 'test'), a recording (a path or "
        "a mapping of columns) or a list of them. Recordings have no manifest to say what rate "
        "the gyro sensed: give it as input_rate_dph (°/h; 0 for an axis that sees no rotation), "
        "or the target subtracts each recording's mean and the turn-on bias is lost; another "
        "target's reference is given in references, e.g. {'accel_x_g': 0.0} (docs/logs.md, "
        "\"Other targets\"). Returns a "
        "dict: 'method', 'source', "
        "'overall' and one entry per recording in 'recordings' (MAE, RMSE, STD before and "
        "after, start-up residual, opposite-position difference, all °/h, or the target's unit "
        "as the keys say; novelty shares; with "
        "allan=True the Allan noise terms raw and compensated), 'guard', 'warnings'; the model "
        "beside its baselines ('baselines', 'verdict', 'harmed', 'no_better', each recording's "
        "'baselines' and 'extrapolation'; a Python warning for each harm); with figures=DIR, "
        "the figures `fogdrift evaluate --figures` draws, written to DIR as PNG and JSON, and "
        "their names under 'figures'.");
  m.def("northfind", &northfind, py::arg("campaign"), py::arg("model") = nullptr,
        "Four-position north-finding on a campaign's northfind and stable recordings, raw and "
        "with the model's drift subtracted (paper Table 3), as `fogdrift northfind --json` "
        "prints it: a dict with each recording's per-finding azimuth errors (°) and 'table3' "
        "(RMSE per initial temperature; on simulated recordings the floor with the true drift "
        "subtracted and the share of the removable error removed, on the RMSEs as "
        "'removable_error_removed' and finding by finding as 'drift_error_removed').");
  m.def("find_north", &find_north, py::arg("recording"), py::arg("latitude_deg"),
        py::arg("model") = nullptr,
        "Every four-position finding of one recording (a path or a mapping of columns with "
        "table_deg, accel_x_g and accel_y_g), raw or with the model's drift subtracted: a list "
        "of dicts with azimuth_deg (of the FOG axis at table 0°, [0, 360)), pitch_deg, "
        "roll_deg, horizontal_rate_dph, start_s, end_s and the four positions' mean gyro_dph. "
        "Positions are found from table_deg (within tolerance_deg, settle_s after arriving, "
        "held at least min_dwell_s), as northfind finds them.");
  m.def("allan_deviation", &allan_deviation, py::arg("rate"), py::arg("dt_s") = 1.0,
        py::arg("points_per_decade") = 0,
        "Overlapping Allan deviation of a rate signal sampled every dt_s seconds (IEEE Std 952; "
        "allantools' oadev with data_type='freq'): (tau_s, adev, m), adev in the rate's unit, m "
        "the samples per cluster. points_per_decade=0 gives every octave (m = 1, 2, 4, ...).");
  m.def("noise_terms", &noise_terms, py::arg("rate"), py::arg("dt_s") = 1.0,
        "Datasheet noise terms of a gyro rate in °/h from its Allan deviation: angle random "
        "walk (°/√h), bias instability (°/h), rate random walk (°/h/√h), and the tau each was "
        "read at (s).");
}

}  // namespace fogdrift::python
