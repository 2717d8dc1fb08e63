// fogdrift.StreamingCompensator: compensation one sample at a time, as the instrument's
// processor runs it and `fogdrift stream` prints it (compensator.hpp, docs/python.md).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/stream/stream_option_table.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

// The compensator with what it needs to check its samples: which thermometers the model reads.
struct Stream {
  StreamingCompensator compensator;
  bool reads_acc1, reads_acc2;
  std::string gyro_column;  ///< the column the model compensates (Model.target)
  /// The further thermometers' columns (temp_NAME_degc, FeatureSpec::further), and one sample's
  /// readings of them.
  std::vector<std::string> further_columns;
  std::vector<double> further;

  Stream(const CompensationModel& model, double dt_s, const StreamOptions& options)
      : compensator(model, dt_s, options),
        reads_acc1(model.dataset.features.reads(Thermometer::acc1)),
        reads_acc2(model.dataset.features.reads(Thermometer::acc2)),
        gyro_column(model.dataset.target_column) {
    for (const std::string& name : model.dataset.features.further)
      further_columns.push_back(thermometer_column(name));
    further.resize(further_columns.size());
  }

  // A thermometer the model does not read may be absent (0, as `fogdrift stream` takes it).
  double thermometer(const std::optional<double>& value, bool read, const char* name) const {
    if (value) return *value;
    if (read) throw OptionError(name, "the model reads this thermometer; give its reading");
    return 0.0;
  }
};

// The keywords come from `stream`'s one description (stream_option_table.hpp), as `fogdrift
// stream`'s flags do: the guard and the fault policy.
std::unique_ptr<Stream> make_stream(const CompensationModel& model, double dt_s,
                                    const py::kwargs& kwargs) {
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw OptionError("dt_s", "must be a finite number of seconds > 0");
  const auto& table = stream_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  StreamOptions o;
  o.faults = fault_policy_of(model);  // timings fitted to the model, as `fogdrift stream` runs it
  for (const auto& [key, value] : kwargs) {
    const auto name = key.cast<std::string>();
    const Option<StreamOptions>* option = find_option(table, name);
    if (option == nullptr) {
      std::string all = "model, dt_s";
      for (const auto& spec : specs) all += ", " + spec.keyword;
      throw py::type_error(fmt::format(
          "StreamingCompensator() got an unexpected keyword argument '{}'; its keywords are {}",
          name, all));
    }
    option->set(o, keyword_text(option->spec, value, "StreamingCompensator"));
  }
  // "faults.bridge_s" is the keyword bridge_s here.
  in_keywords_of(specs, [&] { validate(o.faults); });
  // Streamed, a model trained on centred rates sees causal ones, noisier than those it learned:
  // a tuned SVR's drift then departs from its batch drift by about the drift's own STD
  // (docs/python.md, step 6).
  if (model.dataset.preprocessing.rates.causality != signal::Causality::causal)
    warn(
        "the model was trained with centred temperature rates; streamed, it sees causal ones and "
        "its drift differs from Model.predict's. For the instrument, train with "
        "differentiator='causal'");
  try {
    return std::make_unique<Stream>(model, dt_s, o);
  } catch (const OptionError& e) {  // an interval the model cannot run at: the keyword dt_s
    if (e.option() == "rate") throw OptionError("dt_s", e.message());
    throw;
  }
}

