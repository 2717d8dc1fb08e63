// Values between Octave/MATLAB and the library (mx_convert.hpp).
#include "mx_convert.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"

namespace fogdrift::matlab {
namespace {

std::string class_of(const mxArray* a) {
  return mxGetClassName(a);
}

bool is_real_double(const mxArray* a) {
  return mxIsDouble(a) && !mxIsComplex(a);
}

/// A JSON key as a struct field name: letters, digits and '_', starting with a letter, at most
/// 63 characters (MATLAB's namelengthmax).
std::string field_name(const std::string& key) {
  std::string out;
  for (const char c : key) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "x" + out;
  if (out.size() > 63) out.resize(63);
  return out;
}

MxPtr scalar_struct(const std::vector<std::string>& names) {
  std::vector<const char*> p;
  for (const auto& n : names) p.push_back(n.c_str());
  return MxPtr(mxCreateStructMatrix(1, 1, static_cast<int>(p.size()), p.data()));
}

}  // namespace

const mxArray* Args::at(std::size_t i, const std::string& what) const {
  if (i >= values.size())
    throw InputError(what, 0, 0, fmt::format("argument {} is missing", i + 1));
  return values[i];
}

std::string text_of(const mxArray* a, const std::string& what) {
  if (!mxIsChar(a) || (mxGetM(a) > 1))
    throw InputError(what, 0, 0, fmt::format("must be text (a char row), not {}", class_of(a)));
  char* s = mxArrayToString(a);
  std::string out = s ? s : "";
  mxFree(s);
  return out;
}

double scalar_of(const mxArray* a, const std::string& what) {
  if (!is_real_double(a) || mxIsSparse(a) || mxGetNumberOfElements(a) != 1)
    throw InputError(what, 0, 0,
                     fmt::format("must be a real double scalar, not a {}×{} {}", mxGetM(a),
                                 mxGetN(a), class_of(a)));
  return mxGetScalar(a);
}

std::vector<double> vector_of(const mxArray* a, const std::string& what) {
  if (!is_real_double(a) || mxIsSparse(a) || (mxGetM(a) != 1 && mxGetN(a) != 1 && !mxIsEmpty(a)))
    throw InputError(what, 0, 0,
                     fmt::format("must be a real double vector, not a {}×{} {}{}", mxGetM(a),
                                 mxGetN(a), mxIsSparse(a) ? "sparse " : "", class_of(a)));
  const double* p = mxGetPr(a);
  return std::vector<double>(p, p + mxGetNumberOfElements(a));
}

svr::Data data_of(const mxArray* y, const mxArray* x) {
  if (!is_real_double(y) || mxIsSparse(y) || mxGetN(y) != 1)
    throw InputError("label vector", 0, 0,
                     fmt::format("must be an m×1 real double column, not a {}×{} {}", mxGetM(y),
                                 mxGetN(y), class_of(y)));
  if (!is_real_double(x))
    throw InputError(
        "instance matrix", 0, 0,
        fmt::format("must be a real double matrix (dense or sparse), not {}", class_of(x)));
  const std::size_t m = mxGetM(x), n = mxGetN(x);
  if (m != mxGetM(y))
    throw InputError(
        "instance matrix", 0, 0,
        fmt::format("has {} rows and the label vector {}; give one row per label", m, mxGetM(y)));
  if (m == 0) throw InputError("instance matrix", 0, 0, "has no rows; give at least one sample");
  svr::Data d;
  d.rows = m;
  d.cols = n;
  d.y.assign(mxGetPr(y), mxGetPr(y) + m);
  d.x.assign(m * n, 0.0);
  const double* v = mxGetPr(x);
  if (mxIsSparse(x)) {
    const mwIndex* ir = mxGetIr(x);
    const mwIndex* jc = mxGetJc(x);
    for (std::size_t j = 0; j < n; ++j)
      for (mwIndex k = jc[j]; k < jc[j + 1]; ++k) d.x[ir[k] * n + j] = v[k];
  } else {
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < m; ++i) d.x[i * n + j] = v[j * m + i];  // column-major in
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (!std::isfinite(d.y[i]))
      throw InputError("label vector", i + 1, 0, "is not a finite number; drop or fill the sample");
    for (std::size_t j = 0; j < n; ++j)
      if (!std::isfinite(d.x[i * n + j]))
        throw InputError("instance matrix", i + 1, j + 1,
                         "is not a finite number; drop or fill the sample");
  }
  return d;
}

std::vector<std::pair<std::string, const mxArray*>> name_values(const Args& args,
                                                                std::size_t first) {
  std::vector<std::pair<std::string, const mxArray*>> out;
  if (args.size() > first && (args.size() - first) % 2 != 0)
    throw InputError("arguments", 0, 0,
                     "options come in name–value pairs ('c_max', 1000, …); the last name has no "
                     "value");
  std::set<std::string> seen;
  for (std::size_t i = first; i + 1 < args.size(); i += 2) {
    if (!mxIsChar(args.values[i]))
      throw InputError("arguments", 0, 0,
                       fmt::format("argument {} must be an option's name (text), not {}", i + 2,
                                   class_of(args.values[i])));
    std::string name = text_of(args.values[i], "option name");
    if (!seen.insert(name).second) throw OptionError(name, "is given twice; give it once");
    out.emplace_back(std::move(name), args.values[i + 1]);
  }
  return out;
}

