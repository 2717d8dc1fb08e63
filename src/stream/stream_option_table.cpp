// `stream`'s options (stream_option_table.hpp): the guard, then the fault policy's table lifted
// onto StreamOptions::faults. Defaults are StreamOptions'.
#include "fogdrift/stream/stream_option_table.hpp"

#include "fogdrift/model/guard_option.hpp"
#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<StreamOptions> make_stream_table() {
  OptionTable<StreamOptions> t;
  t.push_back(guarded_option<StreamOptions>());
  for (Option<StreamOptions>& o : lifted<StreamOptions>(
           fault_option_table(), [](auto& s) -> auto& { return s.faults; }))
    t.push_back(std::move(o));
  return t;
}

}  // namespace

const OptionTable<StreamOptions>& stream_option_table() {
  static const OptionTable<StreamOptions> table = make_stream_table();
  return table;
}

}  // namespace fogdrift
