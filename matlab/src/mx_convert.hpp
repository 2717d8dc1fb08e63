// Values between Octave/MATLAB and the library, for the one MEX file fogdrift_mex
// (docs/matlab.md): text, numbers, matrices as regression data, recordings as structs of
// columns, name–value options by the library's option tables, and JSON as structs.
#pragma once

#include <mex.h>

#include <cstddef>
#include <memory>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/svr/kernel.hpp"

namespace fogdrift::matlab {

/// An array the MEX file owns until it hands it to the host.
struct MxDeleter {
  void operator()(mxArray* a) const noexcept { mxDestroyArray(a); }
};
using MxPtr = std::unique_ptr<mxArray, MxDeleter>;

/// The arguments of a call after the command's name, with the function's name for messages.
struct Args {
  std::string function;  ///< e.g. "fogdrift.train"
  std::span<const mxArray* const> values;

  std::size_t size() const { return values.size(); }
  /// Argument i (0-based); InputError naming the function and `what` when it is missing.
  const mxArray* at(std::size_t i, const std::string& what) const;
};

/// A char row vector's text; InputError(function, "WHAT must be text") otherwise.
std::string text_of(const mxArray* a, const std::string& what);
/// A real double scalar; InputError otherwise.
double scalar_of(const mxArray* a, const std::string& what);
/// A real double vector (row or column, dense) as values; InputError otherwise.
std::vector<double> vector_of(const mxArray* a, const std::string& what);

/// Regression data from an m × 1 target vector and an m × n matrix of features (dense or sparse
/// double, as LIBSVM's svmtrain takes them); InputError naming the argument for another shape,
/// class or a value that is not finite.
svr::Data data_of(const mxArray* y, const mxArray* x);

/// The name–value pairs from argument `first` on: each name a char row, given once.
std::vector<std::pair<std::string, const mxArray*>> name_values(const Args& args,
                                                                std::size_t first);

/// The text the option table parses for a value given to `spec`'s option: a number for whole and
/// number options, 'auto' or a number, true/false (logical or 0/1), a char row for choices and
/// text, a char row or cell of them for names, a numeric vector for numbers. OptionError naming
/// the keyword and what it takes otherwise.
std::string option_text(const OptionSpec& spec, const mxArray* value);

/// Sets every pair whose name is an option of `table` on `o`, in the table's order; returns the
/// pairs the table does not have, for the function's own names.
template <class O>
std::vector<std::pair<std::string, const mxArray*>> apply_options(
    const OptionTable<O>& table, O& o,
    const std::vector<std::pair<std::string, const mxArray*>>& pairs) {
  std::vector<std::pair<std::string, const mxArray*>> rest;
  for (const auto& p : pairs)
    if (!find_option(table, p.first)) rest.push_back(p);
  for (const auto& option : table)
    for (const auto& p : pairs)
      if (p.first == option.spec.keyword) option.set(o, option_text(option.spec, p.second));
  return rest;
}

/// f(), with an OptionError it throws named in the keywords of `specs` (option_word), as the
/// name–value names are.
template <class F>
auto in_keywords_of(const std::vector<OptionSpec>& specs, F&& f) {
  return in_option_words_of(specs, false, std::forward<F>(f));
}

/// OptionError for a name no option of the function has, listing the names it takes.
[[noreturn]] void unknown_option(const std::string& function, const std::string& name,
                                 const std::vector<std::string>& own,
                                 const std::vector<OptionSpec>& specs);

/// A recording from a scalar struct whose fields are columns (column or row vectors of equal
/// length): fogdrift's columns and further thermometers are read, other fields ignored; then
/// checked as a file is (recording.hpp), errors naming `source`.
Recording recording_of(const mxArray* s, const std::string& source);
/// A recording as a scalar struct of column vectors: fogdrift's columns present, then the
/// further columns (numbers, or cells of text).
MxPtr to_struct(const Recording& r);

MxPtr column(const std::vector<double>& values);
MxPtr text(const std::string& s);
/// A JSON value: object → scalar struct (keys made valid field names), array of numbers → column
/// (null → NaN), of booleans → logical column, of objects with the same keys → struct column,
/// other arrays → cell column; text → char row; null → [].
MxPtr to_mx(const nlohmann::ordered_json& j);

}  // namespace fogdrift::matlab