std::string option_text(const OptionSpec& spec, const mxArray* v) {
  const auto wrong = [&](const std::string& takes) {
    return OptionError(spec.keyword, fmt::format("must be {}, not a {}×{} {}", takes, mxGetM(v),
                                                 mxGetN(v), class_of(v)));
  };
  const bool scalar_number = (is_real_double(v) || mxIsNumeric(v)) && !mxIsComplex(v) &&
                             !mxIsSparse(v) && mxGetNumberOfElements(v) == 1;
  switch (spec.type) {
    case OptionType::whole:
    case OptionType::number: {
      if (!scalar_number) throw wrong("a number");
      const double x = mxGetScalar(v);
      if (spec.type == OptionType::whole && (x != std::floor(x) || !(x >= 0)))
        throw OptionError(spec.keyword, fmt::format("must be a whole number ≥ 0 (got {})",
                                                    option_number_text(x)));
      return spec.type == OptionType::whole ? fmt::format("{:.0f}", x) : option_number_text(x);
    }
    case OptionType::seconds_or_auto:
    case OptionType::whole_or_auto:
      if (mxIsChar(v)) return text_of(v, spec.keyword);
      if (!scalar_number) throw wrong("'auto' or a number");
      return option_number_text(mxGetScalar(v));
    case OptionType::on_off:
      if (mxIsLogical(v) && mxGetNumberOfElements(v) == 1)
        return mxIsLogicalScalarTrue(v) ? "true" : "false";
      if (scalar_number && (mxGetScalar(v) == 0 || mxGetScalar(v) == 1))
        return mxGetScalar(v) == 1 ? "true" : "false";
      throw wrong("true or false");
    case OptionType::choice:
    case OptionType::text:
      if (!mxIsChar(v)) throw wrong("text");
      return text_of(v, spec.keyword);
    case OptionType::names: {
      if (mxIsChar(v)) return text_of(v, spec.keyword);
      if (!mxIsCell(v)) throw wrong("text or a cell array of text");
      std::string out;
      for (std::size_t i = 0; i < mxGetNumberOfElements(v); ++i) {
        const mxArray* c = mxGetCell(v, i);
        if (!c || !mxIsChar(c)) throw wrong("a cell array of text");
        out += (i ? "," : "") + text_of(c, spec.keyword);
      }
      return out;
    }
    case OptionType::numbers:
      if (mxIsChar(v)) return text_of(v, spec.keyword);
      if (!is_real_double(v) || mxIsSparse(v) || mxIsEmpty(v)) throw wrong("a vector of numbers");
      return option_numbers_text(vector_of(v, spec.keyword));
    case OptionType::number_or_none:
      if (mxIsEmpty(v)) return "none";
      if (mxIsChar(v)) return text_of(v, spec.keyword);
      if (!scalar_number) throw wrong("[] or a number");
      return option_number_text(mxGetScalar(v));
    case OptionType::assignments: {
      if (mxIsChar(v)) return text_of(v, spec.keyword);
      if (!mxIsCell(v)) throw wrong("'NAME=VALUE' or a cell array of them");
      std::string out;
      for (std::size_t i = 0; i < mxGetNumberOfElements(v); ++i) {
        const mxArray* c = mxGetCell(v, i);
        if (!c || !mxIsChar(c)) throw wrong("a cell array of 'NAME=VALUE'");
        out +=
            (i ? std::string(1, kAssignmentSeparator) : std::string()) + text_of(c, spec.keyword);
      }
      return out;
    }
  }
  throw wrong("a value");
}

void unknown_option(const std::string& function, const std::string& name,
                    const std::vector<std::string>& own, const std::vector<OptionSpec>& specs) {
  std::string known;
  for (const auto& k : own) known += (known.empty() ? "" : ", ") + k;
  for (const auto& s : specs) known += (known.empty() ? "" : ", ") + s.keyword;
  throw OptionError(name,
                    fmt::format("is not an option of {}; its options are {}", function, known));
}

Recording recording_of(const mxArray* s, const std::string& source) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    throw InputError(source, 0, 0,
                     fmt::format("a recording must be a scalar struct of columns (a table: "
                                 "table2struct(T, 'ToScalar', true)), not a {}×{} {}",
                                 mxGetM(s), mxGetN(s), class_of(s)));
  Recording r;
  r.source = source;
  const auto read = [&](const std::string& name, std::vector<double>& into) {
    const mxArray* f = mxGetField(s, 0, name.c_str());
    into = vector_of(f, source + ": column " + name);
  };
  for (const auto* names : {&required_columns(), &optional_columns()})
    for (const std::string& name : *names)
      if (mxGetField(s, 0, name.c_str())) read(name, *known_column(r, name, true));
  for (const std::string& name : required_columns())
    if (!mxGetField(s, 0, name.c_str()))
      throw InputError(source, 0, 0, "missing required column " + name);
  for (int k = 0; k < mxGetNumberOfFields(s); ++k) {
    const std::string name = mxGetFieldNameByNumber(s, k);
    const mxArray* values = mxGetField(s, 0, name.c_str());
    if (r.has_column(name) || !further_thermometer_name(name) || !values) continue;
    ExtraColumn c{name, {}};
    for (double x : vector_of(values, source + ": column " + name))
      c.cells.push_back(csv::format_number(x));
    if (c.cells.size() != r.size())
      throw InputError(
          source, 0, 0,
          fmt::format("column {}: has {} values, time_s {}", name, c.cells.size(), r.size()));
    r.extra.push_back(std::move(c));
  }
  validate(r);
  return r;
}

