// Option descriptions as Python keywords (option_keywords.hpp).
#include "option_keywords.hpp"

#include <fmt/format.h>

#include <cmath>

namespace py = pybind11;

namespace fogdrift::python {
namespace {

bool is_bool(const py::handle& v) {
  return PyBool_Check(v.ptr()) || py::isinstance(v, py::module_::import("numpy").attr("bool_"));
}

/// An int, or any integer type (NumPy's) that is not a bool.
bool is_whole(const py::handle& v) {
  return !is_bool(v) && PyIndex_Check(v.ptr());
}

bool is_number(const py::handle& v) {
  return !is_bool(v) && (PyFloat_Check(v.ptr()) || PyIndex_Check(v.ptr()) ||
                         py::isinstance(v, py::module_::import("numpy").attr("floating")));
}

std::string whole_text(const py::handle& v) {
  return py::str(py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()))).cast<std::string>();
}

std::string number_text(const py::handle& v) {
  return option_number_text(py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>());
}

/// What values of `type` Python takes, for the TypeError.
std::string_view python_what(OptionType type) {
  switch (type) {
    case OptionType::whole:
      return "an int";
    case OptionType::number:
      return "a number";
    case OptionType::seconds_or_auto:
      return "'auto' (or None) or a number of seconds";
    case OptionType::whole_or_auto:
      return "'auto' (or None) or an int";
    case OptionType::choice:
    case OptionType::text:
      return "a str";
    case OptionType::names:
      return "a str or a list of str";
    case OptionType::numbers:
      return "a list of numbers or a str";
    case OptionType::on_off:
      return "a bool";
    case OptionType::number_or_none:
      return "None or a number";
    case OptionType::assignments:
      return "a dict or a list of 'NAME=VALUE' str";
  }
  return "?";
}

}  // namespace

std::string keyword_text(const OptionSpec& spec, const py::handle& value,
                         const std::string& function) {
  const bool text = py::isinstance<py::str>(value);
  // None is Python's word for "let the library choose" (pywt.wavedec's level=None).
  if (value.is_none() &&
      (spec.type == OptionType::seconds_or_auto || spec.type == OptionType::whole_or_auto))
    return "auto";
  if (value.is_none() && spec.type == OptionType::number_or_none) return "none";
  switch (spec.type) {
    case OptionType::whole:
      if (is_whole(value)) return whole_text(value);
      break;
    case OptionType::number:
      if (is_number(value)) return number_text(value);
      break;
    case OptionType::seconds_or_auto:
      if (text) return value.cast<std::string>();
      if (is_number(value)) return number_text(value);
      break;
    case OptionType::whole_or_auto:
      if (text) return value.cast<std::string>();
      if (is_whole(value)) return whole_text(value);
      break;
    case OptionType::choice:
    case OptionType::text:
      if (text) return value.cast<std::string>();
      break;
    case OptionType::names:
      if (text) return value.cast<std::string>();
      if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        std::string joined;
        bool all_text = true;
        for (const py::handle item : value) {
          all_text = all_text && py::isinstance<py::str>(item);
          if (all_text) joined += (joined.empty() ? "" : ",") + item.cast<std::string>();
        }
        if (all_text) return joined;
      }
      break;
    case OptionType::numbers:
      if (text) return value.cast<std::string>();
      if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
          py::isinstance(value, py::module_::import("numpy").attr("ndarray"))) {
        std::string joined;
        bool all_numbers = true;
        for (const py::handle item : value) {
          all_numbers = all_numbers && is_number(item);
          if (all_numbers) joined += (joined.empty() ? "" : ",") + number_text(item);
        }
        if (all_numbers) return joined;
      }
      break;
    case OptionType::on_off:
      if (is_bool(value)) return value.cast<bool>() ? "true" : "false";
      break;
    case OptionType::number_or_none:
      if (text) return value.cast<std::string>();
      if (is_number(value)) return number_text(value);
      break;
    case OptionType::assignments: {
      // {name: value} or ["name=value", ...]: one item each, whatever commas it holds.
      std::vector<std::pair<std::string, std::string>> items;
      bool fits = true;
      if (py::isinstance<py::dict>(value)) {
        for (const auto& [k, v] : value.cast<py::dict>()) {
          fits = fits && py::isinstance<py::str>(k) && (py::isinstance<py::str>(v) || is_number(v));
          if (fits)
            items.emplace_back(k.cast<std::string>(),
                               py::isinstance<py::str>(v) ? v.cast<std::string>() : number_text(v));
        }
        if (fits) return option_assignments_text(items);
      } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        std::string joined;
        for (const py::handle item : value) {
          fits = fits && py::isinstance<py::str>(item);
          if (fits)
            joined += (joined.empty() ? "" : std::string(1, kAssignmentSeparator)) +
                      item.cast<std::string>();
        }
        if (fits) return joined;
      }
      break;
    }
  }
  std::string shown = py::repr(value).cast<std::string>();
  if (shown.size() > 40) shown = shown.substr(0, 37) + "...";
  throw py::type_error(fmt::format(
      "{}(): {} must be {}, not {} ({})", function, spec.keyword, python_what(spec.type),
      py::type::of(value).attr("__name__").cast<std::string>(), shown));
}

py::list describe_options(const std::vector<OptionSpec>& specs,
                          const std::vector<std::string>& defaults) {
  py::list out;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const OptionSpec& s = specs[i];
    py::dict d;
    d["keyword"] = s.keyword;
    d["type"] = std::string(to_string(s.type));
    d["default"] = defaults[i];
    d["unit"] = s.unit;
    d["doc"] = option_help(s, specs, false);
    d["flag"] = s.flag;
    out.append(d);
  }
  return out;
}

}  // namespace fogdrift::python
