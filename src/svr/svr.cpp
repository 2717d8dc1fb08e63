#include "fogdrift/svr/svr.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <numeric>
#include <set>

#include "base/json_number.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/memory.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/workspace.hpp"
#include "svr/loops.hpp"

namespace fogdrift::svr {
namespace {

using ojson = nlohmann::ordered_json;

void require(bool ok, const std::string& name, double value, const char* rule) {
  if (!ok) throw OptionError(name, fmt::format("must be {} (got {})", rule, value));
}

// The model from a solved dual: support vectors are the samples with α⁺ ≠ α⁻.
FitResult finish(const TrainingSet& set, const Params& params, DualSolution dual,
                 SolverSummary solver, double seconds) {
  FitResult r;
  const std::size_t n = set.size(), d = set.dims();
  r.model.kernel = params.kernel;
  r.model.dims = d;
  r.model.rho = solver.rho;
  double sum_abs = 0, sum_weights = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = dual.alpha[i] - dual.alpha[i + n];
    const double weight = set.data().weight_of(i);
    sum_abs += std::fabs(a);
    sum_weights += weight;
    if (std::fabs(a) > 0) {
      r.model.coef.push_back(a);
      const double* row = set.data().row(i);
      r.model.support_vectors.insert(r.model.support_vectors.end(), row, row + d);
      if (std::fabs(a) >= params.c * weight) ++r.summary.n_bsv;
    }
  }
  r.summary.n_sv = r.model.coef.size();
  r.summary.nu = sum_abs / (params.c * sum_weights);
  r.summary.solver = solver;
  r.summary.seconds = seconds;
  r.dual = std::move(dual);
  return r;
}

// The share of Params::cache_mb for rows as computed (KernelCache); the rest holds rows in the
// solver's order. The pair solver computes its rows straight into its own order
// (SolverOptions::rows_in_order) and needs none, unless the rows come from a distance matrix:
// then it gathers them and gets the 10 % every fit had before rows were computed in order (at
// N = 20,000, C = 10, σ = 0.5 and 200 MB, 10 % took a fit from 6.8 s with half and half to
// 4.2 s; measured without a distance matrix, before rows were computed in order). A C path needs
// none either: its fits pass the solver's order and rows from one to the next through the
// KernelCache (0.50-0.53 s for the bench's 20-value sweep, as fast as half and half with rows
// gathered). The LIBSVM path keeps rows of 2l entries in its order and was measured no faster with
// any split: half and half.
double computed_rows_share(const TrainingSet& set, const Params& p) {
  if (p.libsvm_path) return 0.5;
  return set.has_distances() ? 0.1 : 0.0;
}

FitResult fit_with(const TrainingSet& set, KernelCache& cache, const Params& params,
                   double computed_share, const DualSolution* warm) {
  const auto start = std::chrono::steady_clock::now();
  DualSolution dual;
  SolverOptions options;
  options.tolerance = params.tolerance;
  options.shrinking = params.shrinking;
  options.max_iterations = params.max_iterations;
  options.solver_order_cache_mb = params.cache_mb * (1 - computed_share);
  options.libsvm_path = params.libsvm_path;
  options.conjugate = params.conjugate;
  options.newton = params.newton;
  const SolverSummary s =
      solve_epsilon_svr(cache, set.data().y, params.c, params.epsilon, options, dual, warm);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return finish(set, params, std::move(dual), s, seconds);
}

FitResult fit_unchecked(const TrainingSet& set, const Params& params, const DualSolution* warm,
                        Workspace* workspace) {
  const auto start = std::chrono::steady_clock::now();
  const double share = computed_rows_share(set, params);
  KernelCache cache(set, params.kernel, params.cache_mb * share, workspace,
                    params.kernel_arithmetic);
  FitResult r = fit_with(set, cache, params, share, warm);
  r.summary.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

void require_fit_memory(const TrainingSet& set, const Params& params, std::size_t concurrent,
                        std::uint64_t kept_bytes) {
  const std::uint64_t need = fit_bytes(set.size(), set.dims(), params) * concurrent + kept_bytes;
  require_memory_beside_reserve(
      need,
      fmt::format("{} of {} rows with a {} MB kernel cache{}{}",
                  concurrent == 1 ? "an SVR fit" : fmt::format("{} SVR fits at once", concurrent),
                  set.size(), params.cache_mb, concurrent == 1 ? "" : " each",
                  kept_bytes == 0 ? std::string()
                                  : fmt::format(", and {} of solutions kept as warm starts",
                                                format_bytes(kept_bytes))),
      "A smaller kernel cache, fewer threads or fewer rows would fit.");
}

std::uint64_t fit_bytes(std::size_t rows, std::size_t dims, const Params& params) {
  const auto n = static_cast<std::uint64_t>(rows);
  const auto row_floats = params.libsvm_path ? 2 * n : n;  // the longest row the solver keeps
  // Every row a fit can cache: the whole matrix, or the budget; at least two rows per store.
  const double whole_matrix =
      4.0 * static_cast<double>(row_floats) * static_cast<double>(row_floats);
  const double budget = std::max(0.0, params.cache_mb) * double(1 << 20);
  const auto rows_bytes =
      static_cast<std::uint64_t>(std::min(whole_matrix, budget)) + 16 * row_floats;
  // Per sample: the features in the solver's order and in the model (2·8·(d+1)), and the
  // solver's arrays (the pair solver's twelve per-sample doubles, take_arrays in
  // pair_solver.cpp, with its flags, dual and order; the LIBSVM path's 2l-long arrays), 256
  // bytes at most.
  return rows_bytes + n * (16 * (static_cast<std::uint64_t>(dims) + 1) + 256);
}

void validate(const Params& p, const ParamNames& names) {
  require(std::isfinite(p.c) && p.c > 0, names.c, p.c, "a finite number > 0");
  if (p.kernel.type == KernelType::rbf)
    require(std::isfinite(p.kernel.gamma) && p.kernel.gamma > 0, names.gamma, p.kernel.gamma,
            "a finite number > 0 (σ = 1/√(2γ) > 0)");
  require(std::isfinite(p.epsilon) && p.epsilon >= 0, names.epsilon, p.epsilon,
          "a finite number ≥ 0");
  require(std::isfinite(p.tolerance) && p.tolerance > 0, names.tolerance, p.tolerance,
          "a finite number > 0");
  require(std::isfinite(p.cache_mb) && p.cache_mb >= 0, names.cache_mb, p.cache_mb,
          "a finite number ≥ 0");
  require(p.max_iterations >= 0, names.max_iterations, static_cast<double>(p.max_iterations),
          "≥ 0");
  require(p.kernel_arithmetic == KernelArithmetic::single ||
              p.kernel_arithmetic == KernelArithmetic::libsvm,
          names.kernel_arithmetic, static_cast<double>(p.kernel_arithmetic),
          "KernelArithmetic::single or KernelArithmetic::libsvm");
}

double Model::predict(const double* x) const noexcept {
  double sum = 0;
  const std::size_t n = coef.size();
  for (std::size_t i = 0; i < n; ++i)
    sum += coef[i] * kernel(support_vectors.data() + i * dims, x, dims);
  return sum - rho;
}

void Model::predict(std::span<const double> x, std::span<double> out, ThreadPool* pool) const {
  const std::size_t rows = out.size();
  if (x.size() != rows * dims)
    throw std::invalid_argument(
        fmt::format("predict: {} values are not {} rows of {} features", x.size(), rows, dims));
  constexpr std::size_t kChunk = 64;
  const std::size_t chunks = (rows + kChunk - 1) / kChunk;
  auto run = [&](std::size_t c) {
    const std::size_t end = std::min(rows, (c + 1) * kChunk);
    for (std::size_t i = c * kChunk; i < end; ++i) out[i] = predict(x.data() + i * dims);
  };
  if (pool != nullptr) {
    pool->parallel_for(chunks, run);
  } else {
    for (std::size_t c = 0; c < chunks; ++c) run(c);
  }
}

std::vector<double> Model::predict(const Data& data, ThreadPool* pool) const {
  if (data.cols != dims)
    throw std::invalid_argument(
        fmt::format("predict: data has {} features, the model {}", data.cols, dims));
  std::vector<double> out(data.rows);
  predict(data.x, out, pool);
  return out;
}

namespace {

// Σ_u b[u]·k[u] in kSumLanes running sums, term u in sum u mod kSumLanes, the sums then added
// pairwise: a fixed order (the same bits on every processor and thread count) whose sums are
// independent chains of adds (docs/svr.md, "Where the speed comes from").
constexpr std::size_t kSumLanes = 8;
static_assert(kSumLanes == 8, "lane_sum adds its eight sums pairwise by hand");

double lane_sum(const double* b, const float* k, std::size_t n) {
  double lane[kSumLanes] = {};
  std::size_t u = 0;
  for (; u + kSumLanes <= n; u += kSumLanes)
    for (std::size_t t = 0; t < kSumLanes; ++t) lane[t] += b[u + t] * static_cast<double>(k[u + t]);
  for (std::size_t t = 0; u + t < n; ++t) lane[t] += b[u + t] * static_cast<double>(k[u + t]);
  return ((lane[0] + lane[1]) + (lane[2] + lane[3])) + ((lane[4] + lane[5]) + (lane[6] + lane[7]));
}

}  // namespace

std::vector<double> path_predictions(const TrainingSet& set, std::span<const FitResult> path,
                                     const Data& data, std::span<const std::size_t> rows,
                                     KernelArithmetic arithmetic) {
  const std::size_t l = set.size(), models = path.size();
  if (data.cols != set.dims())
    throw std::invalid_argument(fmt::format(
        "path_predictions: data has {} features, the training set {}", data.cols, set.dims()));
  // The samples that are a support vector of some model, and each model's coefficient of each
  // of them (eq. 6: α⁺ − α⁻), model by model so that lane_sum reads them contiguously.
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < l; ++i)
    for (const FitResult& r : path)
      if (r.dual.alpha[i] != r.dual.alpha[i + l]) {
        used.push_back(i);
        break;
      }
  const std::size_t n_used = used.size();
  std::vector<double> beta(models * n_used);  // beta[m · n_used + u]
  for (std::size_t m = 0; m < models; ++m)
    for (std::size_t u = 0; u < n_used; ++u)
      beta[m * n_used + u] = path[m].dual.alpha[used[u]] - path[m].dual.alpha[used[u] + l];
  std::vector<double> out(rows.size() * models), f(models);
  const Kernel kernel = path.empty() ? Kernel{} : path.front().model.kernel;
  const std::size_t d = set.dims();
  // Linear: each model's primal weights w = Σ β_i·x_i, in double (float kernel values would
  // lose digits to the cancellation in Σ β_i·K_i at large C).
  std::vector<double> w;
  if (kernel.type == KernelType::linear) {
    w.assign(models * d, 0.0);
    for (std::size_t m = 0; m < models; ++m)
      for (std::size_t u = 0; u < n_used; ++u)
        for (std::size_t c = 0; c < d; ++c)
          w[m * d + c] += beta[m * n_used + u] * set.data().row(used[u])[c];
  }
  // RBF: the support vectors alone, feature-major (in float for the single arithmetic), so that
  // a row costs one kernel value per support vector rather than per training sample (a quarter
  // of them in a typical search). Each value is the float TrainingSet::kernel_row_of computes for
  // that sample in that arithmetic: the loops compute every entry from its own column alone.
  const bool in_float = kernel.type != KernelType::linear && arithmetic == KernelArithmetic::single;
  std::vector<double> xt, sq;
  std::vector<float> xt_f32, x_f32, k;
  if (kernel.type != KernelType::linear) {
    if (in_float) {
      xt_f32.resize(n_used * d);
      x_f32.resize(detail::kRowsAtOnce * d);
      for (std::size_t u = 0; u < n_used; ++u)
        for (std::size_t c = 0; c < d; ++c) xt_f32[c * n_used + u] = set.row_f32(used[u])[c];
    } else {
      xt.resize(n_used * d);
      sq.resize(n_used);
      for (std::size_t u = 0; u < n_used; ++u) {
        for (std::size_t c = 0; c < d; ++c) xt[c * n_used + u] = set.data().row(used[u])[c];
        sq[u] = set.squared_norm(used[u]);
      }
    }
    k.resize((in_float ? detail::kRowsAtOnce : 1) * n_used);
  }
  const detail::Loops& loops = detail::loops();
  for (const std::size_t row : rows)
    if (row >= data.rows)
      throw std::invalid_argument("path_predictions: a row index is out of range");
  // In float, kRowsAtOnce held-out rows at a time, so that each support vector's features are
  // read once for all of them (loops.hpp, rbf_rows): the same floats as row by row.
  const std::size_t at_once = in_float ? detail::kRowsAtOnce : 1;
  for (std::size_t r0 = 0; r0 < rows.size(); r0 += at_once) {
    const std::size_t m = std::min(at_once, rows.size() - r0);
    if (in_float && n_used > 0) {
      for (std::size_t r = 0; r < m; ++r)
        for (std::size_t c = 0; c < d; ++c)
          x_f32[r * d + c] = static_cast<float>(data.row(rows[r0 + r])[c]);
      loops.rbf_rows(x_f32.data(), m, xt_f32.data(), n_used, n_used, d, kernel.gamma, k.data(),
                     n_used);
    }
    for (std::size_t r = 0; r < m; ++r) {
      const double* x = data.row(rows[r0 + r]);
      std::fill(f.begin(), f.end(), 0.0);
      if (kernel.type == KernelType::linear) {
        for (std::size_t j = 0; j < models; ++j)
          for (std::size_t c = 0; c < d; ++c) f[j] += w[j * d + c] * x[c];
      } else if (n_used > 0) {
        if (!in_float) {
          double sq_x = 0;  // summed in feature order, as the set's own norms
          for (std::size_t c = 0; c < d; ++c) sq_x += x[c] * x[c];
          loops.libsvm_rbf_row(x, sq_x, xt.data(), n_used, sq.data(), n_used, d, kernel.gamma,
                               k.data());
        }
        const float* kr = k.data() + (in_float ? r * n_used : 0);
        for (std::size_t j = 0; j < models; ++j)
          f[j] = lane_sum(beta.data() + j * n_used, kr, n_used);
      }
      for (std::size_t j = 0; j < models; ++j)
        out[(r0 + r) * models + j] = f[j] - path[j].model.rho;
    }
  }
  return out;
}

std::vector<double> path_squared_errors(const TrainingSet& set, std::span<const FitResult> path,
                                        const Data& data, std::span<const std::size_t> rows,
                                        KernelArithmetic arithmetic) {
  const std::vector<double> f = path_predictions(set, path, data, rows, arithmetic);
  const std::size_t models = path.size();
  std::vector<double> sse(models, 0.0);
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t m = 0; m < models; ++m) {
      const double e = f[r * models + m] - data.y[rows[r]];
      sse[m] += e * e;
    }
  return sse;
}

