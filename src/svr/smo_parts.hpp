// What the two SMO solvers (smo_solver.cpp, pair_solver.cpp) share besides their rows
// (rows.hpp): LIBSVM's analytic two-variable step. Internal header: not installed.
#pragma once

#include "svr/rows.hpp"

namespace fogdrift::svr::detail {

constexpr double kTau = 1e-12;  // LIBSVM's TAU: the curvature used when Q is not positive

/// LIBSVM's analytic solution of the two-variable subproblem in α_i, α_j (signs y_i, y_j,
/// gradients G_i, G_j, curvature `quad` = K_ii + K_jj − 2K_ij), clipped to the box [0, C]² and
/// keeping y_i·α_i + y_j·α_j fixed.
inline void two_variable_step(double& a_i, double& a_j, int y_i, int y_j, double g_i, double g_j,
                              double quad, double c) {
  if (quad <= 0) quad = kTau;
  if (y_i != y_j) {
    const double delta = (-g_i - g_j) / quad;
    const double diff = a_i - a_j;
    a_i += delta;
    a_j += delta;
    if (diff > 0) {
      if (a_j < 0) {
        a_j = 0;
        a_i = diff;
      }
    } else if (a_i < 0) {
      a_i = 0;
      a_j = -diff;
    }
    if (diff > 0) {  // LIBSVM: diff > C_i − C_j, and C_i = C_j here
      if (a_i > c) {
        a_i = c;
        a_j = c - diff;
      }
    } else if (a_j > c) {
      a_j = c;
      a_i = c + diff;
    }
  } else {
    const double delta = (g_i - g_j) / quad;
    const double sum = a_i + a_j;
    a_i -= delta;
    a_j += delta;
    if (sum > c) {
      if (a_i > c) {
        a_i = c;
        a_j = sum - c;
      }
    } else if (a_j < 0) {
      a_j = 0;
      a_i = sum;
    }
    if (sum > c) {
      if (a_j > c) {
        a_j = c;
        a_i = sum - c;
      }
    } else if (a_i < 0) {
      a_i = 0;
      a_j = sum;
    }
  }
}

}  // namespace fogdrift::svr::detail
