// Conversions shared by the bindings (convert.hpp).
#include "convert.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <memory>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/train/train_option_table.hpp"

namespace py = pybind11;

namespace fogdrift::python {

namespace {

// An array of `shape` and `strides` (bytes) over `values`' buffer, which it takes over.
py::array_t<double> owning(std::vector<double>&& values, std::vector<py::ssize_t> shape,
                           std::vector<py::ssize_t> strides) {
  auto* owned = new std::vector<double>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>(std::move(shape), std::move(strides), owned->data(), owner);
}

}  // namespace

py::array_t<double> to_array(std::vector<double>&& values, std::size_t rows, std::size_t columns) {
  const auto c = static_cast<py::ssize_t>(columns), item = py::ssize_t{sizeof(double)};
  return owning(std::move(values), {static_cast<py::ssize_t>(rows), c}, {c * item, item});
}

py::array_t<double> to_array(std::vector<double>&& values) {
  const auto n = static_cast<py::ssize_t>(values.size());
  return owning(std::move(values), {n}, {py::ssize_t{sizeof(double)}});
}

py::array_t<double> copy_to_array(const std::vector<double>& values) {
  return to_array(std::vector<double>(values));
}

py::dict to_dict(const Recording& r) {
  py::dict out;
  for (const auto* names : {&required_columns(), &optional_columns()})
    for (const std::string& name : *names)
      if (const std::vector<double>* column = known_column(r, name);
          column != nullptr && !column->empty())
        out[py::str(name)] = copy_to_array(*column);
  for (const ExtraColumn& c : r.extra) {
    try {
      out[py::str(c.name)] = to_array(r.numeric_column(c.name));
    } catch (const InputError&) {
      out[py::str(c.name)] = py::cast(c.cells);  // text: kept as it was written
    }
  }
  return out;
}

Recording to_recording(const py::object& columns, const std::string& source, bool keep_others) {
  if (py::isinstance<py::str>(columns) || py::hasattr(columns, "__fspath__"))
    return read_recording(py::cast<std::filesystem::path>(columns));
  // A mapping has keys; an array (a DataFrame's .to_numpy()) has none and would be asked
  // elementwise whether it contains a name.
  if (!py::hasattr(columns, "keys") || !py::hasattr(columns, "__getitem__")) {
    const std::string type = py::str(py::type::of(columns).attr("__qualname__"));
    throw InputError(source, 0, 0,
                     "a recording must be a path or a mapping of column names to arrays (a dict "
                     "or a pandas DataFrame), not " +
                         type +
                         (py::hasattr(columns, "shape")
                              ? "; an array has no column names: pass the DataFrame itself, or "
                                "a dict such as {'time_s': t, 'gyro_dph': g, ...}"
                              : ""));
  }
  Recording r;
  r.source = source;
  for (const auto* names : {&required_columns(), &optional_columns()})
    for (const std::string& name : *names) {
      if (!columns.attr("__contains__")(name).cast<bool>()) continue;
      const auto values = py::array_t<double, py::array::forcecast>::ensure(columns[py::str(name)]);
      if (!values || values.ndim() != 1)
        throw InputError(source, 0, 0, "column " + name + ": must be a 1-D array of numbers");
      std::vector<double>* column = known_column(r, name, true);
      column->assign(values.data(), values.data() + values.shape(0));
    }
  for (const std::string& name : required_columns())
    if (!columns.attr("__contains__")(name).cast<bool>())
      throw InputError(source, 0, 0, "missing required column " + name);
  if (r.time_s.empty())
    throw InputError(source, 0, 0, "has no rows: a recording needs at least one sample");
  // Further thermometers always (a model may read them, docs/logs.md "More thermometers"); the
  // other columns when asked.
  for (const py::handle key : columns.attr("keys")()) {
    const auto name = py::str(key).cast<std::string>();
    if (r.has_column(name) || !(keep_others || further_thermometer_name(name))) continue;
    const py::object values = columns[key];
    ExtraColumn c{name, {}};
    if (const auto numbers = py::array_t<double, py::array::forcecast>::ensure(values);
        numbers && numbers.ndim() == 1) {
      for (py::ssize_t i = 0; i < numbers.shape(0); ++i)
        c.cells.push_back(csv::format_number(numbers.at(i)));
    } else {
      PyErr_Clear();
      for (const py::handle cell : values) c.cells.push_back(py::str(cell).cast<std::string>());
    }
    if (c.cells.size() != r.size())
      throw InputError(source, 0, 0,
                       "column " + name + ": has " + std::to_string(c.cells.size()) +
                           " values, time_s " + std::to_string(r.size()));
    r.extra.push_back(std::move(c));
  }
  validate(r);
  return r;
}

const std::vector<OptionSpec>& train_specs() {
  static const std::vector<OptionSpec> specs = specs_of(train_option_table());
  return specs;
}

std::string keyword_of(const std::string& field) {
  return option_word(train_specs(), field, false);
}

std::optional<double> seconds_or_auto(const py::object& value, const char* name) {
  if (py::isinstance<py::str>(value)) {
    if (value.cast<std::string>() == "auto") return std::nullopt;
    throw OptionError(name, "must be 'auto' or a number of seconds > 0 (got '" +
                                value.cast<std::string>() + "')");
  }
  const double v = value.cast<double>();
  if (!(v > 0)) throw OptionError(name, "must be 'auto' or a number of seconds > 0");
  return v;
}

py::object from_json(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

bool is_held_campaign(const py::object& given) {
  return py::isinstance<py::dict>(given) && given.cast<py::dict>().contains("recordings");
}

HeldCampaign held_campaign(const py::object& given) {
  py::dict manifest;
  for (const auto& [key, value] : given.cast<py::dict>())
    if (key.cast<std::string>() != "data") manifest[key] = value;
  if (!given.contains("data"))
    throw InputError("campaign", 0, 0,
                     "data: required in a campaign given as a dict (one recording per entry of "
                     "recordings, as fogdrift.simulate returns it)");
  const auto text = py::module_::import("json").attr("dumps")(manifest).cast<std::string>();
  HeldCampaign h{campaign_from_json(text, "campaign"), {}};
  std::size_t i = 0;
  for (const py::handle recording : given["data"]) {
    const std::string name =
        i < h.campaign.recordings.size()
            ? "campaign data[" + std::to_string(i) + "] (" + h.campaign.recordings[i].file + ")"
            : "campaign data[" + std::to_string(i) + "]";
    h.recordings.push_back(to_recording(py::reinterpret_borrow<py::object>(recording), name, true));
    ++i;
  }
  return h;
}

}  // namespace fogdrift::python
