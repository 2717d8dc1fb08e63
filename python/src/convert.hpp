// Conversions between the library's types and Python's, shared by the bindings: arrays without a
// second copy, recordings as mappings of columns, JSON text as Python objects.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/recording.hpp"

namespace fogdrift::python {

/// A 1-D float64 array that takes over `values` (no copy): the array owns the vector's buffer.
pybind11::array_t<double> to_array(std::vector<double>&& values);

/// A rows × columns float64 array over a row-major vector, taking it over.
pybind11::array_t<double> to_array(std::vector<double>&& values, std::size_t rows,
                                   std::size_t columns);

/// A 1-D float64 array copied from `values`.
pybind11::array_t<double> copy_to_array(const std::vector<double>& values);

/// Every column of the recording, in fogdrift's column order, then the others it carries (as
/// float64 arrays when every cell is a number, else lists of str); thermometers the unit lacks
/// are left out.
pybind11::dict to_dict(const Recording& recording);

/// A recording from a path, or from any mapping of column names to 1-D sequences (dict,
/// DataFrame): the known columns are read, the others kept as text (numbers in shortest
/// round-trip form) when `keep_others` or when they are a further thermometer (temp_NAME_degc),
/// else ignored; then checked as a file would be (recording.hpp), errors naming `source`.
Recording to_recording(const pybind11::object& columns, const std::string& source,
                       bool keep_others = false);

/// The descriptions of fogdrift.train's options (train_option_table.hpp).
const std::vector<OptionSpec>& train_specs();

/// The Python keyword of a library field: the keyword of the option of fogdrift.train that sets
/// it (max_degree for degree, rate_window_s for window_s, rate_degree for poly_order), else the
/// field's own name.
std::string keyword_of(const std::string& field);

/// f(), with an OptionError it throws named in the words of the options `specs` describes: its
/// field by the keyword of the option that sets it (option_word), and the options its message
/// names as {keyword} by their keywords.
template <class F>
auto in_keywords_of(const std::vector<OptionSpec>& specs, F&& f) {
  return in_option_words_of(specs, false, std::forward<F>(f));
}

/// in_keywords_of fogdrift.train's options.
template <class F>
auto in_keywords(F&& f) {
  return in_keywords_of(train_specs(), std::forward<F>(f));
}

/// None for "auto", else a number of seconds > 0; OptionError naming `name` otherwise.
std::optional<double> seconds_or_auto(const pybind11::object& value, const char* name);

/// The Python value of a JSON text (json.loads).
pybind11::object from_json(const std::string& text);

/// A campaign in memory: the manifest's fields (as campaign.json holds them) with "data", one
/// recording (a mapping of columns) per entry of "recordings" (what fogdrift.simulate returns).
struct HeldCampaign {
  Campaign campaign;
  std::vector<Recording> recordings;
};

/// Whether `given` is such a campaign: a dict with "recordings".
bool is_held_campaign(const pybind11::object& given);

/// The campaign a dict holds; InputError naming "campaign" and the entry for what is wrong.
HeldCampaign held_campaign(const pybind11::object& given);

}  // namespace fogdrift::python
