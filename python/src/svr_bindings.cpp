// The ε-SVR engine for fogdrift.SVR (python/fogdrift/svr.py): arrays in, arrays out, the GIL
// released while the engine works. Inputs may be float64 arrays in either memory order; each
// is copied once, into the engine's own row-major data.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/grid_search.hpp"
#include "fogdrift/svr/svr.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

using Array = py::array_t<double, py::array::forcecast>;

using Rows = py::array_t<std::int64_t, py::array::forcecast>;

// X (n × d, any strides) and y as the engine's data, in one copy: every row, or only `rows`
// (the samples of non-zero weight); w has one weight per row taken.
svr::Data to_data(const Array& x, const Array& y, const std::optional<Array>& weight,
                  const std::optional<Rows>& rows = std::nullopt) {
  if (x.ndim() != 2) throw std::invalid_argument("X must be a 2-D array");
  if (y.ndim() != 1 || y.shape(0) != x.shape(0))
    throw std::invalid_argument("y must be a 1-D array with one value per row of X");
  const py::ssize_t n = rows ? rows->shape(0) : x.shape(0);
  auto row = [&](py::ssize_t i) {
    if (!rows) return i;
    const std::int64_t r = rows->at(i);
    if (r < 0 || r >= x.shape(0)) throw std::invalid_argument("rows: an index outside X");
    return static_cast<py::ssize_t>(r);
  };
  svr::Data d;
  d.rows = static_cast<std::size_t>(n);
  d.cols = static_cast<std::size_t>(x.shape(1));
  d.x.resize(d.rows * d.cols);
  d.y.resize(d.rows);
  const auto xv = x.unchecked<2>();
  const auto yv = y.unchecked<1>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const py::ssize_t r = row(i);
    for (py::ssize_t k = 0; k < x.shape(1); ++k)
      d.x[static_cast<std::size_t>(i) * d.cols + static_cast<std::size_t>(k)] = xv(r, k);
    d.y[static_cast<std::size_t>(i)] = yv(r);
  }
  if (weight) {
    if (weight->ndim() != 1 || weight->shape(0) != n)
      throw std::invalid_argument(
          "sample_weight must be a 1-D array with one value per row of X taken");
    const auto wv = weight->unchecked<1>();
    d.weight.resize(d.rows);
    for (py::ssize_t i = 0; i < weight->shape(0); ++i)
      d.weight[static_cast<std::size_t>(i)] = wv(i);
  }
  return d;
}

// γ as given, or scikit-learn's 'scale' (1/(d·Var X), 1 when X is constant) or 'auto' (1/d),
// computed from the row-major copy so that C- and F-ordered X give the same γ to the bit.
using Gamma = std::variant<double, std::string>;
double gamma_of(const Gamma& gamma, const svr::Data& d) {
  if (const double* g = std::get_if<double>(&gamma)) return *g;
  const std::string& name = std::get<std::string>(gamma);
  const auto cols = static_cast<double>(d.cols);
  if (name == "auto") return 1.0 / cols;
  if (name != "scale")
    throw OptionError("gamma", "must be 'scale', 'auto' or a number > 0 (got '" + name + "')");
  double mean = 0;
  for (const double v : d.x) mean += v;
  mean /= static_cast<double>(d.x.size());
  double var = 0;
  for (const double v : d.x) var += (v - mean) * (v - mean);
  var /= static_cast<double>(d.x.size());
  return var != 0 ? 1.0 / (cols * var) : 1.0;
}

