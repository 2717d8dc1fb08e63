// Quartz flexible accelerometer (QFA) model (docs/simulator.md §3): the specific force of gravity
// along its axis (+1 g when the axis points straight up), plus a bias that drifts with the
// temperature of its own node, plus white noise.
#pragma once

#include "fogdrift/base/random.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/turntable.hpp"

namespace fogdrift::sim {

/// One sample, g: up·axis + bias + temp_coeff·(T_node − 25 °C) + noise.
double accelerometer_output_g(const AccelerometerParams& params, const Vec3& axis_enu,
                              double node_degc, Rng& rng);

}  // namespace fogdrift::sim
