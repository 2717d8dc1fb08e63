// fogdrift.simulate: the built-in north-finding-system simulator and its protocols, as
// `fogdrift simulate` runs them, with the options under the library's field names
// (sim/scenarios.hpp, docs/python.md).
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

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
    const auto& table = sim::calibration_option_table();
    sim::CalibrationOptions o;
    in_keywords_of(specs_of(table), [&] {
      apply_keywords(table, o, options, "simulate", {},
                     "the " + scenario + " simulation's options");
    });
    o.seed = seed;
    py::gil_scoped_release release;
    c = in_keywords_of(specs_of(table), [&] { return sim::simulate_calibration(unit, o); });
  } else if (scenario == "northfind" || scenario == "stable") {
    const auto& table = sim::northfind_option_table();
    sim::NorthfindOptions o =
        scenario == "stable" ? sim::stable_defaults() : sim::NorthfindOptions{};
    in_keywords_of(specs_of(table), [&] {
      apply_keywords(table, o, options, "simulate", {},
                     "the " + scenario + " simulation's options");
    });
    o.seed = seed;
    py::gil_scoped_release release;
    c = in_keywords_of(specs_of(table), [&] {
      return scenario == "stable" ? sim::simulate_stable(unit, o)
                                  : sim::simulate_northfind(unit, o);
    });
  } else {
    throw OptionError("scenario",
                      "must be 'calibration', 'northfind' or 'stable' (got '" + scenario + "')");
  }
  if (out) {
    // A campaign replaced over the instrument file it was made from would lose that file.
    if (!instrument.is_none() && !py::isinstance<py::dict>(instrument))
      check_output_not_among(*out, {instrument.cast<std::filesystem::path>()}, "out");
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
  m.def(
      "simulate_options",
      [](const std::string& scenario) {
        if (scenario == "calibration") {
          const auto& t = sim::calibration_option_table();
          return describe_options(specs_of(t), defaults_of(t));
        }
        if (scenario == "northfind" || scenario == "stable") {
          const auto& t = sim::northfind_option_table();
          return describe_options(specs_of(t),
                                  defaults_of(t, scenario == "stable" ? sim::stable_defaults()
                                                                      : sim::NorthfindOptions{}));
        }
        throw OptionError(
            "scenario", "must be 'calibration', 'northfind' or 'stable' (got '" + scenario + "')");
      },
      py::arg("scenario") = "calibration",
      "The options of fogdrift.simulate(scenario), one dict each (keyword, type, default, unit, "
      "doc, flag), from the one description fogdrift keeps of them (docs/options.md).");
  m.def("simulate", &simulate, py::arg("scenario") = "calibration", py::kw_only(),
        py::arg("out") = py::none(), py::arg("seed") = 1, py::arg("instrument") = py::none(),
        py::arg("replace") = false,
        "Simulates a north-finding system in a thermal chamber (docs/simulator.md), as "
        "`fogdrift simulate SCENARIO` does: scenario 'calibration' (paper §4.1), 'northfind' "
        "(§4.2) or 'stable'. Further keywords are the scenario's options, as "
        "fogdrift.simulate_options(scenario) describes them (docs/options.md). instrument: a dict "
        "of parameters or a JSON file "
        "(`fogdrift simulate --print-instrument`). With out=, also writes the campaign folder "
        "(replace=True replaces it). Returns the manifest as a dict (as campaign.json) with "
        "'data': one dict of column arrays per recording, in the manifest's order.");
}

}  // namespace fogdrift::python
