#include "fault_options.hpp"

#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/stream/fault_option_table.hpp"
#include "fogdrift/stream/stream_option_table.hpp"

namespace fogdrift::app {
namespace {

/// The options of `table` (an O with a `faults` policy) to run `model` with: the fault policy
/// fitted to the model, then `flags` applied, the policy checked; errors named by the flags.
template <class O>
O fitted(const OptionFlags& flags, const OptionTable<O>& table, const CompensationModel& model) {
  O options;
  options.faults = fault_policy_of(model);
  flags.apply(table, options);
  try {
    validate(options.faults);
  } catch (const OptionError& e) {
    throw flags.named(e);
  }
  return options;
}

}  // namespace

std::shared_ptr<OptionFlags> add_export_options(CLI::App* cmd) {
  const auto& table = export_option_table();
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table),
                                       "Header and sensor faults (docs/firmware.md)");
}

ExportOptions export_options(const OptionFlags& flags, const CompensationModel& model) {
  return fitted(flags, export_option_table(), model);
}

std::shared_ptr<OptionFlags> add_stream_options(CLI::App* cmd) {
  const auto& table = stream_option_table();
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table),
                                       "Guard and sensor faults (docs/compensation.md)");
}

StreamOptions stream_options(const OptionFlags& flags, const CompensationModel& model) {
  return fitted(flags, stream_option_table(), model);
}

}  // namespace fogdrift::app
