// fogdrift svr train / predict: the SVR engine behind svm-train's and svm-predict's flags, so
// that LIBSVM users can swap the command and keep their files and scripts.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/svr/libsvm_format.hpp"
#include "fogdrift/svr/libsvm_option_table.hpp"
#include "fogdrift/svr/libsvm_options.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

/// svm-train's arguments as given: its flags, then DATA and MODEL, read by the library's parser
/// of svm-train's options (libsvm_options.hpp), which fogdrift.svmtrain's option string shares.
struct SvrTrainArgs {
  bool json = false;
  std::string data, model;
  std::vector<std::string> flags;  ///< the flags and their values, --solver pairs first
};

/// Splits `args` into svm-train's flags with their values (-q and --json alone; --json is
/// fogdrift's) and the files after them, as svm-train's usage has them: [options] DATA [MODEL].
SvrTrainArgs split_train_args(std::vector<std::string> args) {
  SvrTrainArgs a;
  // fogdrift's solver unless --solver asks for LIBSVM's: a later flag wins.
  a.flags = {"--solver", "pairs"};
  std::vector<std::string> files;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& t = args[i];
    if (t == "--json") {
      a.json = true;
    } else if (t.size() > 1 && t[0] == '-' && !files.empty()) {
      // svm-train's order; taken as MODEL, "-c" would become the model file's name.
      throw OptionError(t, fmt::format("comes after DATA '{}', and svr train takes [options] "
                                       "DATA [MODEL], its options first as svm-train's: move {} "
                                       "before DATA (a file whose name begins with '-' is ./{})",
                                       files[0], t, t));
    } else if (t.size() > 1 && t[0] == '-') {
      a.flags.push_back(t);
      if (!svr::is_libsvm_train_switch(t)) {  // an unknown flag too: the parser names it
        if (i + 1 >= args.size()) throw OptionError(t, "needs a value after it");
        a.flags.push_back(args[++i]);
      }
    } else {
      files.push_back(t);
    }
  }
  if (files.empty() || files.size() > 2)
    throw OptionError("DATA",
                      fmt::format("svr train takes [options] DATA [MODEL], its options first "
                                  "(got {} file names)",
                                  files.size()));
  a.data = files[0];
  if (files.size() == 2) a.model = files[1];
  return a;
}

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
  // The options checked before the data are read, then read with the data's feature count
  // (svm-train's default γ is its reciprocal).
  svr::parse_libsvm_train_options(a.flags, 1);
  svr::Data data = svr::read_libsvm_data(a.data);
  const svr::LibsvmTrainOptions o =
      svr::parse_libsvm_train_options(a.flags, std::max<std::size_t>(1, data.cols));
  const svr::Params& p = o.params;
  if (o.folds > 0) {
    // svm-train -v n: the cross-validated error, and no model (libsvm_options.hpp).
    const svr::CrossValidation cv = svr::cross_validate(data, p, o.folds);
    if (a.json) {
      nlohmann::ordered_json j;
      j["folds"] = o.folds;
      j["mean_squared_error"] = cv.mean_squared_error;
      j["squared_correlation"] = std::isfinite(cv.squared_correlation)
                                     ? nlohmann::ordered_json(cv.squared_correlation)
                                     : nlohmann::ordered_json(nullptr);
      std::cout << j.dump(2) << "\n";
    } else if (!o.quiet) {
      std::cout << fmt::format("Cross Validation Mean squared error = {:g}\n",
                               cv.mean_squared_error)
                << fmt::format("Cross Validation Squared correlation coefficient = {:g}\n",
                               cv.squared_correlation);
    }
    return;
  }
  check_output_not_input(
      a.model.empty() ? fs::path(a.data).filename().string() + ".model" : a.model, "MODEL");
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
  if (!o.quiet) {
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

/// svm-train's flags as --help lists them, from their one description (libsvm_option_table.hpp).
std::string train_flags_help() {
  const auto& table = svr::libsvm_train_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  const std::vector<std::string> defaults = defaults_of(table);
  std::string out =
      "Options (svm-train's, with its defaults; fogdrift options svr-train lists them):\n";
  for (std::size_t i = 0; i < specs.size(); ++i)
    out += fmt::format(
        "  {:<8} {} [default: {}]\n", specs[i].flag, option_help(specs[i], specs, true),
        // fogdrift's solver here, which its training uses too; LIBSVM's in
        // fogdrift.svmtrain, whose users compare models with svm-train's.
        specs[i].flag == "--solver" ? "pairs (fogdrift.svmtrain: libsvm)" : defaults[i]);
  out +=
      "  --json   print the fit summary as JSON\n"
      "  DATA     training data, LIBSVM format; MODEL the model file (default: DATA's file name "
      "+\n"
      "           .model; fogdrift's JSON when it ends in .json)";
  return out;
}

}  // namespace

void add_svr(CLI::App& app) {
  auto* svr = app.add_subcommand(
      "svr",
      "ε-SVR with LIBSVM's flags and files: train and predict like svm-train and svm-predict,\n"
      "with the same models (to rounding) in a fraction of the time.");
  svr->require_subcommand(1);

  auto* train = svr->add_subcommand(
      "train",
      "Fit ε-SVR to LIBSVM-format data (svm-train's flags and defaults; -s 3 and -t 2 or 0).\n"
      "Writes MODEL in LIBSVM's model format (readable by svm-predict), or fogdrift's JSON\n"
      "when MODEL ends in .json; prints svm-train's summary lines.\n\n"
      "Example:\n  fogdrift svr train -c 10 -g 0.5 -p 0.1 data.txt data.model");
  train->set_help_flag("--help", "Print this help message and exit (-h is svm-train's shrinking)");
  // Every argument after the help flag is svm-train's, read by the library's parser of its
  // options (libsvm_options.hpp), so that `svr train` and fogdrift.svmtrain take one grammar.
  train->prefix_command();
  train->footer(train_flags_help());
  train->callback([train] {
    const std::vector<std::string> args = train->remaining();
    if (std::find(args.begin(), args.end(), "--help") != args.end()) {
      std::cout << train->help();
      return;
    }
    run_train(split_train_args(args));
  });

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
