#include "fogdrift/stream/stream_faults.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

FaultPolicy fault_policy_for(double model_dt_s, double rate_window_s) {
  FaultPolicy p;
  if (!(model_dt_s > 0) || !std::isfinite(model_dt_s)) return p;
  p.bridge_s = std::max(p.bridge_s, 2 * model_dt_s);
  if (rate_window_s > 0 && std::isfinite(rate_window_s))
    p.hold_s = std::max(p.hold_s, 2 * rate_window_s);
  p.hold_s = std::max(p.hold_s, p.bridge_s);
  p.stuck_s = std::max(p.stuck_s, 5 * model_dt_s);
  return p;
}

void validate(const FaultPolicy& p) {
  auto finite = [](double v) { return std::isfinite(v); };
  if (!finite(p.temp_min_degc) || !finite(p.temp_max_degc) || !(p.temp_min_degc < p.temp_max_degc))
    throw OptionError("faults.temp_max_degc",
                      fmt::format("[{}, {}] °C is not a range: both finite, min < max",
                                  p.temp_min_degc, p.temp_max_degc));
  if (!(p.gyro_limit_dph > 0) || !finite(p.gyro_limit_dph))
    throw OptionError("faults.gyro_limit_dph",
                      fmt::format("{} °/h must be finite and > 0", p.gyro_limit_dph));
  if (!(p.bridge_s >= 0) || !finite(p.bridge_s))
    throw OptionError("faults.bridge_s", fmt::format("{} s must be finite and ≥ 0", p.bridge_s));
  if (!(p.hold_s >= p.bridge_s) || !finite(p.hold_s))
    throw OptionError("faults.hold_s",
                      fmt::format("{} s must be finite and no shorter than the bridge ({} s)",
                                  p.hold_s, p.bridge_s));
  if (!(p.stuck_s >= 0) || !finite(p.stuck_s))
    throw OptionError("faults.stuck_s",
                      fmt::format("{} s must be finite and ≥ 0 (0: no stuck check)", p.stuck_s));
  if (!(p.stuck_delta_degc > 0) || !finite(p.stuck_delta_degc))
    throw OptionError("faults.stuck_delta_degc",
                      fmt::format("{} °C must be finite and > 0", p.stuck_delta_degc));
  if (!(p.temp_jump_degc >= 0) || !finite(p.temp_jump_degc))
    throw OptionError(
        "faults.temp_jump_degc",
        fmt::format("{} °C must be finite and ≥ 0 (0: no jump check)", p.temp_jump_degc));
}

namespace fault {

const std::array<std::string_view, count>& names() {
  static const std::array<std::string_view, count> kNames = {
      "temp_bad", "temp_stuck", "gyro_bad", "time_bad", "gap",       "out_of_order",
      "restart",  "bridged",    "held",     "stopped",  "temp_jump", "off_interval"};
  return kNames;
}

std::string describe(std::uint32_t flags) {
  std::string out;
  for (std::size_t k = 0; k < count; ++k) {
    if ((flags & (1u << k)) == 0) continue;
    if (!out.empty()) out += '|';
    out += names()[k];
  }
  return out;
}

}  // namespace fault
}  // namespace fogdrift
