// fogdrift svr train / predict: the SVR engine behind svm-train's and svm-predict's flags, so
// that LIBSVM users can swap the command and keep their files and scripts.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/svr/libsvm_format.hpp"
#include "fogdrift/svr/libsvm_options.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct SvrTrainArgs {
  int svm_type = 3;
  int kernel_type = 2;
  double gamma = 0;  // 0: 1/number of features, as svm-train
  double sigma = 0;
  double c = 1;
  double epsilon = 0.1;
  double tolerance = 1e-3;
  double cache_mb = 100;
  int shrinking = 1;
  std::string solver = "pairs";
  bool quiet = false;
  bool json = false;
  std::string data, model;
};

struct PredictArgs {
  bool quiet = false;
  bool json = false;
  std::string data, model, output;
};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void run_train(const SvrTrainArgs& a) {
  svr::check_svm_type(a.svm_type);
  svr::check_kernel_type(a.kernel_type);
  if (a.shrinking != 0 && a.shrinking != 1) throw OptionError("-h", "must be 0 or 1");
  if (a.solver != "libsvm" && a.solver != "pairs")
    throw OptionError("--solver", fmt::format("must be libsvm or pairs (got '{}')", a.solver));
  if (a.gamma != 0 && a.sigma != 0) throw OptionError("--sigma", "give either -g or --sigma");
  svr::Data data = svr::read_libsvm_data(a.data);
  svr::Params p;
  check_output_not_input(
      a.model.empty() ? fs::path(a.data).filename().string() + ".model" : a.model, "MODEL");
  if (a.kernel_type == 0) {
    p.kernel = svr::Kernel::linear();
  } else if (a.sigma != 0) {
    if (!(a.sigma > 0) || !std::isfinite(a.sigma))
      throw OptionError("--sigma", fmt::format("must be a finite number > 0 (got {})", a.sigma));
    p.kernel = svr::Kernel::rbf_sigma(a.sigma);
  } else {
    p.kernel = svr::Kernel::rbf_gamma(
        a.gamma != 0 ? a.gamma : 1.0 / static_cast<double>(std::max<std::size_t>(1, data.cols)));
  }
  p.c = a.c;
  p.epsilon = a.epsilon;
  p.tolerance = a.tolerance;
  p.cache_mb = a.cache_mb;
  p.shrinking = a.shrinking == 1;
  p.libsvm_path = a.solver == "libsvm";
  svr::validate(p, svr::ParamNames{"-c", a.sigma != 0 ? "--sigma" : "-g", "-p", "-e", "-m",
                                   "max_iterations"});
  const std::string model_path =
      a.model.empty() ? fs::path(a.data).filename().string() + ".model" : a.model;
  const svr::TrainingSet set(std::move(data));
  const svr::FitResult r = svr::fit(set, p);
  if (ends_with(model_path, ".json"))
    svr::save_model(r.model, model_path);
  else
    svr::write_libsvm_model(r.model, model_path);
  const auto& s = r.summary;
  if (a.json) {
    nlohmann::ordered_json j;
    j["status"] = s.solver.status == svr::SolverStatus::optimal ? "optimal" : "iteration_limit";
    j["iterations"] = s.solver.iterations;
    j["objective"] = s.solver.objective;
    j["rho"] = s.solver.rho;
    j["n_sv"] = s.n_sv;
    j["n_bsv"] = s.n_bsv;
    j["nu"] = s.nu;
    j["max_violation"] = s.solver.max_violation;
    j["kernel_rows"] = s.solver.kernel_rows;
    j["seconds"] = s.seconds;
    j["C"] = p.c;
    j["gamma"] = p.kernel.gamma;
    if (p.kernel.type == svr::KernelType::rbf) j["sigma"] = p.kernel.sigma();
    j["epsilon"] = p.epsilon;
    j["samples"] = set.size();
    j["features"] = set.dims();
    j["model"] = model_path;
    std::cout << j.dump(2) << "\n";
    return;
  }
  if (!a.quiet) {
    // svm-train's closing lines, same formats.
    std::cout << fmt::format("optimization finished, #iter = {}\n", s.solver.iterations)
              << fmt::format("nu = {:f}\n", s.nu)
              << fmt::format("obj = {:f}, rho = {:f}\n", s.solver.objective, s.solver.rho)
              << fmt::format("nSV = {}, nBSV = {}\n", s.n_sv, s.n_bsv);
    if (s.solver.status != svr::SolverStatus::optimal)
      std::cerr << "fogdrift: warning: reached the iteration limit before the tolerance\n";
  }
}

