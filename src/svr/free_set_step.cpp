// The free-set Newton step (free_set_step.hpp; docs/svr.md, "Newton steps on the free set").
#include "svr/free_set_step.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fogdrift::svr::detail {
namespace {

// L Lᵀ + x xᵀ, L lower triangular, in place (the standard rotation update, O(n²)).
template <class Block>
void rank_one_update(Block l, Eigen::VectorXd x) {
  const Eigen::Index n = l.rows();
  for (Eigen::Index k = 0; k < n; ++k) {
    const double lkk = l(k, k), r = std::hypot(lkk, x[k]);
    const double c = r / lkk, s = x[k] / lkk;
    l(k, k) = r;
    for (Eigen::Index i = k + 1; i < n; ++i) {
      l(i, k) = (l(i, k) + s * x[i]) / c;
      x[i] = c * x[i] - s * l(i, k);
    }
  }
}

// Row and column p taken out of the leading n × n block of `a`, in place: the columns after p
// move one to the left, then the rows after p one up (both towards lower addresses, so a forward
// copy is safe). The buffers keep their size, and a step allocates nothing after its start.
void remove_in_place(Eigen::MatrixXd& a, Eigen::Index n, Eigen::Index p) {
  double* data = a.data();
  const Eigen::Index stride = a.rows();
  for (Eigen::Index j = p; j + 1 < n; ++j)
    std::copy(data + (j + 1) * stride, data + (j + 1) * stride + n, data + j * stride);
  for (Eigen::Index j = 0; j + 1 < n; ++j)
    std::copy(data + j * stride + p + 1, data + j * stride + n, data + j * stride + p);
}

// The Cholesky factor of A with row and column p taken out, from the factor L of A (the leading
// n × n block of `l`), in place: the rows above p keep theirs, and the block below-right absorbs
// column p's part below the diagonal.
void remove_from_factor(Eigen::MatrixXd& l, Eigen::Index n, Eigen::Index p) {
  const Eigen::Index q = n - p - 1;
  const Eigen::VectorXd below = l.col(p).segment(p + 1, q);
  remove_in_place(l, n, p);
  if (q > 0) rank_one_update(l.block(p, p, q, q), below);
}

}  // namespace

FreeSetStep free_set_step(const Eigen::MatrixXd& k, const Eigen::VectorXd& r,
                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                          std::size_t max_removals) {
  const Eigen::Index m = k.rows();
  FreeSetStep out;
  out.delta = Eigen::VectorXd::Zero(m);
  out.ends.assign(static_cast<std::size_t>(m), FreeSetEnd::free);
  if (m < 2) return out;

  Eigen::MatrixXd l;
  const double mean_diagonal = k.diagonal().mean();
  for (double ridge = 1e-7;; ridge *= 10) {
    if (ridge > 1e-2 || !(mean_diagonal > 0)) return out;
    Eigen::MatrixXd a = k;
    a.diagonal().array() += ridge * mean_diagonal;
    Eigen::LLT<Eigen::MatrixXd> llt(a);
    if (llt.info() == Eigen::Success) {
      l = llt.matrixL();
      break;
    }
  }

  // The variables still free (positions in k): the leading n × n blocks of the factor and of
  // their kernel block, and their gradient.
  std::vector<Eigen::Index> free(static_cast<std::size_t>(m));
  for (Eigen::Index i = 0; i < m; ++i) free[static_cast<std::size_t>(i)] = i;
  Eigen::MatrixXd kf = k;
  Eigen::VectorXd g = r, ones = Eigen::VectorXd::Ones(m), u(m), v(m), d(m), kd(m);
  for (Eigen::Index n = m; n >= 2;) {
    const auto lower = l.topLeftCorner(n, n).triangularView<Eigen::Lower>();
    u.head(n) = g.head(n);
    lower.solveInPlace(u.head(n));
    lower.transpose().solveInPlace(u.head(n));
    v.head(n) = ones.head(n);
    lower.solveInPlace(v.head(n));
    lower.transpose().solveInPlace(v.head(n));
    // The Newton direction of the equality-constrained problem; its sum is zero but for
    // rounding, which the mean taken out removes.
    d.head(n) = -u.head(n) + (u.head(n).sum() / v.head(n).sum()) * v.head(n);
    d.head(n).array() -= d.head(n).mean();
    kd.head(n).noalias() = kf.topLeftCorner(n, n).selfadjointView<Eigen::Lower>() * d.head(n);
    const double slope = g.head(n).dot(d.head(n)), curvature = d.head(n).dot(kd.head(n));
    if (!(slope < 0) || !(curvature > 0)) break;
    double t = -slope / curvature;
    Eigen::Index stop = -1;  // the variable that meets its bound first
    for (Eigen::Index j = 0; j < n; ++j) {
      const Eigen::Index i = free[static_cast<std::size_t>(j)];
      const double room = d[j] > 0 ? (hi[i] - out.delta[i]) / d[j]
                                   : (d[j] < 0 ? (lo[i] - out.delta[i]) / d[j]
                                               : std::numeric_limits<double>::infinity());
      if (room < t) t = room, stop = j;
    }
    if (!(t > 0)) break;
    for (Eigen::Index j = 0; j < n; ++j) out.delta[free[static_cast<std::size_t>(j)]] += t * d[j];
    g.head(n) += t * kd.head(n);
    out.moved = true;
    if (stop < 0) {
      out.reached_minimum = true;
      break;
    }
    const Eigen::Index i = free[static_cast<std::size_t>(stop)];
    const bool at_upper = d[stop] > 0;
    out.delta[i] = at_upper ? hi[i] : lo[i];
    out.ends[static_cast<std::size_t>(i)] = at_upper ? FreeSetEnd::upper : FreeSetEnd::lower;
    ++out.removals;
    if (out.removals >= max_removals) break;
    free.erase(free.begin() + stop);
    remove_from_factor(l, n, stop);
    remove_in_place(kf, n, stop);
    std::copy(g.data() + stop + 1, g.data() + n, g.data() + stop);
    --n;
  }
  return out;
}

double free_set_step_work(std::size_t m, std::size_t removals) {
  const auto n = static_cast<double>(m);
  return n * n * n / 3 + 6 * n * n * static_cast<double>(removals + 1);
}

}  // namespace fogdrift::svr::detail
