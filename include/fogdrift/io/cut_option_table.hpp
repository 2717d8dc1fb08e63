// How `fogdrift campaign` cuts one long log into recordings (cut.hpp), described once
// (option_table.hpp, docs/options.md). The campaign's own flags (the test recordings, the input
// rate, the references) its command declares.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/cut.hpp"

namespace fogdrift {

const OptionTable<CutOptions>& cut_option_table();

}  // namespace fogdrift