svr::Params to_params(const std::string& kernel, double gamma, double c, double epsilon, double tol,
                      double cache_mb, std::int64_t max_iter, bool shrinking,
                      const std::string& solver) {
  svr::Params p;
  if (kernel == "rbf")
    p.kernel = svr::Kernel::rbf_gamma(gamma);
  else if (kernel == "linear")
    p.kernel = svr::Kernel::linear();
  else
    throw OptionError("kernel", "must be 'rbf' or 'linear' (got '" + kernel + "')");
  p.c = c;
  p.epsilon = epsilon;
  p.tolerance = tol;
  p.cache_mb = cache_mb;
  p.max_iterations = max_iter;
  p.shrinking = shrinking;
  if (solver == "libsvm")
    p.libsvm_path = true;
  else if (solver != "pairs")
    throw OptionError("solver", "must be 'pairs' or 'libsvm' (got '" + solver + "')");
  // scikit-learn's parameter names, so that errors name what the user wrote.
  svr::validate(p, svr::ParamNames{"C", "gamma", "epsilon", "tol", "cache_size", "max_iter"});
  return p;
}

// A fit as the Python estimator stores it: the support vectors' indices into the training rows,
// their coefficients α⁺ − α⁻ and rows, ρ, the γ used, and the solver's summary.
py::dict fit_dict(const svr::FitResult& r, const svr::Data& data, double gamma) {
  const std::size_t n = data.rows, d = data.cols, m = r.model.size();
  py::array_t<std::int32_t> support(static_cast<py::ssize_t>(m));
  auto sv = support.mutable_unchecked<1>();
  py::ssize_t k = 0;
  for (std::size_t i = 0; i < n; ++i)  // the rows fit() kept, in its order
    if (r.dual.alpha[i] - r.dual.alpha[i + n] != 0) sv(k++) = static_cast<std::int32_t>(i);
  if (static_cast<std::size_t>(k) != m) throw std::logic_error("support vectors miscounted");
  py::array_t<double> coef(static_cast<py::ssize_t>(m));
  std::copy(r.model.coef.begin(), r.model.coef.end(), coef.mutable_data());
  py::array_t<double> vectors({static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(d)});
  std::copy(r.model.support_vectors.begin(), r.model.support_vectors.end(), vectors.mutable_data());
  py::dict out;
  out["support"] = support;
  out["dual_coef"] = coef;
  out["support_vectors"] = vectors;
  out["rho"] = r.model.rho;
  out["gamma"] = gamma;
  out["n_iter"] = r.summary.solver.iterations;
  out["converged"] = r.summary.solver.status == svr::SolverStatus::optimal;
  out["objective"] = r.summary.solver.objective;
  out["n_bsv"] = r.summary.n_bsv;
  out["seconds"] = r.summary.seconds;
  return out;
}

// The memory of earlier fits, for the next ones: a Python process that fits many models (a
// search, a cross-validation) pays for fresh pages once per thread that fits, not once per fit
// (docs/svr.md, "Memory"). release_memory() gives it back.
svr::WorkspacePool& workspaces() {
  static svr::WorkspacePool pool;
  return pool;
}

py::dict fit(const Array& x, const Array& y, const std::optional<Array>& weight,
             const std::optional<Rows>& rows, const std::string& kernel, const Gamma& gamma,
             double c, double epsilon, double tol, double cache_mb, std::int64_t max_iter,
             bool shrinking, const std::string& solver) {
  svr::Data data = to_data(x, y, weight, rows);
  const double g = gamma_of(gamma, data);
  const svr::Params p =
      to_params(kernel, g, c, epsilon, tol, cache_mb, max_iter, shrinking, solver);
  std::optional<svr::FitResult> r;
  std::optional<svr::TrainingSet> set;
  released_interruptibly([&] {
    set.emplace(std::move(data));
    const svr::WorkspacePool::Lease workspace = workspaces().borrow();
    r.emplace(svr::fit(*set, p, nullptr, workspace.get()));
  });
  return fit_dict(*r, set->data(), g);
}

