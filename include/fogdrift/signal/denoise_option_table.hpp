// Wavelet denoising's options, described once (option_table.hpp, docs/options.md): the flags of
// `fogdrift denoise` and the keywords of Python's fogdrift.denoise come from this table. What
// only decides how a front end runs (the file, its column and the output; the array and
// summary=) each front end declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/signal/denoise.hpp"

namespace fogdrift::signal {

const OptionTable<DenoiseOptions>& denoise_option_table();

}  // namespace fogdrift::signal
