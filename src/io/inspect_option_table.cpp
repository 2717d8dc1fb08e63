// `inspect`'s options (inspect_option_table.hpp). Defaults are InspectOptions'.
#include "fogdrift/io/inspect_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<InspectOptions> make_inspect_table() {
  using O = InspectOptions;
  OptionTable<O> t;
  t.push_back(on_off_option<O>(
      {"log",
       "--log",
       {},
       "",
       "",
       "The file may be a log to join (a chamber sheet imported with --partial): summarise it "
       "without the gyro or the FOG thermometer, and with times before power-on",
       {}},
      [](auto& o) -> auto& { return o.log; }));
  return t;
}

}  // namespace

const OptionTable<InspectOptions>& inspect_option_table() {
  static const OptionTable<InspectOptions> table = make_inspect_table();
  return table;
}

}  // namespace fogdrift