py::tuple update(Stream& s, double time_s, double gyro_dph, double temp_fog_degc,
                 const std::optional<double>& temp_acc1_degc,
                 const std::optional<double>& temp_acc2_degc, const py::kwargs& further) {
  // Further thermometers by their column names (docs/logs.md, "More thermometers").
  for (const auto& [key, value] : further) {
    const auto name = key.cast<std::string>();
    const auto at = std::find(s.further_columns.begin(), s.further_columns.end(), name);
    if (at == s.further_columns.end())
      throw py::type_error(fmt::format(
          "update() got an unexpected keyword argument '{}'; the model's further thermometers "
          "are: {}",
          name,
          s.further_columns.empty() ? "none"
                                    : fmt::format("{}", fmt::join(s.further_columns, ", "))));
    try {
      s.further[static_cast<std::size_t>(at - s.further_columns.begin())] = value.cast<double>();
    } catch (const py::cast_error&) {
      throw py::type_error(
          fmt::format("StreamingCompensator.update(): {} must be a number, not {}", name,
                      py::str(value.get_type().attr("__name__")).cast<std::string>()));
    }
  }
  for (const std::string& name : s.further_columns)
    if (!further.contains(name.c_str()))
      throw OptionError(name, "the model reads this thermometer; give its reading");
  const StreamOutput out = s.compensator.update(
      {time_s, gyro_dph, temp_fog_degc,
       s.thermometer(temp_acc1_degc, s.reads_acc1, "temp_acc1_degc"),
       s.thermometer(temp_acc2_degc, s.reads_acc2, "temp_acc2_degc"), s.further});
  return py::make_tuple(out.drift_dph, out.gyro_comp_dph, out.flags);
}

// One column of a mapping as float64, or an empty array when absent and not `required`.
py::array_t<double, py::array::forcecast> column(const py::object& columns, const char* name,
                                                 bool required, std::size_t n) {
  using Array = py::array_t<double, py::array::forcecast>;
  if (!columns.attr("__contains__")(name).cast<bool>()) {
    if (required) throw InputError("(recording)", 0, 0, std::string("missing column ") + name);
    return Array(0);
  }
  auto a = Array::ensure(columns[py::str(name)]);
  if (!a || a.ndim() != 1)
    throw InputError("(recording)", 0, 0, std::string("column ") + name + ": must be 1-D");
  if (n != 0 && static_cast<std::size_t>(a.shape(0)) != n)
    throw InputError("(recording)", 0, 0,
                     std::string("column ") + name + ": has " + std::to_string(a.shape(0)) +
                         " values, time_s " + std::to_string(n));
  return a;
}

// A recording's samples as the stream sees them: a file is read and checked as for training; a
// mapping's columns are taken as they are, NaNs and all, since the fault policy handles them.
py::dict run(Stream& s, const py::object& recording) {
  // time, gyro, fog, acc1, acc2, then the further thermometers in the model's order.
  std::vector<py::array_t<double, py::array::forcecast>> c(5 + s.further_columns.size());
  if (py::isinstance<py::str>(recording) || py::hasattr(recording, "__fspath__")) {
    const Recording r = with_target(
        to_recording(recording, "(recording)", s.gyro_column != "gyro_dph"), s.gyro_column);
    const std::vector<double>* v[5] = {&r.time_s, &r.gyro_dph, &r.temp_fog_degc, &r.temp_acc1_degc,
                                       &r.temp_acc2_degc};
    for (std::size_t k = 0; k < 5; ++k) c[k] = copy_to_array(*v[k]);
    for (std::size_t k = 0; k < s.further_columns.size(); ++k) {
      if (!r.has_column(s.further_columns[k]))
        throw InputError(
            r.source, 1, 0,
            fmt::format("missing column {}, which the model reads", s.further_columns[k]));
      c[5 + k] = copy_to_array(r.numeric_column(s.further_columns[k]));
    }
  } else {
    c[0] = column(recording, "time_s", true, 0);
    const auto n = static_cast<std::size_t>(c[0].shape(0));
    c[1] = column(recording, s.gyro_column.c_str(), true, n);
    c[2] = column(recording, "temp_fog_degc", true, n);
    c[3] = column(recording, "temp_acc1_degc", s.reads_acc1, n);
    c[4] = column(recording, "temp_acc2_degc", s.reads_acc2, n);
    for (std::size_t k = 0; k < s.further_columns.size(); ++k)
      c[5 + k] = column(recording, s.further_columns[k].c_str(), true, n);
  }
  const auto n = static_cast<std::size_t>(c[0].shape(0));
  if (s.reads_acc1 && c[3].shape(0) == 0)
    throw InputError("(recording)", 0, 0, "missing column temp_acc1_degc, which the model reads");
  if (s.reads_acc2 && c[4].shape(0) == 0)
    throw InputError("(recording)", 0, 0, "missing column temp_acc2_degc, which the model reads");
  const bool has_acc1 = c[3].shape(0) != 0, has_acc2 = c[4].shape(0) != 0;
  std::vector<double> drift(n), comp(n), novelty(n), weight(n);
  py::array_t<std::uint32_t> flags(static_cast<py::ssize_t>(n));
  std::uint32_t* f = flags.mutable_data();
  const double *t = c[0].data(), *g = c[1].data(), *fog = c[2].data(), *a1 = c[3].data(),
               *a2 = c[4].data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < s.further.size(); ++k) s.further[k] = c[5 + k].data()[i];
      const StreamOutput out = s.compensator.update(
          {t[i], g[i], fog[i], has_acc1 ? a1[i] : 0.0, has_acc2 ? a2[i] : 0.0, s.further});
      drift[i] = out.drift_dph;
      comp[i] = out.gyro_comp_dph;
      novelty[i] = s.compensator.novelty();
      weight[i] = s.compensator.weight();
      f[i] = out.flags;
    }
  }
  py::dict d;
  d["drift_dph"] = to_array(std::move(drift));
  d["gyro_comp_dph"] = to_array(std::move(comp));
  d["novelty"] = to_array(std::move(novelty));
  d["guard_weight"] = to_array(std::move(weight));
  d["fault_flags"] = flags;
  return d;
}

}  // namespace

