// fogdrift.denoise and fogdrift.features: wavelet denoising of one signal and the model inputs of
// a recording (signal/denoise.hpp, features.hpp; docs/python.md).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/signal/denoise.hpp"
#include "fogdrift/signal/denoise_option_table.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

using Array = py::array_t<double, py::array::forcecast>;

// A 1-D float64 array from any sequence of numbers; `name` is the argument's name in errors.
Array one_dimensional(const py::object& values, const char* name) {
  const auto a = Array::ensure(values);
  if (!a || a.ndim() != 1) throw OptionError(name, "must be a 1-D array of numbers");
  return a;
}

py::object denoise(const py::object& data, bool summary, const py::kwargs& options) {
  const Array x = one_dimensional(data, "data");
  signal::DenoiseOptions o;
  apply_keywords(signal::denoise_option_table(), o, options, "denoise", {"data", "summary"});
  signal::DenoiseResult r;
  {
    py::gil_scoped_release release;
    r = signal::denoise({x.data(), static_cast<std::size_t>(x.shape(0))}, o);
  }
  py::array_t<double> out = to_array(std::move(r.signal));
  if (!summary) return out;
  py::dict s;
  s["level"] = r.summary.level;
  s["noise_sigma"] = r.summary.noise_sigma;
  py::list bands;
  for (const signal::BandSummary& b : r.summary.bands) {
    py::dict d;
    d["level"] = b.level;
    d["size"] = b.size;
    d["threshold"] = b.threshold;
    d["kept"] = b.kept;
    bands.append(d);
  }
  s["bands"] = bands;
  return py::make_tuple(out, s);
}

py::dict features(const py::object& recording, const std::optional<std::string>& spec,
                  const CompensationModel* model, const std::string& differentiator,
                  const py::object& rate_window_s, const py::object& block_s) {
  const Recording r = to_recording(recording, "(recording)");
  FeatureSpec s;
  FeatureOptions o;
  if (model != nullptr) {
    if (spec)
      throw OptionError("spec",
                        "give a feature spec or a model (whose features are used), "
                        "not both");
    const bool auto_window =
        py::isinstance<py::str>(rate_window_s) && rate_window_s.cast<std::string>() == "auto";
    const bool auto_block =
        py::isinstance<py::str>(block_s) && block_s.cast<std::string>() == "auto";
    if (differentiator != "centred" || !auto_window || !auto_block)
      throw OptionError("model",
                        "its own preprocessing is used; leave differentiator, "
                        "rate_window_s and block_s at their defaults");
    s = model->dataset.features;
    o = model->dataset.preprocessing;
  } else {
    s = spec && *spec != "auto" ? FeatureSpec::parse(*spec)
                                : recommended_feature_spec(thermometers_of(r));
    o.rates.causality = signal::parse_causality(differentiator);
    o = preprocessing_for(sample_interval_s(r), r.size(), o);
    if (const auto w = seconds_or_auto(rate_window_s, "rate_window_s")) o.rates.window_s = *w;
    if (const auto b = seconds_or_auto(block_s, "block_s")) o.block.block_s = *b;
  }
  FeatureTable t;
  {
    py::gil_scoped_release release;
    t = in_keywords([&] { return compute_features(r, s, o); });
  }
  py::dict out;
  out["names"] = t.names;
  const std::size_t columns = t.names.size();
  out["x"] = to_array(std::move(t.x), t.rows, columns);
  out["time_s"] = to_array(std::move(t.time_s));
  out["block"] = t.block;
  out["spec"] = s.to_string();
  out["rate_window_s"] = o.rates.window_s;
  out["block_s"] = o.block.block_s;
  return out;
}

}  // namespace

void bind_signal(py::module_& m) {
  m.def(
      "denoise_options",
      [] {
        const auto& table = signal::denoise_option_table();
        return describe_options(specs_of(table), defaults_of(table));
      },
      "The options of fogdrift.denoise, one dict each (keyword, type, default, unit, doc, flag): "
      "the same descriptions `fogdrift denoise`'s flags come from (docs/options.md).");
  m.def("denoise", &denoise, py::arg("data"), py::kw_only(), py::arg("summary") = false,
        "Wavelet-denoises a 1-D signal (docs/signal.md): the same result as `fogdrift denoise`, "
        "with its options as keywords (fogdrift.denoise_options()). Returns the denoised float64 "
        "array, or with summary=True (array, dict) with the level, the noise sigma and each "
        "band's threshold and coefficients kept.");
  m.def("features", &features, py::arg("recording"), py::arg("spec") = py::none(), py::kw_only(),
        py::arg("model") = nullptr, py::arg("differentiator") = "centred",
        py::arg("rate_window_s") = "auto", py::arg("block_s") = "auto",
        "The model inputs of a recording (a path or a mapping of columns), one row per block: "
        "a dict with 'names' (each with its unit), 'x' (rows × features float64), 'time_s' "
        "(block centres), 'block' (samples per block), and the 'spec', 'rate_window_s' and "
        "'block_s' used. spec: a feature spec ('T,dT,grad', docs/signal.md §4) or None for the "
        "inputs train chooses over the unit's thermometers (T,dT,grad,dT@300 over three); with "
        "model=, the model's own features and "
        "preprocessing, the rows it predicts from.");
}

}  // namespace fogdrift::python
