// LIBSVM (libsvm-dev) as the test oracle: train with its C API on the same data and read back
// what it found.
#pragma once

#include <svm.h>

#include <cmath>
#include <vector>

#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr::testing {

struct OracleFit {
  std::vector<double> beta;  ///< α⁺ − α⁻ per training sample (0 for non-support vectors)
  double rho = 0;
  int n_sv = 0;
  svm_model* model = nullptr;
  std::vector<svm_node> nodes;
  std::vector<svm_node*> rows;
  std::vector<double> y;
  svm_problem prob{};

  OracleFit() = default;
  OracleFit(const OracleFit&) = delete;
  OracleFit& operator=(const OracleFit&) = delete;
  ~OracleFit() {
    if (model) svm_free_and_destroy_model(&model);
  }
  double predict(const double* x, std::size_t dims) const {
    std::vector<svm_node> v(dims + 1);
    for (std::size_t k = 0; k < dims; ++k) v[k] = {static_cast<int>(k + 1), x[k]};
    v[dims] = {-1, 0};
    return svm_predict(model, v.data());
  }
};

inline void quiet(const char*) {}

/// Trains LIBSVM's ε-SVR with the same parameters (RBF or linear).
inline void libsvm_train(const Data& d, const Params& p, OracleFit& out) {
  svm_set_print_string_function(quiet);
  out.nodes.resize(d.rows * (d.cols + 1));
  out.rows.resize(d.rows);
  out.y = d.y;
  for (std::size_t i = 0; i < d.rows; ++i) {
    svm_node* r = out.nodes.data() + i * (d.cols + 1);
    for (std::size_t k = 0; k < d.cols; ++k) r[k] = {static_cast<int>(k + 1), d.row(i)[k]};
    r[d.cols] = {-1, 0};
    out.rows[i] = r;
  }
  out.prob.l = static_cast<int>(d.rows);
  out.prob.y = out.y.data();
  out.prob.x = out.rows.data();
  svm_parameter sp{};
  sp.svm_type = EPSILON_SVR;
  sp.kernel_type = p.kernel.type == KernelType::rbf ? RBF : LINEAR;
  sp.gamma = p.kernel.gamma;
  sp.cache_size = 100;
  sp.eps = p.tolerance;
  sp.C = p.c;
  sp.p = p.epsilon;
  sp.shrinking = p.shrinking ? 1 : 0;
  out.model = svm_train(&out.prob, &sp);
  out.rho = out.model->rho[0];
  out.n_sv = out.model->l;
  out.beta.assign(d.rows, 0.0);
  std::vector<int> idx(out.model->l);
  svm_get_sv_indices(out.model, idx.data());
  for (int k = 0; k < out.model->l; ++k) out.beta[idx[k] - 1] = out.model->sv_coef[0][k];
}

/// The dual objective ½βᵀKβ + ε·Σ|β| − yᵀβ of coefficients β, with K in double: an independent
/// check of both solvers' reported objectives.
inline double dual_objective(const Data& d, const Kernel& kernel, double epsilon,
                             const std::vector<double>& beta) {
  double quad = 0, lin = 0;
  for (std::size_t i = 0; i < d.rows; ++i) {
    if (beta[i] == 0) continue;
    lin += epsilon * std::fabs(beta[i]) - d.y[i] * beta[i];
    for (std::size_t j = 0; j < d.rows; ++j) {
      if (beta[j] == 0) continue;
      quad += beta[i] * beta[j] * kernel(d.row(i), d.row(j), d.cols);
    }
  }
  return 0.5 * quad + lin;
}

}  // namespace fogdrift::svr::testing