FitResult fit(const TrainingSet& set, const Params& params, const DualSolution* warm,
              Workspace* workspace) {
  validate(params);
  require_fit_memory(set, params, 1);
  return fit_unchecked(set, params, warm, workspace);
}

std::vector<FitResult> fit_batch(const TrainingSet& set, std::span<const Params> params,
                                 ThreadPool& pool) {
  for (const auto& p : params) validate(p);
  // Handed out longest first (LPT), so that the threads finish together: a fit's length grows
  // with C and with γ (a narrower kernel), so larger C first, then larger γ. Each fit runs on one
  // thread, so the order never changes a result.
  std::vector<std::size_t> order(params.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (params[a].c != params[b].c) return params[a].c > params[b].c;
    return params[a].kernel.gamma > params[b].kernel.gamma;
  });
  if (!params.empty()) {
    // Every thread may be running the largest fit at once.
    const auto largest = std::max_element(params.begin(), params.end(), [&](auto& a, auto& b) {
      return fit_bytes(set.size(), set.dims(), a) < fit_bytes(set.size(), set.dims(), b);
    });
    require_fit_memory(set, *largest, std::min<std::size_t>(pool.size(), params.size()));
  }
  std::vector<FitResult> out(params.size());
  WorkspacePool workspaces;  // one per fit running at once
  pool.parallel_for(params.size(), [&](std::size_t k) {
    const WorkspacePool::Lease workspace = workspaces.borrow();
    out[order[k]] = fit_unchecked(set, params[order[k]], nullptr, workspace.get());
  });
  return out;
}

