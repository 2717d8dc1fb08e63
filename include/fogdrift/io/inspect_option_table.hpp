// `inspect`'s options, described once (option_table.hpp, docs/options.md): `fogdrift
// inspect`'s flags. The file or campaign and --json the command declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/inspect.hpp"

namespace fogdrift {

const OptionTable<InspectOptions>& inspect_option_table();

}  // namespace fogdrift
