#include "fogdrift/regress/gp.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <span>

#include "base/c_text.hpp"
#include "base/json_number.hpp"
#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift {
namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// exp(−½ Σ_k (a_k − b_k)² / ℓ_k²), summed as predict() and the C header sum it.
double correlation(const double* a, const double* b, const std::vector<double>& length,
                   std::size_t d) {
  double acc = 0;
  for (std::size_t k = 0; k < d; ++k) {
    const double e = a[k] - b[k];
    acc += e * e * (0.5 / (length[k] * length[k]));
  }
  return std::exp(-acc);
}

// K + σn² I over the rows of `data` (eq. 1).
Matrix covariance(const Data& data, const GpHyper& h) {
  const auto n = static_cast<Eigen::Index>(data.rows);
  Matrix k(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    k(i, i) = h.signal_variance + h.noise_variance;
    for (Eigen::Index j = 0; j < i; ++j)
      k(i, j) = k(j, i) = h.signal_variance * correlation(data.row(static_cast<std::size_t>(i)),
                                                          data.row(static_cast<std::size_t>(j)),
                                                          h.length_scale, data.cols);
  }
  return k;
}

void check_hyper(const GpHyper& h, std::size_t inputs) {
  auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if (h.length_scale.size() != inputs)
    throw OptionError("gp",
                      fmt::format("{} length scales for {} inputs", h.length_scale.size(), inputs));
  if (!positive(h.signal_variance) || !positive(h.noise_variance) ||
      !std::all_of(h.length_scale.begin(), h.length_scale.end(), positive))
    throw OptionError("gp", "every hyperparameter must be finite and > 0");
}

// The factor of K = K + σn² I (covariance()); OptionError when it is not positive definite.
Eigen::LLT<Matrix> factor_of(const Matrix& k, const GpHyper& h) {
  Eigen::LLT<Matrix> llt(k);
  if (llt.info() != Eigen::Success)
    throw OptionError("gp", fmt::format("K + σn² I is not positive definite in floating point "
                                        "(σn² = {:.3g}); the rows repeat or σn² is too small",
                                        h.noise_variance));
  return llt;
}

Eigen::LLT<Matrix> cholesky(const Data& data, const GpHyper& h) {
  check_hyper(h, data.cols);
  return factor_of(covariance(data, h), h);
}

// eq. 4 from α and the diagonal of L: −½ yᵀα − Σ log L_ii − (n/2) log 2π.
double likelihood_of(std::span<const double> y, std::span<const double> alpha,
                     std::span<const double> diagonal) {
  double value = -0.5 * static_cast<double>(y.size()) * std::log(2 * std::numbers::pi);
  for (std::size_t i = 0; i < y.size(); ++i) value -= 0.5 * y[i] * alpha[i] + std::log(diagonal[i]);
  return value;
}

constexpr std::array<EnumName<GpSelection>, 2> kSelectionNames = {
    {{GpSelection::cv, "cv"}, {GpSelection::likelihood, "likelihood"}}};

}  // namespace

std::string_view to_string(GpSelection selection) {
  return name_in(kSelectionNames, selection);
}

GpSelection parse_gp_selection(const std::string& text, const std::string& option) {
  return parse_in(kSelectionNames, text, option, "a way to choose the hyperparameters");
}

std::string gp_selection_names() {
  return names_in(kSelectionNames);
}

void validate(const GpOptions& o) {
  if (o.max_points < 10 || o.max_points > 4000)
    throw OptionError("gp_points", fmt::format("{} is outside 10 … 4000", o.max_points));
  if (o.max_iterations < 1 || o.max_iterations > 10000)
    throw OptionError("gp_iterations", fmt::format("{} is outside 1 … 10000", o.max_iterations));
  const GpBounds& b = o.bounds;
  if (!(0 < b.signal_min && b.signal_min < b.signal_max && 0 < b.length_min &&
        b.length_min < b.length_max && 0 < b.noise_min && b.noise_min < b.noise_max))
    throw OptionError("gp_bounds", "each bound must be > 0 and below its upper bound");
  const GpSearchBox& x = o.box;
  if (!(0 < x.length_min && x.length_min < x.length_max && std::isfinite(x.length_max) &&
        0 < x.ratio_min && x.ratio_min < x.ratio_max && std::isfinite(x.ratio_max)))
    throw OptionError("gp_box", "each bound must be finite, > 0 and below its upper bound");
  if (o.ard && o.selection == GpSelection::cv)
    throw OptionError("gp_kernel",
                      "ard (one length scale per feature) needs the likelihood fit: the "
                      "cross-validated search chooses one length scale");
}

