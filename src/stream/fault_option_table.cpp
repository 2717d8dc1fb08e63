// The fault policy's options (fault_option_table.hpp). Defaults are FaultPolicy's; validate()
// (stream_faults.hpp) checks the ranges and names "faults.FIELD", which each option lists.
#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<FaultPolicy> make_fault_table() {
  using O = FaultPolicy;
  OptionTable<O> t;
  t.push_back(number_option<O>(
      {"temp_min_degc",
       "--temp-min-degc",
       {},
       "°C",
       "< {temp_max_degc}",
       "Thermometer readings below this are faults",
       {"faults.temp_min_degc"}},
      [](auto& o) -> auto& { return o.temp_min_degc; }));
  t.push_back(number_option<O>(
      {"temp_max_degc",
       "--temp-max-degc",
       {},
       "°C",
       "> {temp_min_degc}",
       "Thermometer readings above this are faults",
       {"faults.temp_max_degc"}},
      [](auto& o) -> auto& { return o.temp_max_degc; }));
  t.push_back(number_option<O>(
      {"gyro_limit_dph",
       "--gyro-limit-dph",
       {},
       "°/h",
       above(0),
       "Gyro readings beyond ± this are faults",
       {"faults.gyro_limit_dph"}},
      [](auto& o) -> auto& { return o.gyro_limit_dph; }));
  t.push_back(number_option<O>(
      {"bridge_s",
       "--bridge-s",
       {},
       "s",
       at_least(0),
       "Thermometer outages and time gaps up to this long are bridged with substituted samples; "
       "time going back further is a restart (default: fitted to the model's sampling)",
       {"faults.bridge_s"}},
      [](auto& o) -> auto& { return o.bridge_s; }));
  t.push_back(number_option<O>(
      {"hold_s",
       "--hold-s",
       {},
       "s",
       "≥ {bridge_s}",
       "Beyond {bridge_s} the drift is held at its last good value up to this long, then the "
       "correction stops (default: fitted to the model's rate window)",
       {"faults.hold_s"}},
      [](auto& o) -> auto& { return o.hold_s; }));
  t.push_back(number_option<O>(
      {"stuck_s",
       "--stuck-s",
       {},
       "s",
       at_least(0),
       "A thermometer unchanged this long while another moved by {stuck_delta_degc} is stuck "
       "(0: no check; default: fitted to the model's rate window)",
       {"faults.stuck_s"}},
      [](auto& o) -> auto& { return o.stuck_s; }));
  t.push_back(number_option<O>(
      {"stuck_delta_degc",
       "--stuck-delta-degc",
       {},
       "°C",
       above(0),
       "How far another thermometer must move for {stuck_s} to apply",
       {"faults.stuck_delta_degc"}},
      [](auto& o) -> auto& { return o.stuck_delta_degc; }));
  t.push_back(number_option<O>(
      {"temp_jump_degc",
       "--temp-jump-degc",
       {},
       "°C",
       at_least(0),
       "A thermometer reading this far from its last good value continued along its rate is a "
       "jump, bridged like a bad reading; one lasting beyond {bridge_s} is a real step (0: no "
       "check)",
       {"faults.temp_jump_degc"}},
      [](auto& o) -> auto& { return o.temp_jump_degc; }));
  return t;
}

}  // namespace

const OptionTable<FaultPolicy>& fault_option_table() {
  static const OptionTable<FaultPolicy> table = make_fault_table();
  return table;
}

}  // namespace fogdrift
