#include "fogdrift/sim/thermal_network.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fogdrift/base/random.hpp"

namespace fogdrift::sim {
namespace {

constexpr int idx(Node n) {
  return static_cast<int>(n);
}

void run(const ThermalNetwork& net, NodeTemps& t, double seconds, double air, bool powered) {
  const double dt = 0.5;
  for (double s = 0; s < seconds; s += dt) net.step(t, dt, air, air, powered);
}

TEST(ThermalNetwork, UnpoweredNodesSettleToTheChamberFromAnyStart) {
  const ThermalNetwork net{ThermalParams{}};
  Rng rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    NodeTemps t;
    for (double& x : t) x = rng.uniform(-40, 60);
    const double air = rng.uniform(-40, 60);
    run(net, t, 24 * 3600.0, air, false);
    for (int k = 0; k < kNodeCount; ++k) ASSERT_NEAR(t[k], air, 1e-6) << "node " << k;
  }
}

TEST(ThermalNetwork, PoweredTransientEndsAtTheLinearSolveAndBalancesEnergy) {
  ThermalParams p;
  const ThermalNetwork net{p};
  const double air = -20.0;
  NodeTemps t;
  t.fill(air);
  run(net, t, 12 * 3600.0, air, true);
  const NodeTemps steady = net.steady_state(air, true);  // LU solve, independent of integration
  for (int k = 0; k < kNodeCount; ++k) EXPECT_NEAR(t[k], steady[k], 1e-6) << "node " << k;
  // Energy balance: everything dissipated leaves through the housing's link to the air.
  const double to_air = p.housing_air_w_per_k * (steady[idx(Node::housing)] - air);
  EXPECT_NEAR(to_air, net.total_power_w(steady[idx(Node::housing)]), 1e-9);
  // The unpowered steady state is the air temperature itself.
  for (double x : net.steady_state(air, false)) EXPECT_EQ(x, air);
}

TEST(ThermalNetwork, PowerOnHeatsTheCoilFromTheHubSoAGradientBuilds) {
  const ThermalNetwork net{ThermalParams{}};
  NodeTemps t;
  t.fill(10.0);
  run(net, t, 300.0, 10.0, true);
  EXPECT_GT(t[idx(Node::electronics)], t[idx(Node::coil_inner)]);
  EXPECT_GT(t[idx(Node::coil_inner)], t[idx(Node::coil_outer)]);
  EXPECT_GT(t[idx(Node::acc1)], t[idx(Node::acc2)]);  // accelerometer 1 sits near the board
  EXPECT_GT(t[idx(Node::coil_outer)], 10.0);
}

TEST(ThermalNetwork, RungeKuttaStepConvergesAtFourthOrder) {
  const ThermalNetwork net{ThermalParams{}};
  auto integrate = [&](double dt) {
    NodeTemps t;
    t.fill(0.0);
    for (int i = 0; i < static_cast<int>(std::lround(600.0 / dt)); ++i) net.step(t, dt, 0, 0, true);
    return t[idx(Node::coil_inner)];
  };
  const double reference = integrate(0.05);
  const double e1 = std::abs(integrate(20.0) - reference);
  const double e2 = std::abs(integrate(10.0) - reference);
  EXPECT_GT(e1 / e2, 12.0);  // 2^4 = 16 for a fourth-order method
}

}  // namespace
}  // namespace fogdrift::sim