py::list fit_path(const Array& x, const Array& y, const std::optional<Array>& weight,
                  const std::optional<Rows>& rows, const std::vector<double>& c_values,
                  const std::string& kernel, const Gamma& gamma, double epsilon, double tol,
                  double cache_mb, std::int64_t max_iter, bool shrinking,
                  const std::string& solver) {
  svr::validate_c_values(c_values);
  svr::Data data = to_data(x, y, weight, rows);
  const double g = gamma_of(gamma, data);
  const svr::Params p =
      to_params(kernel, g, c_values.front(), epsilon, tol, cache_mb, max_iter, shrinking, solver);
  std::optional<svr::TrainingSet> set;
  std::vector<svr::FitResult> path;
  released_interruptibly([&] {
    set.emplace(std::move(data));
    const svr::WorkspacePool::Lease workspace = workspaces().borrow();
    path = svr::fit_c_path(*set, p, c_values, workspace.get());
  });
  py::list out;
  for (const auto& r : path) out.append(fit_dict(r, set->data(), g));
  return out;
}

// Every (gamma, C, fold) of a grid (svr/grid_search.hpp): the sum of squared errors over each
// fold's test rows, or with `predict_rows` (one index array per fold) the predictions at those
// rows, a list of (gamma, C, rows) arrays, one per fold (fogdrift.SVRGridSearchCV scores them
// with any scorer).
py::object search(const Array& x, const Array& y, const std::optional<Array>& weight,
                  const std::vector<py::array_t<std::int64_t>>& train_rows,
                  const std::vector<py::array_t<std::int64_t>>& test_rows,
                  const std::vector<double>& c_values, const std::vector<Gamma>& gammas,
                  const std::string& kernel, double epsilon, double tol, double cache_mb,
                  std::int64_t max_iter, bool shrinking, const std::string& solver, int n_jobs,
                  const std::optional<std::vector<py::array_t<std::int64_t>>>& predict_rows) {
  if (gammas.empty() || train_rows.empty() || train_rows.size() != test_rows.size())
    throw std::invalid_argument("search: needs values of gamma, and train and test folds");
  if (predict_rows && predict_rows->size() != train_rows.size())
    throw std::invalid_argument("search: predict_rows needs one index array per fold");
  const svr::Data all = to_data(x, y, weight);
  auto indices = [&](const py::array_t<std::int64_t>& rows) {
    std::vector<std::size_t> out;
    const auto r = rows.unchecked<1>();
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
      if (r(i) < 0 || static_cast<std::size_t>(r(i)) >= all.rows)
        throw std::invalid_argument("search: a fold's row index is out of range");
      out.push_back(static_cast<std::size_t>(r(i)));
    }
    return out;
  };
  std::vector<svr::GridFold> folds(train_rows.size());
  for (std::size_t f = 0; f < folds.size(); ++f) {
    folds[f].train = indices(train_rows[f]);
    folds[f].test = indices(test_rows[f]);
    if (predict_rows) folds[f].predict = indices((*predict_rows)[f]);
  }
  svr::GridSearchResult r;
  released_interruptibly([&] {
    ThreadPool pool(n_jobs < 0 ? 0u : static_cast<unsigned>(n_jobs));
    r = svr::grid_search(
        all, folds, gammas.size(),
        [&](const svr::Data& train, std::size_t k) {  // errors in scikit-learn's names
          return to_params(kernel, gamma_of(gammas[k], train), c_values.front(), epsilon, tol,
                           cache_mb, max_iter, shrinking, solver);
        },
        c_values, predict_rows.has_value(), pool, workspaces());
  });
  const auto ng = static_cast<py::ssize_t>(r.kernels), nc = static_cast<py::ssize_t>(r.c_values);
  if (predict_rows) {
    py::list out;
    for (std::size_t f = 0; f < folds.size(); ++f) {
      py::array_t<double> a({ng, nc, static_cast<py::ssize_t>(folds[f].predict.size())});
      std::copy(r.predictions[f].begin(), r.predictions[f].end(), a.mutable_data());
      out.append(a);
    }
    return out;
  }
  py::array_t<double> out({ng, nc, static_cast<py::ssize_t>(r.folds)});
  std::copy(r.sse.begin(), r.sse.end(), out.mutable_data());
  return out;
}

