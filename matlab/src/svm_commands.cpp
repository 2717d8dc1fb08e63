// fogdrift.svmtrain, fogdrift.svmpredict and fogdrift.libsvmread: LIBSVM's MATLAB interface
// (its calling convention, option strings, model struct and printed lines) over fogdrift's
// ε-SVR engine, so a LIBSVM script runs by changing two names (docs/matlab.md).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/svr/libsvm_format.hpp"
#include "fogdrift/svr/libsvm_options.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::matlab {
namespace {

MxPtr empty() {
  return MxPtr(mxCreateDoubleMatrix(0, 0, mxREAL));
}

/// A rows × cols row-major matrix as a sparse double matrix, zeros left out.
MxPtr sparse(const std::vector<double>& x, std::size_t rows, std::size_t cols) {
  std::size_t nnz = 0;
  for (double v : x) nnz += v != 0;
  MxPtr a(mxCreateSparse(rows, cols, std::max<std::size_t>(nnz, 1), mxREAL));
  double* pr = mxGetPr(a.get());
  mwIndex* ir = mxGetIr(a.get());
  mwIndex* jc = mxGetJc(a.get());
  std::size_t k = 0;
  for (std::size_t j = 0; j < cols; ++j) {
    jc[j] = k;
    for (std::size_t i = 0; i < rows; ++i)
      if (const double v = x[i * cols + j]; v != 0) {
        pr[k] = v;
        ir[k++] = i;
      }
  }
  jc[cols] = k;
  return a;
}

/// LIBSVM's model struct, its fields in svmtrain's order.
MxPtr model_struct(const svr::FitResult& r, const svr::LibsvmTrainOptions& o, std::size_t rows) {
  const char* names[] = {"Parameters", "nr_class", "totalSV", "rho",     "Label", "sv_indices",
                         "ProbA",      "ProbB",    "nSV",     "sv_coef", "SVs"};
  MxPtr s(mxCreateStructMatrix(1, 1, 11, names));
  const svr::Model& m = r.model;
  const int kernel_type = m.kernel.type == svr::KernelType::linear ? 0 : 2;
  const std::vector<double> parameters = {3, static_cast<double>(kernel_type),
                                          static_cast<double>(o.degree), o.gamma, o.coef0};
  std::vector<double> indices;
  for (std::size_t i = 0; i < rows; ++i)
    if (std::fabs(r.dual.alpha[i] - r.dual.alpha[i + rows]) > 0)
      indices.push_back(static_cast<double>(i + 1));
  mxSetField(s.get(), 0, "Parameters", column(parameters).release());
  mxSetField(s.get(), 0, "nr_class", mxCreateDoubleScalar(2));
  mxSetField(s.get(), 0, "totalSV", mxCreateDoubleScalar(static_cast<double>(m.size())));
  mxSetField(s.get(), 0, "rho", mxCreateDoubleScalar(m.rho));
  mxSetField(s.get(), 0, "Label", empty().release());
  mxSetField(s.get(), 0, "sv_indices", column(indices).release());
  mxSetField(s.get(), 0, "ProbA", empty().release());
  mxSetField(s.get(), 0, "ProbB", empty().release());
  mxSetField(s.get(), 0, "nSV", empty().release());
  mxSetField(s.get(), 0, "sv_coef", column(m.coef).release());
  mxSetField(s.get(), 0, "SVs", sparse(m.support_vectors, m.size(), m.dims).release());
  return s;
}

const mxArray* field(const mxArray* model, const char* name) {
  const mxArray* f = mxGetField(model, 0, name);
  if (!f)
    throw InputError("model", 0, 0,
                     fmt::format("has no field {}; give the struct svmtrain returned", name));
  return f;
}

/// The model struct of fogdrift.svmtrain or LIBSVM's svmtrain as a model; `features` columns
/// of data to predict (support vectors are widened with zeros, LIBSVM's rule for absent
/// features).
svr::Model model_of(const mxArray* s, std::size_t features) {
  if (!mxIsStruct(s) || mxGetNumberOfElements(s) != 1)
    throw InputError("model", 0, 0, "must be the struct svmtrain returned");
  // An edited or damaged struct is refused as a damaged LIBSVM model file is
  // (libsvm_format.hpp): a prediction from it would be wrong, not an error.
  const std::vector<double> p = vector_of(field(s, "Parameters"), "model.Parameters");
  if (p.size() < 5) throw InputError("model.Parameters", 0, 0, "must hold 5 values");
  for (int k : {0, 1})
    if (!(p[k] == std::floor(p[k]) && std::abs(p[k]) < 100))
      throw InputError("model.Parameters", k + 1, 0,
                       fmt::format("{} is not an SVM or kernel type", p[k]));
  const int svm_type = static_cast<int>(p[0]), kernel_type = static_cast<int>(p[1]);
  if (svm_type != 4) svr::check_svm_type(svm_type);  // ν-SVR predicts as ε-SVR does
  svr::check_kernel_type(kernel_type);
  if (kernel_type == 2 && !(p[3] > 0 && std::isfinite(p[3])))
    throw InputError("model.Parameters", 4, 0,
                     fmt::format("gamma is {}; an RBF model needs a finite gamma > 0", p[3]));
  svr::Model m;
  m.kernel = kernel_type == 0 ? svr::Kernel::linear() : svr::Kernel::rbf_gamma(p[3]);
  m.coef = vector_of(field(s, "sv_coef"), "model.sv_coef");
  m.rho = scalar_of(field(s, "rho"), "model.rho");
  const auto finite = [](double x) { return std::isfinite(x); };
  if (!std::all_of(m.coef.begin(), m.coef.end(), finite) || !std::isfinite(m.rho))
    throw InputError("model", 0, 0, "sv_coef or rho holds a value that is not finite");
  const mxArray* svs = field(s, "SVs");
  if (!mxIsDouble(svs) || mxGetM(svs) != m.coef.size())
    throw InputError(
        "model.SVs", 0, 0,
        fmt::format("must be a double matrix of {} rows, one per sv_coef", m.coef.size()));
  m.dims = std::max<std::size_t>(mxGetN(svs), features);
  m.support_vectors.assign(m.size() * m.dims, 0.0);
  const double* v = mxGetPr(svs);
  if (mxIsSparse(svs)) {
    const mwIndex* ir = mxGetIr(svs);
    const mwIndex* jc = mxGetJc(svs);
    for (std::size_t j = 0; j < mxGetN(svs); ++j)
      for (mwIndex k = jc[j]; k < jc[j + 1]; ++k) m.support_vectors[ir[k] * m.dims + j] = v[k];
  } else {
    for (std::size_t j = 0; j < mxGetN(svs); ++j)
      for (std::size_t i = 0; i < m.size(); ++i)
        m.support_vectors[i * m.dims + j] = v[j * m.size() + i];
  }
  if (!std::all_of(m.support_vectors.begin(), m.support_vectors.end(), finite))
    throw InputError("model.SVs", 0, 0, "holds a value that is not finite");
  return m;
}

}  // namespace

