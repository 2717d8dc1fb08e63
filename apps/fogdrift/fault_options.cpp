#include "fault_options.hpp"

#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/stream/fault_option_table.hpp"
#include "fogdrift/stream/stream_command_option_table.hpp"

namespace fogdrift::app {
namespace {

/// The options of `table` to run `model` with: the fault policy (`faults(options)`) fitted to
/// the model, then `flags` applied, the policy checked; errors named by the flags.
template <class O, class Faults>
O fitted(const OptionFlags& flags, const OptionTable<O>& table, const CompensationModel& model,
         Faults faults) {
  O options;
  faults(options) = fault_policy_of(model);
  flags.apply(table, options);
  try {
    validate(faults(options));
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
  return fitted(
      flags, export_option_table(), model, [](auto& o) -> auto& { return o.faults; });
}

std::shared_ptr<OptionFlags> add_stream_options(CLI::App* cmd) {
  const auto& table = stream_command_option_table();
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table),
                                       "Rate, guard and sensor faults (docs/compensation.md)");
}

StreamCommandOptions stream_options(const OptionFlags& flags, const CompensationModel& model) {
  return fitted(
      flags, stream_command_option_table(), model,
      [](auto& o) -> auto& { return o.stream.faults; });
}

}  // namespace fogdrift::app