double Gp::predict(const double* x) const noexcept {
  // Compensated (Kahan) sum: with a small σn² the terms of α are large and cancel.
  double z = 0, carry = 0;
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    const double term = hyper.signal_variance * alpha[i] *
                            correlation(x, points.data() + i * inputs, hyper.length_scale, inputs) -
                        carry;
    const double sum = z + term;
    carry = (sum - z) - term;
    z = sum;
  }
  return z;
}

double GpPosterior::variance(const double* x) const {
  const std::size_t n = gp.size(), d = gp.inputs;
  // v = L⁻¹ k* by forward substitution; V = s² − vᵀv (eq. 3).
  std::vector<double> v(n);
  double vv = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double s = gp.hyper.signal_variance *
               correlation(x, gp.points.data() + i * d, gp.hyper.length_scale, d);
    for (std::size_t j = 0; j < i; ++j) s -= lower[i * n + j] * v[j];
    v[i] = s / lower[i * n + i];
    vv += v[i] * v[i];
  }
  return std::max(0.0, gp.hyper.signal_variance - vv);
}

GpPosterior fit_gp(const Data& train, const GpHyper& hyper) {
  validate(train, "Gaussian-process training data");
  const Eigen::LLT<Matrix> llt = cholesky(train, hyper);
  const auto n = static_cast<Eigen::Index>(train.rows);
  const Eigen::VectorXd a = llt.solve(Eigen::Map<const Eigen::VectorXd>(train.y.data(), n));
  GpPosterior out;
  out.gp.inputs = train.cols;
  out.gp.hyper = hyper;
  out.gp.points = train.x;
  out.gp.alpha.assign(a.data(), a.data() + a.size());
  const Matrix l = llt.matrixL();
  out.lower.assign(l.data(), l.data() + l.size());
  return out;
}

GpPosterior factor(const Gp& gp) {
  Data data;
  data.rows = gp.size();
  data.cols = gp.inputs;
  data.x = gp.points;
  const Matrix l = cholesky(data, gp.hyper).matrixL();
  GpPosterior out{gp, std::vector<double>(l.data(), l.data() + l.size())};
  return out;
}

double GpPosterior::log_likelihood(std::span<const double> y) const {
  const std::size_t n = gp.size();
  std::vector<double> diagonal(n);
  for (std::size_t i = 0; i < n; ++i) diagonal[i] = lower[i * n + i];
  return likelihood_of(y, gp.alpha, diagonal);
}

GpLikelihood log_marginal_likelihood(const Data& train, const GpHyper& h, bool ard) {
  const std::size_t n = train.rows, d = train.cols;
  check_hyper(h, d);
  const Matrix cov = covariance(train, h);
  const Eigen::LLT<Matrix> llt = factor_of(cov, h);
  const Eigen::Map<const Eigen::VectorXd> y(train.y.data(), static_cast<Eigen::Index>(n));
  const Eigen::VectorXd a = llt.solve(y);
  const Eigen::VectorXd diagonal = llt.matrixLLT().diagonal();
  GpLikelihood out;
  out.value = likelihood_of(train.y, std::span<const double>(a.data(), n),
                            std::span<const double>(diagonal.data(), n));
  // eq. 5: ∂/∂θ_j = ½ tr(W ∂K/∂θ_j), W = ααᵀ − K⁻¹, summed over i ≥ j (W and K symmetric).
  const Matrix inverse =
      llt.solve(Matrix::Identity(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)));
  const std::size_t m = ard ? d : 1;
  out.gradient.assign(m + 2, 0.0);
  double trace = 0;
  std::vector<double> scaled(m, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto ii = static_cast<Eigen::Index>(i);
    const double wii = a[ii] * a[ii] - inverse(ii, ii);
    trace += wii;
    out.gradient[0] += 0.5 * wii * h.signal_variance;  // E_ii = 1, D_ii = 0
    for (std::size_t j = 0; j < i; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      const double w = a[ii] * a[jj] - inverse(ii, jj);
      const double* xi = train.row(i);
      const double* xj = train.row(j);
      const double wk = w * cov(ii, jj);  // s²·E_ij; twice, for (i, j) and (j, i), times ½
      out.gradient[0] += wk;
      for (std::size_t k = 0; k < d; ++k) {
        const double e = xi[k] - xj[k];
        scaled[ard ? k : 0] += wk * e * e / (h.length_scale[k] * h.length_scale[k]);
      }
    }
  }
  for (std::size_t k = 0; k < m; ++k) out.gradient[1 + k] = scaled[k];
  out.gradient[m + 1] = 0.5 * h.noise_variance * trace;
  return out;
}

