// How a model file is loaded, described once (option_table.hpp, docs/options.md): the
// `--allow-edited` and `--allow-old-format` flags of every command that reads a model, and the
// keywords of Octave's fogdrift.Model.load. Python's Model.load and Model.from_json take the
// same keywords as pybind11 arguments of their signatures.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/model/model.hpp"

namespace fogdrift {

const OptionTable<ModelLoadOptions>& model_load_option_table();

}  // namespace fogdrift
