// fogdrift.simulate: the built-in north-finding-system simulator and its protocols, as
// `fogdrift simulate` runs them, with the options under the library's field names
// (sim/scenarios.hpp, docs/python.md).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

// Setters of one scenario's options by field name.
template <typename Options>
using Fields = std::map<std::string, std::function<void(Options&, const py::handle&)>>;

template <typename Options, typename T>
std::function<void(Options&, const py::handle&)> set(T Options::*field) {
  return [field](Options& o, const py::handle& v) { o.*field = v.cast<T>(); };
}

const Fields<sim::CalibrationOptions>& calibration_fields() {
  using O = sim::CalibrationOptions;
  static const Fields<O> f = {
      {"temps_degc", set(&O::temps_degc)},
      {"repetitions", set(&O::repetitions)},
      {"test_repetitions", set(&O::test_repetitions)},
      {"soak_s", set(&O::soak_s)},
      {"powered_s", set(&O::powered_s)},
      {"ramp_s", set(&O::ramp_s)},
      {"chamber_setpoint_sd_degc", set(&O::chamber_setpoint_sd_degc)},
      {"azimuth_deg", set(&O::azimuth_deg)},
      {"latitude_deg", set(&O::latitude_deg)},
      {"output_rate_hz", set(&O::output_rate_hz)},
      {"approaches",
       [](O& o, const py::handle& v) {
         o.approaches.clear();
         if (py::isinstance<py::str>(v))
           o.approaches = sim::approaches_from_string(v.cast<std::string>(), "approaches");
         else
           for (const py::handle a : v)
             o.approaches.push_back(sim::approach_from_string(a.cast<std::string>(), "approaches"));
       }},
      {"warm_off_s", set(&O::warm_off_s)},
      {"ramp_degc_per_min", set(&O::ramp_degc_per_min)},
  };
  return f;
}

const Fields<sim::NorthfindOptions>& northfind_fields() {
  using O = sim::NorthfindOptions;
  static const Fields<O> f = {
      {"temps_degc", set(&O::temps_degc)},
      {"findings", set(&O::findings)},
      {"position_s", set(&O::position_s)},
      {"warmup_s", set(&O::warmup_s)},
      {"approach",
       [](O& o, const py::handle& v) {
         o.approach = sim::approach_from_string(v.cast<std::string>(), "approach");
       }},
      {"soak_s", set(&O::soak_s)},
      {"ramp_degc_per_min", set(&O::ramp_degc_per_min)},
      {"warm_off_s", set(&O::warm_off_s)},
      {"latitude_deg", set(&O::latitude_deg)},
      {"output_rate_hz", set(&O::output_rate_hz)},
  };
  return f;
}

template <typename Options>
void apply(Options& o, const Fields<Options>& fields, const py::kwargs& options,
           const std::string& scenario) {
  for (const auto& [key, value] : options) {
    const auto name = key.template cast<std::string>();
    const auto it = fields.find(name);
    if (it == fields.end()) {
      std::string known;
      for (const auto& [n, f] : fields) known += (known.empty() ? "" : ", ") + n;
      throw OptionError(name,
                        "is not an option of the " + scenario + " simulation (" + known + ")");
    }
    try {
      it->second(o, value);
    } catch (const py::cast_error&) {
      throw OptionError(
          name, "has the wrong type (" + py::str(py::type::of(value)).cast<std::string>() + ")");
    }
  }
}

// None: the default instrument; a dict: its fields (the rest default); else a JSON file's path.
sim::Instrument instrument_of(const py::object& instrument) {
  if (instrument.is_none()) return {};
  if (py::isinstance<py::dict>(instrument)) {
    const auto text = py::module_::import("json").attr("dumps")(instrument).cast<std::string>();
    return sim::instrument_from_json(text, "instrument");
  }
  const auto path = instrument.cast<std::filesystem::path>();
  return sim::instrument_from_json(read_text_file(path), path.string());
}

py::dict simulate(const std::string& scenario, const std::optional<std::filesystem::path>& out,
                  std::uint64_t seed, const py::object& instrument, bool replace,
                  const py::kwargs& options) {
  const sim::Instrument unit = instrument_of(instrument);
  sim::SimulatedCampaign c;
  if (scenario == "calibration") {
    sim::CalibrationOptions o;
    apply(o, calibration_fields(), options, scenario);
    o.seed = seed;
    py::gil_scoped_release release;
    c = sim::simulate_calibration(unit, o);
  } else if (scenario == "northfind" || scenario == "stable") {
    sim::NorthfindOptions o =
        scenario == "stable" ? sim::stable_defaults() : sim::NorthfindOptions{};
    apply(o, northfind_fields(), options, scenario);
    o.seed = seed;
    py::gil_scoped_release release;
    c = scenario == "stable" ? sim::simulate_stable(unit, o) : sim::simulate_northfind(unit, o);
  } else {
    throw OptionError("scenario",
                      "must be 'calibration', 'northfind' or 'stable' (got '" + scenario + "')");
  }
  if (out) {
    py::gil_scoped_release release;
    sim::write_campaign(*out, c, replace);
  }
  py::dict result = from_json(manifest_json(c.campaign)).cast<py::dict>();
  py::list recordings;
  for (const Recording& r : c.recordings) recordings.append(to_dict(r));
  result["data"] = recordings;
  return result;
}

}  // namespace

void bind_sim(py::module_& m) {
  m.def("simulate", &simulate, py::arg("scenario") = "calibration", py::kw_only(),
        py::arg("out") = py::none(), py::arg("seed") = 1, py::arg("instrument") = py::none(),
        py::arg("replace") = false,
        "Simulates a north-finding system in a thermal chamber (docs/simulator.md), as "
        "`fogdrift simulate SCENARIO` does: scenario 'calibration' (paper §4.1), 'northfind' "
        "(§4.2) or 'stable'. Further keywords are the scenario's options under the library's "
        "names: calibration: temps_degc, repetitions, test_repetitions, soak_s, powered_s, "
        "ramp_s, chamber_setpoint_sd_degc, azimuth_deg, latitude_deg, output_rate_hz, "
        "approaches, warm_off_s, ramp_degc_per_min; northfind and stable: temps_degc, findings, "
        "position_s, warmup_s, approach, soak_s, ramp_degc_per_min, warm_off_s, latitude_deg, "
        "output_rate_hz. instrument: a dict of parameters or a JSON file "
        "(`fogdrift simulate --print-instrument`). With out=, also writes the campaign folder "
        "(replace=True replaces it). Returns the manifest as a dict (as campaign.json) with "
        "'data': one dict of column arrays per recording, in the manifest's order.");
}

}  // namespace fogdrift::python
