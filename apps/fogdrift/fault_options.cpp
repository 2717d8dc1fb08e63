#include "fault_options.hpp"

#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/stream/fault_option_table.hpp"
#include "fogdrift/stream/stream_option_table.hpp"

namespace fogdrift::app {
namespace {

/// `options` with `flags` applied and its fault policy checked, errors named by the flags.
template <class O>
O applied(const OptionFlags& flags, const OptionTable<O>& table, O options,
          FaultPolicy& (*faults)(O&)) {
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
  ExportOptions options;
  options.faults = fault_policy_of(model);  // the timings fitted to the model, then the flags
  return applied<ExportOptions>(flags, export_option_table(), options,
                                [](ExportOptions& o) -> FaultPolicy& { return o.faults; });
}

std::shared_ptr<OptionFlags> add_stream_options(CLI::App* cmd) {
  const auto& table = stream_option_table();
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table),
                                       "Guard and sensor faults (docs/compensation.md)");
}

StreamOptions stream_options(const OptionFlags& flags, const CompensationModel& model) {
  StreamOptions options;
  options.faults = fault_policy_of(model);  // the timings fitted to the model, then the flags
  return applied<StreamOptions>(flags, stream_option_table(), options,
                                [](StreamOptions& o) -> FaultPolicy& { return o.faults; });
}

}  // namespace fogdrift::app