void svmtrain(const Args& args, Results& out) {
  if (args.size() < 2 || args.size() > 3)
    throw InputError("arguments", 0, 0,
                     "usage: model = fogdrift.svmtrain(training_label_vector, "
                     "training_instance_matrix, 'libsvm_options')");
  const svr::Data data = data_of(args.values[0], args.values[1]);
  const std::string text = args.size() == 3 ? text_of(args.values[2], "libsvm_options") : "";
  const svr::LibsvmTrainOptions o = svr::parse_libsvm_train_options(text, data.cols);
  if (o.folds > 0) {
    const svr::CrossValidation cv = svr::cross_validate(data, o.params, o.folds);
    if (!o.quiet)
      mexPrintf(
          "Cross Validation Mean squared error = %g\n"
          "Cross Validation Squared correlation coefficient = %g\n",
          cv.mean_squared_error, cv.squared_correlation);
    out.values.push_back(MxPtr(mxCreateDoubleScalar(cv.mean_squared_error)));
    return;
  }
  const std::size_t rows = data.rows;
  const svr::TrainingSet set(data);
  const svr::FitResult r = svr::fit(set, o.params);
  const auto& s = r.summary;
  if (!o.quiet)
    mexPrintf(
        "optimization finished, #iter = %lld\nnu = %f\nobj = %f, rho = %f\nnSV = %zu, "
        "nBSV = %zu\n",
        static_cast<long long>(s.solver.iterations), s.nu, s.solver.objective, s.solver.rho, s.n_sv,
        s.n_bsv);
  if (s.solver.status != svr::SolverStatus::optimal)
    out.warnings.push_back(
        "reached the iteration limit before the tolerance -e; the model is "
        "not optimal (scale the features, or lower -c)");
  out.values.push_back(model_struct(r, o, rows));
}

void svmpredict(const Args& args, Results& out) {
  if (args.size() < 3 || args.size() > 4)
    throw InputError("arguments", 0, 0,
                     "usage: [predicted_label, accuracy, decision_values] = "
                     "fogdrift.svmpredict(testing_label_vector, testing_instance_matrix, model, "
                     "'libsvm_options')");
  const svr::Data data = data_of(args.values[0], args.values[1]);
  const bool quiet = svr::parse_libsvm_predict_options(
      args.size() == 4 ? text_of(args.values[3], "libsvm_options") : "");
  const svr::Model m = model_of(args.values[2], data.cols);
  std::vector<double> f(data.rows);
  std::vector<double> x(m.dims, 0.0);
  std::size_t correct = 0;
  double se = 0;
  for (std::size_t i = 0; i < data.rows; ++i) {
    std::copy_n(data.row(i), data.cols, x.begin());
    f[i] = m.predict(x.data());
    correct += f[i] == data.y[i];
    se += (f[i] - data.y[i]) * (f[i] - data.y[i]);
  }
  const double mse = se / static_cast<double>(data.rows);
  const double r2 = svr::squared_correlation(f, data.y);
  if (!quiet)
    mexPrintf(
        "Mean squared error = %g (regression)\nSquared correlation coefficient = %g "
        "(regression)\n",
        mse, r2);
  out.values.push_back(column(f));
  out.values.push_back(
      column({100.0 * static_cast<double>(correct) / static_cast<double>(data.rows), mse, r2}));
  out.values.push_back(column(f));
}

void libsvmread(const Args& args, Results& out) {
  const std::string path = text_of(args.at(0, "filename"), "filename");
  const svr::Data d = svr::read_libsvm_data(path);
  out.values.push_back(column(d.y));
  out.values.push_back(sparse(d.x, d.rows, d.cols));
}

}  // namespace fogdrift::matlab