MxPtr column(const std::vector<double>& values) {
  MxPtr a(mxCreateDoubleMatrix(values.size(), 1, mxREAL));
  std::copy(values.begin(), values.end(), mxGetPr(a.get()));
  return a;
}

MxPtr text(const std::string& s) {
  return MxPtr(mxCreateString(s.c_str()));
}

MxPtr to_struct(const Recording& r) {
  std::vector<std::string> names;
  std::vector<MxPtr> values;
  for (const auto* list : {&required_columns(), &optional_columns()})
    for (const std::string& name : *list)
      if (const std::vector<double>* c = known_column(r, name); c && !c->empty()) {
        names.push_back(name);
        values.push_back(column(*c));
      }
  for (const ExtraColumn& c : r.extra) {
    names.push_back(field_name(c.name));
    try {
      values.push_back(column(r.numeric_column(c.name)));
    } catch (const InputError&) {
      MxPtr cells(mxCreateCellMatrix(c.cells.size(), 1));
      for (std::size_t i = 0; i < c.cells.size(); ++i)
        mxSetCell(cells.get(), i, mxCreateString(c.cells[i].c_str()));
      values.push_back(std::move(cells));
    }
  }
  MxPtr s = scalar_struct(names);
  for (std::size_t k = 0; k < names.size(); ++k)
    mxSetField(s.get(), 0, names[k].c_str(), values[k].release());
  return s;
}

MxPtr to_mx(const nlohmann::ordered_json& j) {
  using J = nlohmann::ordered_json;
  switch (j.type()) {
    case J::value_t::null:
      return MxPtr(mxCreateDoubleMatrix(0, 0, mxREAL));
    case J::value_t::boolean:
      return MxPtr(mxCreateLogicalScalar(j.get<bool>()));
    case J::value_t::number_integer:
    case J::value_t::number_unsigned:
    case J::value_t::number_float:
      return MxPtr(mxCreateDoubleScalar(j.get<double>()));
    case J::value_t::string:
      return text(j.get<std::string>());
    case J::value_t::object: {
      std::vector<std::string> names;
      for (const auto& [k, v] : j.items()) names.push_back(field_name(k));
      MxPtr s = scalar_struct(names);
      std::size_t k = 0;
      for (const auto& item : j.items())
        mxSetField(s.get(), 0, names[k++].c_str(), to_mx(item.value()).release());
      return s;
    }
    case J::value_t::array: {
      bool numbers = true, booleans = true, objects = true;
      for (const auto& v : j) {
        numbers = numbers && (v.is_number() || v.is_null());
        booleans = booleans && v.is_boolean();
        objects = objects && v.is_object() && v.size() == j.front().size();
      }
      if (objects && !j.empty())
        for (const auto& v : j) {
          auto a = v.items().begin();
          for (const auto& [key, value] : j.front().items()) {
            objects = objects && a.key() == key;
            ++a;
          }
        }
      if (j.empty()) return MxPtr(mxCreateDoubleMatrix(0, 1, mxREAL));
      if (numbers) {
        MxPtr a(mxCreateDoubleMatrix(j.size(), 1, mxREAL));
        double* p = mxGetPr(a.get());
        for (const auto& v : j)
          *p++ = v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
        return a;
      }
      if (booleans) {
        MxPtr a(mxCreateLogicalMatrix(j.size(), 1));
        mxLogical* p = mxGetLogicals(a.get());
        for (const auto& v : j) *p++ = v.get<bool>();
        return a;
      }
      if (objects) {
        std::vector<std::string> names;
        std::vector<const char*> p;
        for (const auto& [k, v] : j.front().items()) names.push_back(field_name(k));
        for (const auto& n : names) p.push_back(n.c_str());
        MxPtr s(mxCreateStructMatrix(j.size(), 1, static_cast<int>(p.size()), p.data()));
        for (std::size_t i = 0; i < j.size(); ++i) {
          std::size_t k = 0;
          for (const auto& item : j[i].items())
            mxSetField(s.get(), i, names[k++].c_str(), to_mx(item.value()).release());
        }
        return s;
      }
      MxPtr c(mxCreateCellMatrix(j.size(), 1));
      for (std::size_t i = 0; i < j.size(); ++i) mxSetCell(c.get(), i, to_mx(j[i]).release());
      return c;
    }
    default:
      return MxPtr(mxCreateDoubleMatrix(0, 0, mxREAL));
  }
}

}  // namespace fogdrift::matlab
