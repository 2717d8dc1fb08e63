// `compensate`'s options, described once (option_table.hpp, docs/options.md): `fogdrift
// compensate`'s flags and the keywords of Octave's Model.predict and Model.compensate come from
// this table. The model, the input and the output each front end names itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/model/compensate_file.hpp"

namespace fogdrift {

/// The guard's switch (guard_option.hpp).
const OptionTable<CompensateOptions>& compensate_option_table();

}  // namespace fogdrift
