// The ε-SVR engine against LIBSVM 3.24 (libsvm-dev) as oracle, on five data sets and a grid of
// C, σ and ε; warm starts, thread-count independence, edge cases, model files.
#include "fogdrift/svr/svr.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/libsvm_format.hpp"
#include "svr/datasets.hpp"
#include "svr/libsvm_oracle.hpp"
#include "test_util.hpp"

namespace fogdrift::svr {
namespace {

using testing::dual_objective;
using testing::libsvm_train;
using testing::OracleFit;

double sd(const std::vector<double>& v) {
  double m = 0, s = 0;
  for (double x : v) m += x;
  m /= static_cast<double>(v.size());
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / static_cast<double>(v.size()));
}

Data diabetes() {
  // scikit-learn's diabetes data (442 × 10), written by tests/data/svr/make_diabetes.py.
  Data d = read_libsvm_data(fogdrift::test::data_path("svr/diabetes.libsvm"));
  testing::standardise(d);
  return d;
}

Data duplicated() {
  // Every sample three times: ties everywhere in the working-set selection.
  const Data base = testing::smooth(100, 3, 0.1, 7);
  Data d;
  d.cols = base.cols;
  for (int rep = 0; rep < 3; ++rep) {
    d.x.insert(d.x.end(), base.x.begin(), base.x.end());
    d.y.insert(d.y.end(), base.y.begin(), base.y.end());
  }
  d.rows = d.y.size();
  return d;
}

struct NamedData {
  std::string name;
  Data data;
  bool unique_optimum = true;  // false when samples repeat
};

std::vector<NamedData> datasets() {
  return {{"smooth", testing::smooth(250, 3, 0.0, 1)},
          {"noisy", testing::smooth(300, 4, 0.3, 2)},
          {"duplicated", duplicated(), false},
          {"diabetes", diabetes()},
          {"startup_like", testing::startup_like(540, 3)}};
}

double objective_of(const Data& d, const Params& p, const FitResult& r) {
  std::vector<double> beta(d.rows);
  for (std::size_t i = 0; i < d.rows; ++i) beta[i] = r.dual.alpha[i] - r.dual.alpha[i + d.rows];
  return dual_objective(d, p.kernel, p.epsilon, beta);
}

double worst_prediction_difference(const Data& d, const Model& m, const OracleFit& ref) {
  double worst = 0;
  for (std::size_t i = 0; i < d.rows; ++i)
    worst = std::max(worst, std::fabs(m.predict(d.row(i)) - ref.predict(d.row(i), d.cols)));
  return worst;
}

// Compares one fit with LIBSVM's; returns the relative objective difference.
//  * The solver that follows LIBSVM's path (Params::libsvm_path) must give LIBSVM's model: the
//    objective to 1e-3 relative, predictions to 1e-3 of the target's SD, nSV within 1 %.
//  * The pair solver (the default) takes another path to the same optimum and stops by the same
//    rule, so at the same tolerance its objective agrees to 1e-3 and its final violation is
//    below the tolerance; its predictions then differ from LIBSVM's by what the tolerance
//    allows either solution. At a tight tolerance (1e-7 for both), where both are at the
//    optimum, its predictions must agree to 1e-3 of the target's SD and nSV within 1 %.
double compare_with_libsvm(const Data& d, Params p, const std::string& label,
                           bool unique_optimum = true, bool tight_check = true) {
  SCOPED_TRACE(label);
  const TrainingSet set(d);
  const double tol = 1e-3 * std::max(sd(d.y), 1e-12);
  OracleFit ref;
  libsvm_train(d, p, ref);
  const double obj_ref = dual_objective(d, p.kernel, p.epsilon, ref.beta);
  const double scale = std::max(1e-12, std::fabs(obj_ref));
  auto check_nsv = [&](const FitResult& r, const OracleFit& o) {
    const int n_sv = static_cast<int>(r.summary.n_sv);
    EXPECT_LE(std::abs(n_sv - o.n_sv), std::max(2, o.n_sv / 100))
        << "nSV ours " << n_sv << " LIBSVM " << o.n_sv;
  };

  p.libsvm_path = true;
  const FitResult exact = fit(set, p);
  const double obj_exact = objective_of(d, p, exact);
  const double rel = std::fabs(obj_exact - obj_ref) / scale;
  EXPECT_LE(rel, 1e-3) << "ours " << obj_exact << " LIBSVM " << obj_ref;
  // The solver's own objective is the same quantity from its gradient, with the kernel in float
  // as LIBSVM keeps it; at large C the two differ by a few parts in 10⁴.
  EXPECT_NEAR(exact.summary.solver.objective, obj_exact,
              1e-3 * std::max(1.0, std::fabs(obj_exact)));
  EXPECT_LE(worst_prediction_difference(d, exact.model, ref), tol);
  check_nsv(exact, ref);
  EXPECT_EQ(exact.summary.solver.status, SolverStatus::optimal);

  p.libsvm_path = false;
  const FitResult pairs = fit(set, p);
  const double obj_pairs = objective_of(d, p, pairs);
  EXPECT_LE(std::fabs(obj_pairs - obj_ref) / scale, 1e-3)
      << "pairs " << obj_pairs << " LIBSVM " << obj_ref;
  EXPECT_NEAR(pairs.summary.solver.objective, obj_pairs,
              1e-3 * std::max(1.0, std::fabs(obj_pairs)));
  EXPECT_LT(pairs.summary.solver.max_violation, p.tolerance);
  EXPECT_EQ(pairs.summary.solver.status, SolverStatus::optimal);

  if (!tight_check) return std::max(rel, std::fabs(obj_pairs - obj_ref) / scale);
  p.tolerance = 1e-7;
  OracleFit tight_ref;
  libsvm_train(d, p, tight_ref);
  const FitResult tight = fit(set, p);
  EXPECT_LE(worst_prediction_difference(d, tight.model, tight_ref), tol) << "tight tolerance";
  // With repeated samples only the sum of their coefficients is determined, not how it is split.
  if (unique_optimum) check_nsv(tight, tight_ref);
  return std::max(rel, std::fabs(obj_pairs - obj_ref) / scale);
}

TEST(SvrVsLibsvm, AgreesOnFiveDataSetsOverAGridOfCSigmaAndEpsilon) {
  double worst = 0;
  int fits = 0;
  for (const auto& [name, data, unique] : datasets()) {
    for (double c : {0.01, 1.0, 100.0, 1000.0}) {
      for (double sigma : {0.5, 2.0}) {
        for (double eps : {0.05, 0.2}) {
          Params p;
          p.kernel = Kernel::rbf_sigma(sigma);
          p.c = c;
          p.epsilon = eps;
          worst = std::max(worst, compare_with_libsvm(data, p,
                                                      name + " C=" + std::to_string(c) +
                                                          " sigma=" + std::to_string(sigma) +
                                                          " eps=" + std::to_string(eps),
                                                      unique, c <= 100 && eps > 0.1));
          ++fits;
        }
      }
    }
  }
  EXPECT_EQ(fits, 80);
  RecordProperty("worst_relative_objective_difference", std::to_string(worst));
}

TEST(SvrVsLibsvm, WithoutShrinkingAndWithTheLinearKernel) {
  const Data d = testing::smooth(200, 3, 0.2, 4);
  Params p;
  p.kernel = Kernel::rbf_gamma(0.7);
  p.c = 10;
  p.shrinking = false;
  compare_with_libsvm(d, p, "no shrinking");
  p.kernel = Kernel::linear();
  p.c = 1;
  compare_with_libsvm(d, p, "linear");
}

TEST(SvrVsLibsvm, EdgeCases) {
  Params p;
  p.kernel = Kernel::rbf_sigma(1.0);
  {  // one sample: no pair to optimise, α = 0, ρ from the bounds
    Data d{1, 2, {0.5, -0.5}, {0.3}, {}};
    compare_with_libsvm(d, p, "one sample");
  }
  {  // every target inside the tube: no support vectors
    Data d = testing::smooth(50, 2, 0.0, 5);
    for (double& y : d.y) y *= 0.01;
    p.epsilon = 0.5;
    const FitResult r = fit(TrainingSet(d), p);
    EXPECT_EQ(r.summary.n_sv, 0u);
    EXPECT_EQ(r.summary.solver.objective, 0.0);
    compare_with_libsvm(d, p, "inside the tube");
    p.epsilon = 0.1;
  }
  {  // tiny C: every support vector at the bound
    const Data d = testing::smooth(120, 3, 0.5, 6);
    p.c = 1e-4;
    const FitResult r = fit(TrainingSet(d), p);
    EXPECT_EQ(r.summary.n_bsv, r.summary.n_sv);
    compare_with_libsvm(d, p, "all at bound");
    p.c = 1;
  }
  {  // a constant feature
    Data d = testing::smooth(150, 3, 0.1, 8);
    for (std::size_t i = 0; i < d.rows; ++i) d.x[i * 3 + 1] = 4.0;
    compare_with_libsvm(d, p, "constant feature");
  }
}

TEST(SvrWarmStart, APathsTestErrorsArePredictionsErrors) {
  const Data d = testing::startup_like(600, 5);
  std::vector<std::size_t> train_rows, test_rows;
  for (std::size_t i = 0; i < d.rows; ++i) (i % 3 == 0 ? test_rows : train_rows).push_back(i);
  const TrainingSet set(d.subset(train_rows));
  for (const Kernel kernel : {Kernel::rbf_sigma(1.0), Kernel::linear()}) {
    Params base;
    base.kernel = kernel;
    const std::vector<double> cs{0.5, 5, 50};
    const auto path = fit_c_path(set, base, cs);
    const std::vector<double> sse = path_squared_errors(set, path, d, test_rows);
    const std::vector<double> f = path_predictions(set, path, d, test_rows);
    ASSERT_EQ(sse.size(), cs.size());
    ASSERT_EQ(f.size(), cs.size() * test_rows.size());
    // RBF: float kernel values, as the solver's; linear: primal weights in double.
    const double tolerance = kernel.type == KernelType::linear ? 1e-9 : 1e-5;
    for (std::size_t k = 0; k < cs.size(); ++k) {
      double expected = 0, from_predictions = 0;
      for (std::size_t r = 0; r < test_rows.size(); ++r) {
        const double predicted = path[k].model.predict(d.row(test_rows[r]));
        EXPECT_NEAR(f[r * cs.size() + k], predicted, tolerance * (1 + std::abs(predicted)));
        const double e = predicted - d.y[test_rows[r]];
        expected += e * e;
        const double e_path = f[r * cs.size() + k] - d.y[test_rows[r]];
        from_predictions += e_path * e_path;
      }
      EXPECT_NEAR(sse[k], expected, tolerance * expected) << "C=" << cs[k];
      EXPECT_EQ(sse[k], from_predictions) << "C=" << cs[k];  // the same sums, in the same order
    }
    if (kernel.type == KernelType::linear) continue;
    // RBF: each kernel value is the float of the training set's own row for that point,
    // though only the support vectors' values are computed; the u-th sample that is a support
    // vector of some model goes into running sum u mod 8, and the eight sums are added pairwise.
    std::vector<float> row(set.size());
    const std::size_t l = set.size();
    for (std::size_t r = 0; r < test_rows.size(); ++r) {
      set.kernel_row_of(kernel, d.row(test_rows[r]), row.data());
      for (std::size_t k = 0; k < cs.size(); ++k) {
        double lane[8] = {};
        std::size_t u = 0;
        for (std::size_t i = 0; i < l; ++i) {
          bool used = false;
          for (const FitResult& each : path)
            used = used || each.dual.alpha[i] != each.dual.alpha[i + l];
          if (!used) continue;
          const double beta = path[k].dual.alpha[i] - path[k].dual.alpha[i + l];
          lane[u++ % 8] += beta * static_cast<double>(row[i]);
        }
        const double f_k = ((lane[0] + lane[1]) + (lane[2] + lane[3])) +
                           ((lane[4] + lane[5]) + (lane[6] + lane[7]));
        EXPECT_EQ(f[r * cs.size() + k], f_k - path[k].model.rho) << "C=" << cs[k] << " row " << r;
      }
    }
  }
  const std::vector<std::size_t> outside{d.rows};
  EXPECT_THROW(
      path_squared_errors(set, fit_c_path(set, Params{}, std::vector<double>{1.0}), d, outside),
      std::invalid_argument);
}

TEST(SvrWarmStart, CPathMatchesColdFitsAndReusesTheGradient) {
  const Data d = testing::startup_like(720, 5);
  const TrainingSet set(d);
  Params base;
  base.kernel = Kernel::rbf_sigma(1.0);
  const std::vector<double> cs{0.1, 0.3, 1, 3, 10, 30, 100};
  const auto path = fit_c_path(set, base, cs);
  ASSERT_EQ(path.size(), cs.size());
  std::int64_t warm_iterations = 0, cold_iterations = 0, warm_rows = 0, cold_rows = 0;
  for (std::size_t k = 0; k < cs.size(); ++k) {
    Params p = base;
    p.c = cs[k];
    const FitResult cold = fit(set, p);
    const double a = path[k].summary.solver.objective, b = cold.summary.solver.objective;
    EXPECT_LE(std::fabs(a - b) / std::fabs(b), 1e-3) << "C=" << cs[k];
    // Both stop within the tolerance (1e-3) of the optimum from different starts, so their
    // predictions differ by a few tolerances at most.
    for (std::size_t i = 0; i < d.rows; i += 7)
      EXPECT_NEAR(path[k].model.predict(d.row(i)), cold.model.predict(d.row(i)), 5e-3);
    EXPECT_EQ(path[k].summary.solver.warm_started, k > 0);
    EXPECT_EQ(path[k].summary.solver.gradient_reused, k > 0);
    if (k > 0) {
      warm_iterations += path[k].summary.solver.iterations;
      cold_iterations += cold.summary.solver.iterations;
      warm_rows += path[k].summary.solver.kernel_rows;
      cold_rows += cold.summary.solver.kernel_rows;
    }
  }
  EXPECT_LT(warm_iterations, cold_iterations);
  // Each fit of the path starts in the order, and with the rows, the last one left.
  EXPECT_LT(warm_rows * 4, cold_rows)
      << warm_rows << " rows computed on the path, " << cold_rows << " cold";

  // With a tight tolerance, warm and cold reach the same optimum.
  base.tolerance = 1e-6;
  const std::vector<double> two{3, 30};
  const auto tight = fit_c_path(set, base, two);
  base.c = 30;
  const FitResult cold = fit(set, base);
  for (std::size_t i = 0; i < d.rows; i += 7)
    EXPECT_NEAR(tight[1].model.predict(d.row(i)), cold.model.predict(d.row(i)), 1e-4);
}

TEST(SvrWarmStart, FromAnotherKernelRebuildsTheGradient) {
  const Data d = testing::smooth(200, 3, 0.2, 9);
  const TrainingSet set(d);
  Params p;
  p.kernel = Kernel::rbf_sigma(1.0);
  p.c = 5;
  const FitResult first = fit(set, p);
  p.kernel = Kernel::rbf_sigma(0.7);
  const FitResult warm = fit(set, p, &first.dual);
  const FitResult cold = fit(set, p);
  EXPECT_TRUE(warm.summary.solver.warm_started);
  EXPECT_FALSE(warm.summary.solver.gradient_reused);
  EXPECT_LE(std::fabs(warm.summary.solver.objective - cold.summary.solver.objective) /
                std::fabs(cold.summary.solver.objective),
            1e-3);
}

TEST(SvrWarmStart, EitherSolverStartsFromTheOthersSolution) {
  // Both solvers export LIBSVM's layout (α⁺, α⁻, G, Ḡ), so a search may mix them.
  const Data d = testing::startup_like(540, 7);
  const TrainingSet set(d);
  Params p;
  p.kernel = Kernel::rbf_sigma(1.0);
  p.c = 3;
  for (bool first_exact : {true, false}) {
    SCOPED_TRACE(first_exact ? "LIBSVM path, then pairs" : "pairs, then LIBSVM path");
    p.libsvm_path = first_exact;
    p.c = 3;
    const FitResult first = fit(set, p);
    p.libsvm_path = !first_exact;
    p.c = 4;
    const FitResult warm = fit(set, p, &first.dual);
    const FitResult cold = fit(set, p);
    EXPECT_TRUE(warm.summary.solver.gradient_reused);
    EXPECT_LT(warm.summary.solver.iterations, cold.summary.solver.iterations);
    EXPECT_LE(std::fabs(warm.summary.solver.objective - cold.summary.solver.objective) /
                  std::fabs(cold.summary.solver.objective),
              1e-3);
    EXPECT_LT(warm.summary.solver.max_violation, p.tolerance);
  }
}

// A solver option that changes the path, not the rule: fits `p` with the option off and on
// (`flag` points into p), checks the second meets the same tolerance with the same objective to
// far below it, and returns both fits for the option's own checks.
std::pair<FitResult, FitResult> off_and_on(const Data& d, const TrainingSet& set, Params p,
                                           bool Params::*flag) {
  p.*flag = false;
  FitResult off = fit(set, p);
  p.*flag = true;
  FitResult on = fit(set, p);
  EXPECT_LT(on.summary.solver.max_violation, p.tolerance);
  EXPECT_EQ(on.summary.solver.status, SolverStatus::optimal);
  const double obj_off = objective_of(d, p, off), obj_on = objective_of(d, p, on);
  EXPECT_LE(std::fabs(obj_on - obj_off), 1e-4 * std::fabs(obj_off));
  // The solver's running gradient stays the gradient of its α: the objective it reports from it
  // matches the one recomputed from the model.
  EXPECT_NEAR(on.summary.solver.objective, obj_on, 1e-3 * std::fabs(obj_on));
  return {std::move(off), std::move(on)};
}

// Conjugate steps (SolverOptions::conjugate): at large C the iterations fall by a third or more
// (about half on the benchmark data). Newton steps are off here, to see the conjugate steps
// alone.
TEST(SvrConjugate, FewerIterationsAtLargeCSameOptimum) {
  const Data d = testing::startup_like(1500, 3);
  const TrainingSet set(d);
  for (double c : {10.0, 100.0, 1000.0}) {
    SCOPED_TRACE("C=" + std::to_string(c));
    Params p;
    p.kernel = Kernel::rbf_sigma(1.0);
    p.c = c;
    p.newton = false;
    const auto [plain, conj] = off_and_on(d, set, p, &Params::conjugate);
    EXPECT_EQ(plain.summary.solver.conjugate_steps, 0);
    EXPECT_GT(conj.summary.solver.conjugate_steps, conj.summary.solver.iterations / 2);
    EXPECT_LT(conj.summary.solver.iterations, 2 * plain.summary.solver.iterations / 3);
  }
}

// Newton steps on the free set (SolverOptions::newton): where SMO steps take many passes over the
// samples (large C, a wide kernel: the paper's search ends there) the iterations fall by half or
// more. At small C the fit converges before the first Newton step is due.
TEST(SvrNewton, FewerIterationsAtLargeCSameOptimum) {
  const Data d = testing::startup_like(1500, 3);
  const TrainingSet set(d);
  for (double c : {1.0, 100.0, 1000.0}) {
    SCOPED_TRACE("C=" + std::to_string(c));
    Params p;
    p.kernel = Kernel::rbf_sigma(3.0);
    p.c = c;
    const auto [plain, newton] = off_and_on(d, set, p, &Params::newton);
    EXPECT_EQ(plain.summary.solver.newton_steps, 0);
    if (c >= 100) {
      EXPECT_GT(newton.summary.solver.newton_steps, 0);
      EXPECT_LT(newton.summary.solver.iterations, plain.summary.solver.iterations / 2);
    }
  }
}

TEST(SvrBatch, ResultsDoNotDependOnTheThreadCount) {
  const Data d = testing::startup_like(360, 6);
  const TrainingSet set(d);
  std::vector<Params> grid;
  for (double c : {0.5, 5.0, 50.0})
    for (double sigma : {0.7, 1.5}) {
      Params p;
      p.kernel = Kernel::rbf_sigma(sigma);
      p.c = c;
      grid.push_back(p);
    }
  ThreadPool one(1), two(2);
  const auto a = fit_batch(set, grid, one);
  const auto b = fit_batch(set, grid, two);
  ASSERT_EQ(a.size(), grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k) {
    EXPECT_EQ(a[k].model.coef, b[k].model.coef);
    EXPECT_EQ(a[k].model.rho, b[k].model.rho);
    EXPECT_EQ(a[k].summary.solver.iterations, b[k].summary.solver.iterations);
  }
}

TEST(SvrCache, ASmallCacheGivesTheSameModel) {
  const Data d = testing::smooth(400, 3, 0.2, 10);
  const TrainingSet set(d);
  Params p;
  p.c = 10;
  const FitResult big = fit(set, p);
  p.cache_mb = 0;  // two rows in each cache: every other row is recomputed
  const FitResult tiny = fit(set, p);
  EXPECT_EQ(big.model.coef, tiny.model.coef);
  EXPECT_EQ(big.model.rho, tiny.model.rho);
  EXPECT_GT(tiny.summary.solver.kernel_rows, big.summary.solver.kernel_rows);
}

TEST(SvrModel, JsonAndLibsvmFilesRoundTripExactly) {
  const Data d = testing::smooth(150, 3, 0.2, 11);
  Params p;
  p.kernel = Kernel::rbf_sigma(0.8);
  p.c = 3;
  const Model m = fit(TrainingSet(d), p).model;
  fogdrift::test::TempDir dir;
  save_model(m, dir.path() / "m.json");
  write_libsvm_model(m, dir.path() / "m.model");
  for (const Model& back :
       {load_model(dir.path() / "m.json"), read_libsvm_model(dir.path() / "m.model"),
        read_any_model(dir.path() / "m.json"), read_any_model(dir.path() / "m.model")}) {
    EXPECT_EQ(back.kernel, m.kernel);
    EXPECT_EQ(back.rho, m.rho);
    EXPECT_EQ(back.coef, m.coef);
    EXPECT_EQ(back.support_vectors, m.support_vectors);
  }
  // LIBSVM itself reads fogdrift's model file and predicts the same numbers.
  svm_model* lm = svm_load_model((dir.path() / "m.model").c_str());
  ASSERT_NE(lm, nullptr);
  for (std::size_t i = 0; i < d.rows; i += 5) {
    svm_node x[4] = {{1, d.row(i)[0]}, {2, d.row(i)[1]}, {3, d.row(i)[2]}, {-1, 0}};
    EXPECT_EQ(svm_predict(lm, x), m.predict(d.row(i)));
  }
  svm_free_and_destroy_model(&lm);
}

TEST(SvrModel, RejectsAnotherFormatVersionAndBadFields) {
  auto message = [](const std::string& text) {
    try {
      model_from_json(text, "m.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(R"({"format":"fogdrift-svr","version":2})"),
            "m.json: version: model format version 2 is not supported (this fogdrift reads "
            "version 1; written by a newer fogdrift)");
  EXPECT_EQ(message(R"({"format":"other"})"),
            "m.json: format: must be \"fogdrift-svr\" (is this an SVR model written by fogdrift?)");
  EXPECT_EQ(message(R"({"format":"fogdrift-svr","version":1,"kernel":"rbf","gamma":1,"dims":1,)"
                    R"("rho":0,"coef":[1],"support_vectors":[[1,2]]})"),
            "m.json: support_vectors[0]: has 2 values, dims is 1");
  EXPECT_EQ(message(R"({"format":"fogdrift-svr","version":1,"extra":1})"),
            "m.json: extra: unknown field");
  EXPECT_EQ(message("{\"format\": \n nope}").substr(0, 61),
            "m.json:2:3: invalid JSON: syntax error while parsing value - ");
}

TEST(SvrParams, ValidationNamesTheOption) {
  auto message = [](Params p) {
    try {
      validate(p, ParamNames{"-c", "-g", "-p", "-e", "-m", "--max-iterations"});
    } catch (const OptionError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Params p;
  EXPECT_EQ(message(p), "no error");
  p.c = 0;
  EXPECT_EQ(message(p), "option -c: must be a finite number > 0 (got 0)");
  p = Params{};
  p.kernel.gamma = -1;
  EXPECT_EQ(message(p), "option -g: must be a finite number > 0 (σ = 1/√(2γ) > 0) (got -1)");
  p = Params{};
  p.epsilon = -0.1;
  EXPECT_EQ(message(p), "option -p: must be a finite number ≥ 0 (got -0.1)");
  p = Params{};
  p.tolerance = std::nan("");
  EXPECT_EQ(message(p), "option -e: must be a finite number > 0 (got nan)");
  p = Params{};
  p.kernel_arithmetic = static_cast<KernelArithmetic>(7);
  EXPECT_EQ(message(p),
            "option kernel_arithmetic: must be KernelArithmetic::single or "
            "KernelArithmetic::libsvm (got 7)");
}

TEST(SvrData, RejectsNonFiniteValuesNamingTheSample) {
  Data d{2, 2, {1, 2, 3, std::numeric_limits<double>::infinity()}, {0, 1}, {}};
  try {
    TrainingSet set(d);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "training data:2: sample 2: feature 2 is inf");
  }
  EXPECT_THROW(TrainingSet(Data{}), InputError);
}

TEST(SvrData, RejectsWeightsThatAreNotPositiveOrNotOnePerSample) {
  auto message = [](std::vector<double> weight) {
    Data d = testing::smooth(3, 2, 0.1, 1);
    d.weight = std::move(weight);
    try {
      TrainingSet set(d);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({1, 0, 1}),
            "training data:2: sample 2: weight is 0; weights must be finite and > 0 (leave out "
            "samples of weight 0)");
  EXPECT_EQ(message({1, 1, -2}),
            "training data:3: sample 3: weight is -2; weights must be finite and > 0 (leave out "
            "samples of weight 0)");
  EXPECT_EQ(message({std::nan(""), 1, 1}),
            "training data:1: sample 1: weight is nan; weights must be finite and > 0 (leave out "
            "samples of weight 0)");
  EXPECT_EQ(message({1, 1}), "training data: 3 samples need 3 weights (or none), got 2");
  EXPECT_EQ(message({}), "no error");
}

// Sample weights bound sample i's variables by C·weight_i (LIBSVM's and scikit-learn's weights).
TEST(SvrWeights, EqualWeightsAreALargerC) {
  const Data d = testing::startup_like(400, 3);
  Data weighted = d;
  weighted.weight.assign(d.rows, 4.0);
  const TrainingSet plain_set(d), weighted_set(weighted);
  for (const bool libsvm_path : {false, true}) {
    Params p;
    p.kernel = Kernel::rbf_sigma(1.0);
    p.libsvm_path = libsvm_path;
    p.c = 2.5;
    const FitResult w = fit(weighted_set, p);
    p.c = 10;  // 2.5 · 4, exactly
    const FitResult c = fit(plain_set, p);
    EXPECT_EQ(w.model.coef, c.model.coef) << (libsvm_path ? "LIBSVM path" : "pairs");
    EXPECT_EQ(w.model.rho, c.model.rho);
    EXPECT_EQ(w.summary.n_bsv, c.summary.n_bsv);
    EXPECT_DOUBLE_EQ(w.summary.nu, c.summary.nu);  // ν is relative to C·Σweight
  }
}

TEST(SvrWeights, AWeightOfTwoActsAsTheSampleTwice) {
  // Two copies of a sample have two pairs of variables bounded by C, one sample of weight 2 one
  // pair bounded by 2C: the same set of feasible β, so the same optimum. Both solvers, a tight
  // tolerance, C large enough that many weighted samples reach their bound.
  const Data d = testing::smooth(240, 3, 0.2, 6);
  Data twice = d, weighted = d;
  weighted.weight.assign(d.rows, 1.0);
  for (std::size_t i = 0; i < d.rows; i += 3) {
    weighted.weight[i] = 2.0;
    twice.x.insert(twice.x.end(), d.row(i), d.row(i) + d.cols);
    twice.y.push_back(d.y[i]);
    ++twice.rows;
  }
  const TrainingSet twice_set(twice), weighted_set(weighted);
  for (const bool libsvm_path : {false, true}) {
    Params p;
    p.kernel = Kernel::rbf_sigma(0.8);
    p.c = 3;
    p.epsilon = 0.05;
    p.tolerance = 1e-7;
    p.libsvm_path = libsvm_path;
    const FitResult a = fit(twice_set, p), b = fit(weighted_set, p);
    EXPECT_NEAR(a.summary.solver.objective, b.summary.solver.objective,
                1e-6 * std::fabs(a.summary.solver.objective));
    EXPECT_GT(b.summary.n_bsv, 10u);
    for (std::size_t i = 0; i < d.rows; ++i)
      ASSERT_NEAR(a.model.predict(d.row(i)), b.model.predict(d.row(i)), 1e-5)
          << (libsvm_path ? "LIBSVM path" : "pairs") << ", sample " << i;
  }
}

TEST(SvrKernelInFloat, ReachesLibsvmsOptimumWithinTheKernelsRounding) {
  // The float kernel (KernelArithmetic::single, the searches') against LIBSVM's floats, both at
  // the optimum (tolerance 1e-7): kernel entries a few float steps apart move the objective by
  // parts in 10⁶ and the predictions by at most a few 1e-4 of the target's SD (1.4e-4 when
  // written), within the 1e-3 the LIBSVM comparisons above ask.
  for (const auto& [name, data, unique] : datasets()) {
    SCOPED_TRACE(name);
    const TrainingSet set(data);
    for (const double c : {1.0, 100.0}) {
      Params p;
      p.kernel = Kernel::rbf_sigma(1.0);
      p.c = c;
      p.epsilon = 0.05;
      p.tolerance = 1e-7;
      const FitResult libsvm = fit(set, p);
      p.kernel_arithmetic = KernelArithmetic::single;
      const FitResult single = fit(set, p);
      const double obj = objective_of(data, p, libsvm);
      EXPECT_NEAR(objective_of(data, p, single), obj, 1e-5 * std::max(1.0, std::fabs(obj)));
      double worst = 0;
      for (std::size_t i = 0; i < data.rows; ++i)
        worst = std::max(worst, std::fabs(single.model.predict(data.row(i)) -
                                          libsvm.model.predict(data.row(i))));
      EXPECT_LE(worst, 1e-3 * std::max(sd(data.y), 1e-12)) << "C = " << c;
      // Scoring a path in either arithmetic: the same predictions to the kernel's rounding
      // times the coefficients' sum (2e-5 of the SD at C = 100 when written).
      std::vector<std::size_t> rows(data.rows);
      std::iota(rows.begin(), rows.end(), std::size_t{0});
      const std::vector<FitResult> path{single};
      const auto f_single = path_predictions(set, path, data, rows, KernelArithmetic::single);
      const auto f_libsvm = path_predictions(set, path, data, rows, KernelArithmetic::libsvm);
      for (std::size_t i = 0; i < data.rows; i += 7)
        EXPECT_NEAR(f_single[i], f_libsvm[i], 1e-4 * std::max(sd(data.y), 1e-12));
    }
  }
}

TEST(SvrWeights, BothSolversAndWarmStartsReachTheSameWeightedOptimum) {
  const Data base = testing::startup_like(500, 8);
  Data d = base;
  Rng rng(4);
  for (std::size_t i = 0; i < d.rows; ++i) d.weight.push_back(rng.uniform(0.1, 5));
  const TrainingSet set(d);
  Params p;
  p.kernel = Kernel::rbf_sigma(1.0);
  p.tolerance = 1e-6;
  p.c = 8;
  const FitResult pairs = fit(set, p);
  p.libsvm_path = true;
  const FitResult libsvm = fit(set, p);
  p.libsvm_path = false;
  const auto path = fit_c_path(set, p, std::vector<double>{0.5, 8});
  const double obj = pairs.summary.solver.objective;
  EXPECT_NEAR(libsvm.summary.solver.objective, obj, 1e-7 * std::fabs(obj));
  EXPECT_NEAR(path[1].summary.solver.objective, obj, 1e-7 * std::fabs(obj));
  EXPECT_TRUE(path[1].summary.solver.warm_started);
  for (std::size_t i = 0; i < d.rows; i += 5) {
    EXPECT_NEAR(libsvm.model.predict(d.row(i)), pairs.model.predict(d.row(i)), 1e-4);
    EXPECT_NEAR(path[1].model.predict(d.row(i)), pairs.model.predict(d.row(i)), 1e-4);
  }
  // Each variable stays in its own box, and some reach it.
  std::size_t at_bound = 0;
  for (std::size_t i = 0; i < d.rows; ++i) {
    const double beta = pairs.dual.alpha[i] - pairs.dual.alpha[i + d.rows];
    ASSERT_LE(std::fabs(beta), p.c * d.weight[i] * (1 + 1e-12));
    if (std::fabs(beta) >= p.c * d.weight[i]) ++at_bound;
  }
  EXPECT_EQ(at_bound, pairs.summary.n_bsv);
  EXPECT_GT(at_bound, 0u);
  // Unweighted, the same data gives another model.
  EXPECT_NE(fit(TrainingSet(base), p).model.rho, pairs.model.rho);
}

}  // namespace
}  // namespace fogdrift::svr