std::vector<std::size_t> gp_rows(std::size_t rows, std::size_t max_points) {
  const std::size_t n = std::min(rows, max_points);
  std::vector<std::size_t> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = i * rows / n;
  return out;
}

GpFit train_gp(const Data& train, const GpOptions& o) {
  validate(o);
  validate(train, "Gaussian-process training data");
  const std::vector<std::size_t> kept = gp_rows(train.rows, o.max_points);
  const Data data = train.subset(kept);
  const std::size_t d = train.cols, m = o.ard ? d : 1, p = m + 2;
  const GpBounds& b = o.bounds;
  // θ = (log s², log ℓ, log σn²) and its box.
  std::vector<double> lo(p, std::log(b.length_min)), hi(p, std::log(b.length_max));
  lo[0] = std::log(b.signal_min), hi[0] = std::log(b.signal_max);
  lo[p - 1] = std::log(b.noise_min), hi[p - 1] = std::log(b.noise_max);
  std::vector<double> theta(p, 0.5 * std::log(static_cast<double>(d)));
  theta[0] = 0, theta[p - 1] = std::log(0.1);
  for (std::size_t i = 0; i < p; ++i) theta[i] = std::clamp(theta[i], lo[i], hi[i]);
  auto hyper_of = [&](const std::vector<double>& t) {
    GpHyper h;
    h.signal_variance = std::exp(t[0]);
    for (std::size_t k = 0; k < d; ++k) h.length_scale.push_back(std::exp(t[1 + (o.ard ? k : 0)]));
    h.noise_variance = std::exp(t[p - 1]);
    return h;
  };
  GpSummary summary;
  summary.points = kept.size();
  // f = −log p and its gradient; +∞ where K + σn² I cannot be factored (the search steps back).
  auto objective = [&](const std::vector<double>& t, std::vector<double>& g) {
    ++summary.evaluations;
    try {
      GpLikelihood l = log_marginal_likelihood(data, hyper_of(t), o.ard);
      for (std::size_t i = 0; i < p; ++i) g[i] = -l.gradient[i];
      return -l.value;
    } catch (const OptionError&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  // The gradient with the components that push against an active bound set to 0.
  auto projected = [&](const std::vector<double>& t, const std::vector<double>& g) {
    std::vector<double> out = g;
    for (std::size_t i = 0; i < p; ++i)
      if ((t[i] <= lo[i] && g[i] > 0) || (t[i] >= hi[i] && g[i] < 0)) out[i] = 0;
    return out;
  };
  auto dot = [](const std::vector<double>& a, const std::vector<double>& c) {
    double s = 0;
    for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * c[i];
    return s;
  };
  // Projected L-BFGS with ten pairs and a backtracking (Armijo) line search; it stops as
  // scipy's L-BFGS-B does by default: a projected gradient below 1e-5, or a relative decrease
  // of f below 1e7 · machine ε (docs/gp.md, "By the marginal likelihood").
  std::vector<double> g(p), g_new(p), t_new(p);
  double f = objective(theta, g);
  if (!std::isfinite(f))
    throw OptionError("gp", "the likelihood cannot be computed at the search's start");
  std::deque<std::pair<std::vector<double>, std::vector<double>>> pairs;  // (s, y)
  constexpr double kGradientTolerance = 1e-5;
  const double decrease_tolerance = 1e7 * std::numeric_limits<double>::epsilon();
  for (summary.iterations = 0; summary.iterations < o.max_iterations; ++summary.iterations) {
    std::vector<double> pg = projected(theta, g);
    double pg_max = 0;
    for (double v : pg) pg_max = std::max(pg_max, std::abs(v));
    if (pg_max <= kGradientTolerance) {
      summary.converged = true;
      break;
    }
    // Two-loop recursion on the projected gradient.
    std::vector<double> q = pg, rho(pairs.size()), a(pairs.size());
    for (std::size_t k = pairs.size(); k-- > 0;) {
      rho[k] = 1 / dot(pairs[k].second, pairs[k].first);
      a[k] = rho[k] * dot(pairs[k].first, q);
      for (std::size_t i = 0; i < p; ++i) q[i] -= a[k] * pairs[k].second[i];
    }
    const double gamma = pairs.empty() ? 1 / pg_max
                                       : dot(pairs.back().first, pairs.back().second) /
                                             dot(pairs.back().second, pairs.back().second);
    for (double& v : q) v *= gamma;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      const double beta = rho[k] * dot(pairs[k].second, q);
      for (std::size_t i = 0; i < p; ++i) q[i] += (a[k] - beta) * pairs[k].first[i];
    }
    std::vector<double> dir(p);
    for (std::size_t i = 0; i < p; ++i) {
      dir[i] = -q[i];
      if ((theta[i] <= lo[i] && dir[i] < 0) || (theta[i] >= hi[i] && dir[i] > 0)) dir[i] = 0;
    }
    if (dot(dir, pg) >= 0) {  // not a descent direction: start the memory again
      pairs.clear();
      for (std::size_t i = 0; i < p; ++i) dir[i] = -pg[i] / pg_max;
    }
    double step = 1, f_new = f;
    bool moved = false;
    for (int tries = 0; tries < 40; ++tries, step *= 0.5) {
      for (std::size_t i = 0; i < p; ++i)
        t_new[i] = std::clamp(theta[i] + step * dir[i], lo[i], hi[i]);
      std::vector<double> s(p);
      for (std::size_t i = 0; i < p; ++i) s[i] = t_new[i] - theta[i];
      f_new = objective(t_new, g_new);
      if (f_new <= f + 1e-4 * dot(g, s)) {
        moved = true;
        break;
      }
    }
    if (!moved) {
      summary.converged = true;  // no decrease along a descent direction: a numerical optimum
      break;
    }
    std::vector<double> s(p), y(p);
    for (std::size_t i = 0; i < p; ++i) s[i] = t_new[i] - theta[i], y[i] = g_new[i] - g[i];
    if (dot(s, y) > 1e-10 * dot(y, y)) {
      pairs.emplace_back(s, y);
      if (pairs.size() > 10) pairs.pop_front();
    }
    const double decrease = (f - f_new) / std::max({std::abs(f), std::abs(f_new), 1.0});
    theta = t_new, g = g_new, f = f_new;
    if (decrease <= decrease_tolerance) {
      summary.converged = true;
      ++summary.iterations;
      break;
    }
  }
  GpFit out{fit_gp(data, hyper_of(theta)), summary};
  out.summary.log_likelihood = -f;
  return out;
}

std::string to_json(const Gp& gp) {
  const nlohmann::ordered_json j = {{"inputs", gp.inputs},
                                    {"signal_variance", gp.hyper.signal_variance},
                                    {"length_scale", gp.hyper.length_scale},
                                    {"noise_variance", gp.hyper.noise_variance},
                                    {"points", gp.points},
                                    {"alpha", gp.alpha}};
  return j.dump();
}

Gp regressor_from_json(std::type_identity<Gp>, const std::string& text, const std::string& source) {
  auto fail = [&](const std::string& where, const std::string& rule) {
    throw InputError(source, 0, 0, fmt::format("{}: {}", where, rule));
  };
  check_json_nesting(source, text);
  Gp gp;
  std::string where = "(top level)";
  try {
    const auto r = nlohmann::json::parse(text);
    where = "inputs";
    gp.inputs = fogdrift::detail::whole_number<std::size_t>(r.at("inputs"));
    where = "signal_variance";
    gp.hyper.signal_variance = r.at("signal_variance").get<double>();
    where = "length_scale";
    gp.hyper.length_scale = r.at("length_scale").get<std::vector<double>>();
    where = "noise_variance";
    gp.hyper.noise_variance = r.at("noise_variance").get<double>();
    where = "points";
    gp.points = r.at("points").get<std::vector<double>>();
    where = "alpha";
    gp.alpha = r.at("alpha").get<std::vector<double>>();
  } catch (const nlohmann::json::exception& e) {
    fail(where, fmt::format("missing or mistyped field ({})", json_error_text(e)));
  }
  auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if (gp.inputs == 0) fail("inputs", "must be at least 1");
  if (!positive(gp.hyper.signal_variance)) fail("signal_variance", "must be finite and > 0");
  if (!positive(gp.hyper.noise_variance)) fail("noise_variance", "must be finite and > 0");
  if (gp.hyper.length_scale.size() != gp.inputs)
    fail("length_scale", "needs one length scale per input");
  if (!std::all_of(gp.hyper.length_scale.begin(), gp.hyper.length_scale.end(), positive))
    fail("length_scale", "must be finite and > 0");
  if (gp.alpha.empty()) fail("alpha", "needs at least one row");
  if (gp.points.size() != gp.alpha.size() * gp.inputs)
    fail("points", "must hold inputs numbers for each value of alpha");
  for (double v : gp.points)
    if (!std::isfinite(v)) fail("points", "must be finite numbers");
  for (double v : gp.alpha)
    if (!std::isfinite(v)) fail("alpha", "must be finite numbers");
  return gp;
}

CRegressor to_c(const Gp& gp, const CNames& names) {
  const std::string& prefix = names.prefix;
  const std::string& upper = names.upper;
  const std::size_t n = gp.size();
  std::vector<double> half_inverse, coef;
  for (double l : gp.hyper.length_scale) half_inverse.push_back(0.5 / (l * l));
  for (double a : gp.alpha) coef.push_back(gp.hyper.signal_variance * a);
  CRegressor out;
  out.tables = fmt::format("#define {}_N_POINTS {}\n", upper, n);
  out.tables += fmt::format("static const @REAL@ {}_gp_points[{}] = {{{}}};\n", prefix,
                            gp.points.size(), detail::c_array(gp.points));
  out.tables += fmt::format("static const @REAL@ {}_gp_half_inv_l2[{}] = {{{}}};\n", prefix,
                            gp.inputs, detail::c_array(half_inverse));
  out.tables += fmt::format("static const @REAL@ {}_gp_coef[{}] = {{{}}};\n\n", prefix, n,
                            detail::c_array(coef));
  out.body = fmt::format(
      "  @REAL@ z = 0.0, carry = 0.0; /* compensated sum (Kahan), as Gp::predict */\n"
      "  int i, k;\n"
      "  for (i = 0; i < {1}_N_POINTS; ++i) {{\n"
      "    const @REAL@* p = {0}_gp_points + i * {1}_N_FEATURES;\n"
      "    @REAL@ acc = 0.0, term, sum;\n"
      "    for (k = 0; k < {1}_N_FEATURES; ++k) {{\n"
      "      const @REAL@ e = x[k] - p[k];\n"
      "      acc += e * e * {0}_gp_half_inv_l2[k];\n"
      "    }}\n"
      "    term = {0}_gp_coef[i] * exp@F@(-acc) - carry;\n"
      "    sum = z + term;\n"
      "    carry = (sum - z) - term;\n"
      "    z = sum;\n"
      "  }}\n",
      prefix, upper);
  return out;
}

}  // namespace fogdrift
