// `fogdrift stream`'s options, described once (option_table.hpp, docs/options.md): how the
// command reads its CSV (the logger's rate, strictness), then the streaming compensator's own
// (stream_option_table.hpp). Python's StreamingCompensator takes only the latter: it is given
// each sample's interval, and raises on what it cannot take.
#pragma once

#include <optional>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/stream/compensator.hpp"

namespace fogdrift {

struct StreamCommandOptions {
  /// The logger's fixed sample rate, Hz; none: the model's own.
  std::optional<double> rate_hz;
  /// Stop at the first faulty sample or torn line instead of compensating through it.
  bool strict = false;
  StreamOptions stream;
};

const OptionTable<StreamCommandOptions>& stream_command_option_table();

}  // namespace fogdrift
