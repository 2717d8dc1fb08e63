#include "fault_options.hpp"

namespace fogdrift::app {

void add_fault_options(CLI::App* cmd, FaultPolicy& p) {
  const char* group = "Sensor faults (docs/compensation.md)";
  cmd->add_option("--temp-min-degc", p.temp_min_degc,
                  "Thermometer readings below this are faults, °C")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--temp-max-degc", p.temp_max_degc,
                  "Thermometer readings above this are faults, °C")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--gyro-limit-dph", p.gyro_limit_dph,
                  "Gyro readings beyond ± this are faults, °/h")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--bridge-s", p.bridge_s,
                  "Thermometer outages and time gaps up to this long are bridged with substituted "
                  "samples; time going back further is a restart, s")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--hold-s", p.hold_s,
                  "Beyond --bridge-s the drift is held at its last good value up to this long, "
                  "then the correction stops, s")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--stuck-s", p.stuck_s,
                  "A thermometer unchanged this long while another moved by --stuck-delta-degc is "
                  "stuck, s (0: no check)")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--stuck-delta-degc", p.stuck_delta_degc,
                  "How far another thermometer must move for --stuck-s to apply, °C")
      ->capture_default_str()
      ->group(group);
  cmd->add_option("--temp-jump-degc", p.temp_jump_degc,
                  "A thermometer reading this far from its last good value continued along its "
                  "rate is a jump, bridged like a bad reading; one lasting beyond --bridge-s is a "
                  "real step, °C (0: no check)")
      ->capture_default_str()
      ->group(group);
}

void fault_timings_from_model(const CLI::App& cmd, const CompensationModel& model,
                              FaultPolicy& policy) {
  const FeatureOptions& f = model.dataset.preprocessing;
  if (f.sample_interval_s == 0) return;  // a model file that does not record it: the defaults
  const FaultPolicy fitted =
      fault_policy_for(f.sample_interval_s,
                       static_cast<double>(signal::window_samples(f.rates, f.sample_interval_s)) *
                           f.sample_interval_s);
  if (cmd.count("--bridge-s") == 0) policy.bridge_s = fitted.bridge_s;
  if (cmd.count("--hold-s") == 0) policy.hold_s = fitted.hold_s;
  if (cmd.count("--stuck-s") == 0) policy.stuck_s = fitted.stuck_s;
}

const FlagTable& fault_flags() {
  static const FlagTable kFlags = {{"faults.temp_min_degc", "--temp-min-degc"},
                                   {"faults.temp_max_degc", "--temp-max-degc"},
                                   {"faults.gyro_limit_dph", "--gyro-limit-dph"},
                                   {"faults.bridge_s", "--bridge-s"},
                                   {"faults.hold_s", "--hold-s"},
                                   {"faults.stuck_s", "--stuck-s"},
                                   {"faults.stuck_delta_degc", "--stuck-delta-degc"},
                                   {"faults.temp_jump_degc", "--temp-jump-degc"}};
  return kFlags;
}

}  // namespace fogdrift::app