void run_predict(const PredictArgs& a) {
  svr::Model m = svr::read_any_model(a.model);
  svr::Data data = svr::read_libsvm_data(a.data, m.dims);
  check_output_not_input(a.output, "OUTPUT");
  if (data.cols > m.dims) {
    // Features the model never saw are zero in every support vector (LIBSVM's sparse rule).
    std::vector<double> sv(m.size() * data.cols, 0.0);
    for (std::size_t i = 0; i < m.size(); ++i)
      std::copy_n(m.support_vectors.data() + i * m.dims, m.dims, sv.data() + i * data.cols);
    m.support_vectors = std::move(sv);
    m.dims = data.cols;
  }
  const std::vector<double> f = m.predict(data);
  write_file_atomically(a.output, [&](std::ostream& out) {
    for (double v : f) out << fmt::format("{:.17g}\n", v);
  });
  // svm-predict's regression summary: mean squared error and squared correlation.
  double se = 0;
  for (std::size_t i = 0; i < f.size(); ++i) se += (f[i] - data.y[i]) * (f[i] - data.y[i]);
  const double mse = se / static_cast<double>(f.size());
  const double r2 = svr::squared_correlation(f, data.y);
  if (a.json) {
    nlohmann::ordered_json j;
    j["samples"] = f.size();
    j["mean_squared_error"] = mse;
    j["squared_correlation"] = std::isfinite(r2) ? nlohmann::ordered_json(r2) : nullptr;
    j["output"] = a.output;
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    std::cout << fmt::format("Mean squared error = {:g} (regression)\n", mse)
              << fmt::format("Squared correlation coefficient = {:g} (regression)\n", r2);
  }
}

}  // namespace

void add_svr(CLI::App& app) {
  auto* svr = app.add_subcommand(
      "svr",
      "ε-SVR with LIBSVM's flags and files: train and predict like svm-train and svm-predict,\n"
      "with the same models (to rounding) in a fraction of the time.");
  svr->require_subcommand(1);

  auto ta = std::make_shared<SvrTrainArgs>();
  auto* train = svr->add_subcommand(
      "train",
      "Fit ε-SVR to LIBSVM-format data (svm-train's flags and defaults; -s 3 and -t 2 or 0).\n"
      "Writes MODEL in LIBSVM's model format (readable by svm-predict), or fogdrift's JSON\n"
      "when MODEL ends in .json; prints svm-train's summary lines.\n\n"
      "Example:\n  fogdrift svr train -c 10 -g 0.5 -p 0.1 data.txt data.model");
  train->set_help_flag("--help", "Print this help message and exit (-h is svm-train's shrinking)");
  train->add_option("-s", ta->svm_type, "SVM type; only 3 (epsilon-SVR)")->capture_default_str();
  train->add_option("-t", ta->kernel_type, "kernel: 2 RBF exp(-gamma|u-v|^2), 0 linear u'v")
      ->capture_default_str();
  train->add_option("-g", ta->gamma, "RBF gamma = 1/(2 sigma^2) (default 1/number of features)");
  train->add_option("--sigma", ta->sigma, "RBF width sigma, the paper's parameter (instead of -g)");
  train->add_option("-c", ta->c, "cost C > 0")->capture_default_str();
  train->add_option("-p", ta->epsilon, "epsilon >= 0 of the insensitive tube, target units")
      ->capture_default_str();
  train->add_option("-e", ta->tolerance, "stopping tolerance > 0")->capture_default_str();
  train->add_option("-m", ta->cache_mb, "kernel cache, MB")->capture_default_str();
  train->add_option("-h", ta->shrinking, "shrinking heuristics, 0 or 1")->capture_default_str();
  train
      ->add_option(
          "--solver", ta->solver,
          "pairs: fogdrift's solver (its training uses it too), svm-train's optimum to the\n"
          "tolerance -e by another path, about 3x faster than libsvm; libsvm: LIBSVM's working\n"
          "sets one for one, so the model, iterations and nSV are svm-train's (for audits)")
      ->capture_default_str();
  train->add_flag("-q", ta->quiet, "print nothing");
  train->add_flag("--json", ta->json, "print the fit summary as JSON");
  train->add_option("DATA", ta->data, "training data, LIBSVM format")->required();
  train->add_option("MODEL", ta->model, "model file (default: DATA's file name + .model)");
  train->callback([ta] { run_train(*ta); });

  auto pa = std::make_shared<PredictArgs>();
  auto* predict = svr->add_subcommand(
      "predict",
      "Predict LIBSVM-format data with a model (LIBSVM or fogdrift JSON), writing one value a\n"
      "line to OUTPUT and printing svm-predict's mean squared error and squared correlation.\n\n"
      "Example:\n  fogdrift svr predict test.txt data.model predictions.txt");
  predict->add_flag("-q", pa->quiet, "print nothing");
  predict->add_flag("--json", pa->json, "print the error summary as JSON");
  predict->add_option("DATA", pa->data, "data to predict, LIBSVM format")->required();
  predict->add_option("MODEL", pa->model, "model file")->required();
  predict->add_option("OUTPUT", pa->output, "predictions, one a line")->required();
  predict->callback([pa] { run_predict(*pa); });
}

}  // namespace fogdrift::app