void bind_stream(py::module_& m) {
  m.def(
      "stream_options", [] { return describe_options(stream_option_table()); },
      "The keywords of StreamingCompensator (the guard's switch and the fault policy), one dict "
      "each (keyword, type, default, "
      "unit, doc, flag), from the one description `fogdrift stream`'s flags come from "
      "(docs/options.md). The defaults of bridge_s, hold_s and stuck_s are a model's unless it "
      "records its sample interval, when they are fitted to it.");
  py::class_<Stream>(m, "StreamingCompensator",
                     "A Model run one sample at a time, causally, as the instrument's processor "
                     "runs it (`fogdrift stream`): rates from the causal differentiator, the "
                     "novelty guard, and the fault policy (docs/field.md) that keeps the output "
                     "finite through bad samples, flagging each.")
      .def(py::init(&make_stream), py::arg("model"), py::arg("dt_s"), py::keep_alive<1, 2>(),
           "dt_s: the logger's fixed sample interval, s. The other keywords, guarded (the "
           "novelty guard, default True) and the fault policy's, are `fogdrift stream`'s "
           "options, under their keywords (fogdrift.stream_options(), docs/options.md); the "
           "timings not given (bridge_s, hold_s, stuck_s) are fitted to the model, as `fogdrift "
           "stream` fits them.")
      .def("update", &update, py::arg("time_s"), py::arg("gyro_dph"), py::arg("temp_fog_degc"),
           py::arg("temp_acc1_degc") = py::none(), py::arg("temp_acc2_degc") = py::none(),
           "One sample in, (drift_dph, gyro_comp_dph, fault_flags) out; a NaN reading is a "
           "fault, flagged, not an error. A thermometer the model does not read may be left "
           "out; a further one the model reads is given by its column name, e.g. "
           "temp_case_degc=21.5 (docs/logs.md, \"More thermometers\").")
      .def("run", &run, py::arg("recording"),
           "Every sample of a recording (a path or a mapping of columns) through update(), "
           "continuing from the state before: a dict of arrays drift_dph, gyro_comp_dph, "
           "novelty, guard_weight and fault_flags (uint32), the columns `fogdrift stream` adds.")
      .def(
          "reset", [](Stream& s) { s.compensator.reset(); }, "Starts again, as at power-on.")
      .def_property_readonly("novelty", [](const Stream& s) { return s.compensator.novelty(); })
      .def_property_readonly("weight", [](const Stream& s) { return s.compensator.weight(); })
      .def_static(
          "describe_flags", [](std::uint32_t flags) { return fault::describe(flags); },
          py::arg("flags"), "The names of the faults in a fault_flags value.");
}

}  // namespace fogdrift::python
