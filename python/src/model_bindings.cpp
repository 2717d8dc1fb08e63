// Recordings and compensation models for Python (fogdrift.Model, fogdrift.read_recording): a
// recording is a mapping from column names to arrays (a dict, or a pandas DataFrame), a model the
// C++ CompensationModel with its JSON file (docs/python.md).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_load_option_table.hpp"
#include "fogdrift/model/model_set.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

py::dict hyperparameters(const CompensationModel& m) {
  py::dict out;
  for (const auto& [name, value] : m.provenance.hyperparameters) out[py::str(name)] = value;
  return out;
}

}  // namespace

void bind_model(py::module_& m) {
  m.def(
      "read_recording",
      [](const std::filesystem::path& path) { return to_dict(read_recording(path)); },
      py::arg("path"),
      "A recording CSV (docs/formats.md) as a dict of column name → float64 array; thermometers "
      "the unit lacks are left out. Errors name the file, line and column.");
  m.def(
      "write_recording",
      [](const std::filesystem::path& path, const py::object& columns) {
        write_recording(path, to_recording(columns, path.string(), true));
      },
      py::arg("path"), py::arg("columns"),
      "Writes a mapping of columns (dict or DataFrame) as a recording CSV, atomically; columns "
      "fogdrift does not know are written after its own, as they are.");

  m.def(
      "model_load_options", [] { return describe_options(model_load_option_table()); },
      "The keywords of Model.load and Model.from_json (allow_edited, allow_old_format), one dict "
      "each: the descriptions every command's --allow-edited and --allow-old-format come from "
      "(docs/options.md).");
  py::class_<CompensationModel>(m, "Model",
                                "A compensation model: features, scalers, regressor, novelty "
                                "guard and provenance, as `fogdrift train` writes it.")
      .def_static(
          "load",
          [](const std::filesystem::path& path, const std::optional<std::string>& target,
             const py::kwargs& kwargs) {
            ModelLoadOptions load;
            apply_keywords(model_load_option_table(), load, kwargs, "Model.load",
                           {"path", "target"});
            return choose_model(load_model_set(path, load), target, "target");
          },
          py::arg("path"), py::kw_only(), py::arg("target") = py::none(),
          "Reads and checks a model file (its checksum too, unless allow_edited); a file of "
          "format version 1 or 2, which has no checksum, only with allow_old_format. Of a model "
          "with several axes (fogdrift train --targets), target names the one to load, e.g. "
          "'gyro_y_dph'.")
      .def_static(
          "from_json",
          [](const std::string& text, const py::kwargs& kwargs) {
            ModelLoadOptions load;
            apply_keywords(model_load_option_table(), load, kwargs, "Model.from_json", {"text"});
            return compensation_model_from_json(text, "(text)", load);
          },
          py::arg("text"), "A model from a model file's text, checked as Model.load checks a file.")
      .def(
          "to_json", [](const CompensationModel& self) { return to_json(self); },
          "The model file's text, byte for byte what save() writes.")
      .def(
          "save",
          [](const CompensationModel& self, const std::filesystem::path& path) {
            save(self, path);
          },
          py::arg("path"), "Writes the model file atomically.")
      .def_property_readonly("method",
                             [](const CompensationModel& self) { return self.provenance.method; })
      .def_property_readonly(
          "target", [](const CompensationModel& self) { return self.dataset.target_column; },
          "The column the model compensates: gyro_dph, another gyro axis (gyro_NAME_dph), an "
          "accelerometer (accel_NAME_g) or a scale-factor channel (sf_NAME_ppm).")
      .def_property_readonly("feature_names",
                             [](const CompensationModel& self) { return self.feature_names; })
      .def_property_readonly("hyperparameters", &hyperparameters)
      .def_property_readonly("fitness",
                             [](const CompensationModel& self) { return self.provenance.fitness; })
      .def_property_readonly(
          "fitness_value",
          [](const CompensationModel& self) { return self.provenance.fitness_value; })
      .def_property_readonly(
          "training_rows",
          [](const CompensationModel& self) { return self.provenance.training_rows; })
      .def_property_readonly("training_files",
                             [](const CompensationModel& self) {
                               py::list out;
                               for (const auto& f : self.provenance.files)
                                 out.append(py::make_tuple(f.path, f.sha256));
                               return out;
                             })
      .def(
          "predict",
          [](const CompensationModel& self, const py::object& recording, bool guarded) {
            const Recording r = to_recording(recording, "(recording)");
            RecordingPrediction p;
            {
              py::gil_scoped_release release;
              p = self.predict(r, guarded);
            }
            // Keys in the target's unit: drift_dph for a gyro, drift_g, drift_ppm (target.hpp).
            const std::string unit(target_of(self.dataset.target_column).unit());
            py::dict out;
            out[py::str("drift_" + unit)] = to_array(std::move(p.drift_dph));
            out[py::str("model_drift_" + unit)] = to_array(std::move(p.model_drift_dph));
            out["novelty"] = to_array(std::move(p.novelty));
            out["guard_weight"] = to_array(std::move(p.weight));
            return out;
          },
          py::arg("recording"), py::arg("guarded") = true,
          "Drift at every sample of a recording (a path, or a mapping of columns), °/h: "
          "drift_dph (what to subtract), model_drift_dph (before the guard), novelty and "
          "guard_weight, each a float64 array; as `fogdrift compensate` computes them. A model "
          "of another target names the drifts in its unit: drift_g for an accelerometer, "
          "drift_ppm for a scale-factor channel.")
      .def(
          "compensate",
          [](const CompensationModel& self, const py::object& recording, bool guarded) {
            // The gyro the model compensates: gyro_dph, or another axis (Model.target).
            const Recording r = with_target(
                to_recording(recording, "(recording)", self.dataset.target_column != "gyro_dph"),
                self.dataset.target_column);
            std::vector<double> out;
            {
              py::gil_scoped_release release;
              out = self.predict_dph(r, guarded);
              for (std::size_t i = 0; i < out.size(); ++i) out[i] = r.gyro_dph[i] - out[i];
            }
            return to_array(std::move(out));
          },
          py::arg("recording"), py::arg("guarded") = true,
          "gyro − drift_dph: the compensated gyro of a recording, °/h (the channel the model "
          "compensates, Model.target, in its unit).")
      // Pickled as its file's text: a model crosses to another process (a Dask worker)
      // unchanged and checked again on arrival.
      .def(py::pickle([](const CompensationModel& self) { return to_json(self); },
                      [](const std::string& text) {
                        return compensation_model_from_json(text, "(pickle)", {false});
                      }))
      .def("__repr__", [](const CompensationModel& self) {
        return "<fogdrift.Model " + self.provenance.method + ", " + std::to_string(self.inputs()) +
               " features, " + std::to_string(self.provenance.training_rows) + " training rows>";
      });
}

}  // namespace fogdrift::python
