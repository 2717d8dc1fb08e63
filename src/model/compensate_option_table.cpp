// `compensate`'s options (compensate_option_table.hpp). Defaults are CompensateOptions'.
#include "fogdrift/model/compensate_option_table.hpp"

#include "fogdrift/model/guard_option.hpp"

namespace fogdrift {
namespace {

OptionTable<CompensateOptions> make_compensate_table() {
  OptionTable<CompensateOptions> t;
  t.push_back(guarded_option<CompensateOptions>());
  return t;
}

}  // namespace

const OptionTable<CompensateOptions>& compensate_option_table() {
  static const OptionTable<CompensateOptions> table = make_compensate_table();
  return table;
}

}  // namespace fogdrift
