#include "fogdrift/sim/accelerometer.hpp"

namespace fogdrift::sim {

double accelerometer_output_g(const AccelerometerParams& p, const Vec3& axis_enu, double node_degc,
                              Rng& rng) {
  // At rest the accelerometer senses the reaction to gravity: +1 g along local up (ENU z).
  const double specific_force_g = axis_enu[2];
  return specific_force_g + p.bias_g + p.temp_coeff_g_per_k * (node_degc - 25.0) +
         p.noise_g * rng.normal();
}

}  // namespace fogdrift::sim