void validate_c_values(std::span<const double> c_values, const std::string& name) {
  if (c_values.empty()) throw OptionError(name, "needs at least one value");
  for (const double c : c_values)
    if (!(std::isfinite(c) && c > 0))
      throw OptionError(name, fmt::format("every value must be a finite number > 0 (got {})", c));
}

std::vector<FitResult> fit_c_path(const TrainingSet& set, const Params& base,
                                  std::span<const double> c_values, Workspace* workspace,
                                  const DualSolution* warm) {
  validate(base);
  require_fit_memory(set, base, 1);
  std::vector<FitResult> out;
  out.reserve(c_values.size());
  const double share = computed_rows_share(set, base);
  // One cache for the path: each fit leaves its sample order and rows in the cache's workspace
  // for the next.
  KernelCache cache(set, base.kernel, base.cache_mb * share, workspace, base.kernel_arithmetic);
  for (double c : c_values) {
    Params p = base;
    p.c = c;
    validate(p);
    out.push_back(fit_with(set, cache, p, share, out.empty() ? warm : &out.back().dual));
  }
  return out;
}

std::string to_json(const Model& m) {
  ojson doc;
  doc["format"] = "fogdrift-svr";
  doc["version"] = kModelFormatVersion;
  doc["kernel"] = std::string(to_string(m.kernel.type));
  if (m.kernel.type == KernelType::rbf) {
    doc["gamma"] = m.kernel.gamma;
    doc["sigma"] = m.kernel.sigma();
  }
  doc["dims"] = m.dims;
  doc["rho"] = m.rho;
  doc["coef"] = m.coef;
  ojson svs = ojson::array();
  for (std::size_t i = 0; i < m.size(); ++i) {
    svs.push_back(std::vector<double>(m.support_vectors.begin() + i * m.dims,
                                      m.support_vectors.begin() + (i + 1) * m.dims));
  }
  doc["support_vectors"] = std::move(svs);
  return doc.dump(1) + "\n";
}

