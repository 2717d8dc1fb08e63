// The novelty guard's switch (guard.hpp), described once (option_table.hpp, docs/options.md):
// every command and function that applies a model takes it from here, `--no-guard` on the
// command line and `guarded=False` in Python and Octave, in `compensate`'s, `stream`'s,
// `evaluate`'s and `northfind`'s tables.
#pragma once

#include "fogdrift/base/option_table.hpp"

namespace fogdrift {

/// The switch on `O::guarded` (a bool, on by default).
template <class O>
Option<O> guarded_option() {
  return on_off_option<O>(
      {"guarded",
       "--no-guard",
       {},
       "",
       "",
       "Reduce the model's correction where its inputs are novel to it "
       "(docs/field.md); off, the full correction everywhere",
       {}},
      [](auto& o) -> auto& { return o.guarded; });
}

}  // namespace fogdrift
