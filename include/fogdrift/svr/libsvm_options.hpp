// svm-train's options, described and checked once: as one string, the way LIBSVM's MATLAB and
// Python interfaces take them ('-s 3 -t 2 -c 10 -g 0.1 -p 0.05 -h 0'), or as a command line's
// arguments; and what `-v n` returns: the cross-validated mean squared error. `fogdrift svr
// train`'s flags and fogdrift.svmtrain's option string (matlab/, docs/matlab.md) are both read
// here (docs/svr.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr {

/// What one option string asks of a fit.
struct LibsvmTrainOptions {
  /// Kernel, C (-c), ε (-p), tolerance (-e), cache (-m), shrinking (-h). LIBSVM's working sets
  /// (libsvm_path) unless "--solver pairs" asks for fogdrift's solver.
  Params params;
  bool gamma_given = false;  ///< -g (or --sigma) given; else γ = 1/number of features
  bool sigma_given = false;  ///< --sigma: the RBF width the paper tunes, γ = 1/(2σ²)
  /// γ as svm-train records it in the model's parameters: -g, or 1/number of features, also for
  /// the linear kernel, which does not use it.
  double gamma = 0;
  int degree = 3;      ///< -d, kept for the model's Parameters as LIBSVM keeps it
  double coef0 = 0;    ///< -r, likewise
  int folds = 0;       ///< -v n: n-fold cross-validation instead of a model (0: none)
  bool quiet = false;  ///< -q
};

/// OptionError("-s") for an SVM type fogdrift does not fit, naming it: 0 C-SVC, 1 ν-SVC,
/// 2 one-class, 4 ν-SVR; fogdrift fits ε-SVR (3) only.
void check_svm_type(int svm_type);
/// OptionError("-t") for a kernel fogdrift does not have, naming it: 1 polynomial, 3 sigmoid,
/// 4 precomputed; fogdrift has 0 linear and 2 RBF.
void check_kernel_type(int kernel_type);

/// OptionError("-b") for probability estimates (-b 1), which fogdrift's ε-SVR does not give, or
/// a value other than 0 or 1.
void check_probability(const std::string& value);

/// Whether `flag` is one of svm-train's switches, given without a value (-q): read from
/// libsvm_train_option_table(). False for every other flag, known or not.
bool is_libsvm_train_switch(const std::string& flag);

/// Parses svm-train's options, each described in libsvm_train_option_table(). `features` is the
/// number of columns of the training data (the default γ is its reciprocal). OptionError naming the
/// flag for an unknown flag, a flag without its value, a value that is not a number of the flag's
/// kind, a type or kernel fogdrift lacks (check_svm_type, check_kernel_type), probability estimates
/// (-b 1), class weights (-wi) and values out of range (validate(Params)). fogdrift adds --solver
/// libsvm|pairs (LIBSVM's working sets, the default here, or fogdrift's solver) and --sigma S
/// (instead of -g).
LibsvmTrainOptions parse_libsvm_train_options(std::string_view text, std::size_t features);
/// The same from arguments already split, as a command line gives them: flags and their values.
LibsvmTrainOptions parse_libsvm_train_options(const std::vector<std::string>& tokens,
                                              std::size_t features);

/// svm-predict's options in the MATLAB interface: -q, and -b 0 (-b 1 is refused as in
/// parse_libsvm_train_options). Returns whether -q was given.
bool parse_libsvm_predict_options(std::string_view text);

/// What `-v n` gives: each sample predicted by the model fitted on the other folds.
struct CrossValidation {
  std::vector<double> predictions;  ///< in the data's order
  double mean_squared_error = 0;    ///< Σ(f − y)² / rows
  double squared_correlation = 0;   ///< of predictions and targets, as svm-predict prints it
};

/// n-fold cross-validation as svm-train -v: the rows shuffled by fogdrift's generator seeded with
/// `seed` (Fisher–Yates; LIBSVM's own folds come from the C library's rand() and differ), fold k
/// the rows k·l/n … (k+1)·l/n − 1 of that order, each fold predicted by a fit on the others.
/// More folds than rows: one row a fold. OptionError("-v") for n < 2.
CrossValidation cross_validate(const Data& data, const Params& params, int folds,
                               std::uint64_t seed = 1);

/// svm-predict's squared correlation coefficient of `f` against `y`, NaN when either is constant.
double squared_correlation(const std::vector<double>& f, const std::vector<double>& y);

}  // namespace fogdrift::svr