Model model_from_json(const std::string& text, const std::string& source) {
  check_json_nesting(source, text);
  ojson doc;
  try {
    doc = ojson::parse(text);
  } catch (const ojson::parse_error& e) {
    throw_json_syntax_error(source, text, e.byte, e.what());
  } catch (const ojson::out_of_range& e) {
    throw_json_number_error(source, text, e.what());
  }
  auto fail = [&](const std::string& where, const std::string& rule) -> void {
    throw InputError(source, 0, 0, fmt::format("{}: {}", where, rule));
  };
  if (!doc.is_object()) fail("(top level)", "must be a JSON object");
  if (!doc.contains("format") || doc["format"] != "fogdrift-svr")
    fail("format", "must be \"fogdrift-svr\" (is this an SVR model written by fogdrift?)");
  if (!doc.contains("version") || !doc["version"].is_number_integer())
    fail("version", "required integer field is missing");
  int version = 0;
  try {
    version = fogdrift::detail::whole_number<int>(doc["version"]);
  } catch (const ojson::exception&) {
    fail("version", fmt::format("{} is not a format version", doc["version"].dump()));
  }
  if (version != kModelFormatVersion)
    fail("version",
         fmt::format("model format version {} is not supported (this fogdrift reads "
                     "version {}{})",
                     version, kModelFormatVersion,
                     version > kModelFormatVersion ? "; written by a newer fogdrift" : ""));
  const std::set<std::string> known{"format", "version", "kernel", "gamma",          "sigma",
                                    "dims",   "rho",     "coef",   "support_vectors"};
  for (const auto& [key, value] : doc.items())
    if (!known.count(key)) fail(key, "unknown field");
  Model m;
  try {
    const std::string kernel = doc.at("kernel").get<std::string>();
    if (kernel == "rbf") {
      m.kernel = Kernel::rbf_gamma(doc.at("gamma").get<double>());
      if (!(m.kernel.gamma > 0) || !std::isfinite(m.kernel.gamma)) fail("gamma", "must be > 0");
    } else if (kernel == "linear") {
      m.kernel = Kernel::linear();
    } else {
      fail("kernel", "must be \"rbf\" or \"linear\"");
    }
    m.dims = fogdrift::detail::whole_number<std::size_t>(doc.at("dims"));
    m.rho = doc.at("rho").get<double>();
    m.coef = doc.at("coef").get<std::vector<double>>();
    const auto& svs = doc.at("support_vectors");
    if (!svs.is_array() || svs.size() != m.coef.size())
      fail("support_vectors",
           fmt::format("must hold one vector per coefficient ({})", m.coef.size()));
    for (std::size_t i = 0; i < svs.size(); ++i) {
      const auto v = svs[i].get<std::vector<double>>();
      if (v.size() != m.dims)
        fail(fmt::format("support_vectors[{}]", i),
             fmt::format("has {} values, dims is {}", v.size(), m.dims));
      m.support_vectors.insert(m.support_vectors.end(), v.begin(), v.end());
    }
  } catch (const ojson::exception& e) {
    fail("(model)", fmt::format("missing or mistyped field ({})", json_error_text(e)));
  }
  for (double v : m.coef)
    if (!std::isfinite(v)) fail("coef", "must be finite numbers");
  if (!std::isfinite(m.rho)) fail("rho", "must be a finite number");
  return m;
}

void save_model(const Model& model, const std::filesystem::path& path) {
  write_text_atomically(path, to_json(model));
}

Model load_model(const std::filesystem::path& path) {
  return model_from_json(read_text_file(path), path.string());
}

}  // namespace fogdrift::svr
