#include "fogdrift/sim/thermal_network.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace fogdrift::sim {

ThermalNetwork::ThermalNetwork(const ThermalParams& params) : p_(params) {
  auto link = [&](Node a, Node b, double g) {
    g_[node_index(a)][node_index(b)] += g;
    g_[node_index(b)][node_index(a)] += g;
  };
  link(Node::electronics, Node::housing, p_.electronics_housing_w_per_k);
  link(Node::coil_outer, Node::housing, p_.coil_outer_housing_w_per_k);
  link(Node::coil_inner, Node::coil_outer, p_.coil_inner_outer_w_per_k);
  link(Node::coil_inner, Node::electronics, p_.coil_inner_electronics_w_per_k);
  link(Node::acc1, Node::electronics, p_.acc1_electronics_w_per_k);
  link(Node::acc1, Node::housing, p_.acc1_housing_w_per_k);
  link(Node::acc2, Node::housing, p_.acc2_housing_w_per_k);
  g_air_[node_index(Node::housing)] = p_.housing_air_w_per_k;
}

NodeTemps ThermalNetwork::powers_w(double housing_degc, bool powered) const {
  NodeTemps p{};
  if (!powered) return p;
  // The light source and its cooler sit on the electronics board; their heat reaches the coil hub
  // through the hub's mount, so the coil warms from the inside out with a delay.
  p[node_index(Node::electronics)] = p_.electronics_power_w + p_.light_source_power_w +
                                     p_.tec_w_per_k * std::abs(housing_degc - p_.tec_setpoint_degc);
  p[node_index(Node::acc1)] = p_.acc1_power_w;
  p[node_index(Node::acc2)] = p_.acc2_power_w;
  return p;
}

double ThermalNetwork::total_power_w(double housing_degc) const {
  double sum = 0.0;
  for (double w : powers_w(housing_degc, true)) sum += w;
  return sum;
}

NodeTemps ThermalNetwork::derivative(const NodeTemps& t, double air_degc, bool powered) const {
  const NodeTemps p = powers_w(t[node_index(Node::housing)], powered);
  NodeTemps d{};
  for (int k = 0; k < kNodeCount; ++k) {
    double flow = p[k] + g_air_[k] * (air_degc - t[k]);
    for (int j = 0; j < kNodeCount; ++j) flow += g_[k][j] * (t[j] - t[k]);
    d[k] = flow / p_.capacity_j_per_k[k];
  }
  return d;
}

void ThermalNetwork::step(NodeTemps& t, double dt, double air0, double air1, bool powered) const {
  step(t, dt, air0, air1, powered, derivative(t, air0, powered));
}

void ThermalNetwork::step(NodeTemps& t, double dt, double air0, double air1, bool powered,
                          const NodeTemps& k1) const {
  const double air_mid = 0.5 * (air0 + air1);
  auto add = [](const NodeTemps& a, const NodeTemps& b, double s) {
    NodeTemps r;
    for (int k = 0; k < kNodeCount; ++k) r[k] = a[k] + s * b[k];
    return r;
  };
  const NodeTemps k2 = derivative(add(t, k1, 0.5 * dt), air_mid, powered);
  const NodeTemps k3 = derivative(add(t, k2, 0.5 * dt), air_mid, powered);
  const NodeTemps k4 = derivative(add(t, k3, dt), air1, powered);
  for (int k = 0; k < kNodeCount; ++k) {
    t[k] += dt / 6.0 * (k1[k] + 2.0 * k2[k] + 2.0 * k3[k] + k4[k]);
  }
}

NodeTemps ThermalNetwork::steady_state(double air_degc, bool powered) const {
  NodeTemps t;
  t.fill(air_degc);
  if (!powered) return t;
  // Solve L·ΔT = P, ΔT = T − T_air, with L the conductance Laplacian plus the air links; the cooler
  // power depends on |T_housing − set point|, so iterate (it converges in a few steps: the
  // cooler's W/K is small against the housing's link to air).
  Eigen::Matrix<double, kNodeCount, kNodeCount> laplacian =
      Eigen::Matrix<double, kNodeCount, kNodeCount>::Zero();
  for (int k = 0; k < kNodeCount; ++k) {
    laplacian(k, k) = g_air_[k];
    for (int j = 0; j < kNodeCount; ++j) {
      if (j == k) continue;
      laplacian(k, k) += g_[k][j];
      laplacian(k, j) -= g_[k][j];
    }
  }
  const auto solver = laplacian.fullPivLu();
  for (int iteration = 0; iteration < 100; ++iteration) {
    const NodeTemps p = powers_w(t[node_index(Node::housing)], true);
    Eigen::Matrix<double, kNodeCount, 1> rhs;
    for (int k = 0; k < kNodeCount; ++k) rhs(k) = p[k];
    const Eigen::Matrix<double, kNodeCount, 1> rise = solver.solve(rhs);
    double change = 0.0;
    for (int k = 0; k < kNodeCount; ++k) {
      change = std::max(change, std::abs(air_degc + rise(k) - t[k]));
      t[k] = air_degc + rise(k);
    }
    if (change < 1e-12) break;
  }
  return t;
}

double ThermalNetwork::shortest_time_constant_s() const {
  double shortest = 1e300;
  for (int k = 0; k < kNodeCount; ++k) {
    double g = g_air_[k];
    for (int j = 0; j < kNodeCount; ++j) g += g_[k][j];
    if (g > 0) shortest = std::min(shortest, p_.capacity_j_per_k[k] / g);
  }
  return shortest;
}

}  // namespace fogdrift::sim
