#include "fault_options.hpp"

#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift::app {

std::shared_ptr<OptionFlags> add_fault_options(CLI::App* cmd) {
  const auto& table = fault_option_table();
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table),
                                       "Sensor faults (docs/compensation.md)");
}

FaultPolicy fault_policy(const OptionFlags& flags, const CompensationModel& model) {
  FaultPolicy policy = fault_policy_of(model);
  flags.apply(fault_option_table(), policy);
  try {
    validate(policy);
  } catch (const OptionError& e) {
    throw flags.named(e);
  }
  return policy;
}

}  // namespace fogdrift::app
