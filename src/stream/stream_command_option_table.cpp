// `fogdrift stream`'s options (stream_command_option_table.hpp): the rate and --strict, then
// stream_option_table() lifted onto StreamCommandOptions::stream. Defaults are
// StreamCommandOptions'.
#include "fogdrift/stream/stream_command_option_table.hpp"

#include "fogdrift/stream/stream_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<StreamCommandOptions> make_stream_command_table() {
  using O = StreamCommandOptions;
  OptionTable<O> t;
  t.push_back(number_or_none_option<O>(
      {"rate_hz",
       "--rate-hz",
       {},
       "Hz",
       above(0).at_most(kMaxStreamRateHz),
       "The logger's fixed sample rate (none: the model's own): the model's rate or a whole "
       "multiple of it, to 1 %. Steps more than 10 % off its interval are flagged off_interval",
       {"rate"}},
      [](auto& o) -> auto& { return o.rate_hz; }));
  t.push_back(on_off_option<O>(
      {"strict",
       "--strict",
       {},
       "",
       "",
       "Stop at the first faulty sample or torn line, naming its line and column, instead of "
       "compensating through it",
       {}},
      [](auto& o) -> auto& { return o.strict; }));
  for (Option<O>& o : lifted<O>(
           stream_option_table(), [](auto& c) -> auto& { return c.stream; }))
    t.push_back(std::move(o));
  return t;
}

}  // namespace

const OptionTable<StreamCommandOptions>& stream_command_option_table() {
  static const OptionTable<StreamCommandOptions> table = make_stream_command_table();
  return table;
}

}  // namespace fogdrift