py::array_t<double> predict(const Array& vectors, const Array& coef, double rho,
                            const std::string& kernel, double gamma, const Array& x, int n_jobs) {
  svr::Model m;
  m.kernel = kernel == "linear" ? svr::Kernel::linear() : svr::Kernel::rbf_gamma(gamma);
  if (x.ndim() != 2 || vectors.ndim() != 2 || coef.ndim() != 1 || coef.shape(0) != vectors.shape(0))
    throw std::invalid_argument("predict: inconsistent model or data shapes");
  if (x.shape(1) != vectors.shape(1) && vectors.shape(0) > 0)
    throw std::invalid_argument("predict: X has another number of features than the model");
  m.dims = static_cast<std::size_t>(x.shape(1));
  m.rho = rho;
  m.coef.assign(coef.data(), coef.data() + coef.shape(0));
  const auto vv = vectors.unchecked<2>();
  for (py::ssize_t i = 0; i < vectors.shape(0); ++i)
    for (py::ssize_t k = 0; k < vectors.shape(1); ++k) m.support_vectors.push_back(vv(i, k));
  // X row-major (one copy when it is not already), then the rows in parallel.
  const auto rows = static_cast<std::size_t>(x.shape(0));
  const py::array_t<double, py::array::c_style | py::array::forcecast> xc(x);
  py::array_t<double> out(static_cast<py::ssize_t>(rows));
  {
    const std::span<const double> in(xc.data(), rows * m.dims);
    const std::span<double> result(out.mutable_data(), rows);
    py::gil_scoped_release release;
    if (n_jobs == 1 || rows < 256) {
      m.predict(in, result);
    } else {
      ThreadPool pool(n_jobs < 0 ? 0u : static_cast<unsigned>(n_jobs));
      m.predict(in, result, &pool);
    }
  }
  return out;
}

}  // namespace

void bind_svr(py::module_& m) {
  m.def("svr_fit", &fit, py::arg("X"), py::arg("y"), py::arg("sample_weight"), py::arg("rows"),
        py::arg("kernel"), py::arg("gamma"), py::arg("C"), py::arg("epsilon"), py::arg("tol"),
        py::arg("cache_size"), py::arg("max_iter"), py::arg("shrinking"), py::arg("solver"),
        "Fits ε-SVR; returns support, dual_coef, support_vectors, rho and the solver summary.");
  m.def("svr_fit_path", &fit_path, py::arg("X"), py::arg("y"), py::arg("sample_weight"),
        py::arg("rows"), py::arg("C"), py::arg("kernel"), py::arg("gamma"), py::arg("epsilon"),
        py::arg("tol"), py::arg("cache_size"), py::arg("max_iter"), py::arg("shrinking"),
        py::arg("solver"), "Fits ε-SVR at each C in turn, each warm-started from the one before.");
  m.def("svr_search", &search, py::arg("X"), py::arg("y"), py::arg("sample_weight"),
        py::arg("train_rows"), py::arg("test_rows"), py::arg("C"), py::arg("gamma"),
        py::arg("kernel"), py::arg("epsilon"), py::arg("tol"), py::arg("cache_size"),
        py::arg("max_iter"), py::arg("shrinking"), py::arg("solver"), py::arg("n_jobs"),
        py::arg("predict_rows") = py::none(),
        "Sum of squared test errors of every (gamma, C, fold), by warm-started C paths; with "
        "predict_rows (an index array per fold), the predictions at those rows instead: a list "
        "of (gamma, C, rows) arrays, one per fold.");
  m.def(
      "release_memory",
      [] {
        // The workspaces of this module's fits, and the blocks of fits that ended (train's
        // searches among them) kept in the process's reserve.
        return workspaces().clear() + svr::release_reserved_rows();
      },
      "Frees the memory kept from earlier fits for later ones; returns the bytes freed.");
  m.def("svr_predict", &predict, py::arg("support_vectors"), py::arg("dual_coef"), py::arg("rho"),
        py::arg("kernel"), py::arg("gamma"), py::arg("X"), py::arg("n_jobs"),
        "f(x) = Σ dual_coef·K(sv, x) − rho for every row of X.");
}

}  // namespace fogdrift::python
