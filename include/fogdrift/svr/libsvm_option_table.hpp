// svm-train's options, described once (option_table.hpp, docs/options.md): `fogdrift svr
// train`'s flags and the option string of fogdrift.svmtrain (matlab/, docs/matlab.md), which
// parse_libsvm_train_options (libsvm_options.hpp) reads through this table. LibsvmFlags holds the
// values as given; the parser turns them into a fit's Params. The defaults are svm-train's.
#pragma once

#include <optional>

#include "fogdrift/base/option_table.hpp"

namespace fogdrift::svr {

struct LibsvmFlags {
  bool pairs = false;        ///< --solver pairs: fogdrift's solver; libsvm: LIBSVM's working sets
  unsigned svm_type = 3;     ///< -s; ε-SVR (3) only, the others refused by name
  unsigned kernel_type = 2;  ///< -t; 2 RBF or 0 linear
  unsigned degree = 3;       ///< -d, kept for LIBSVM's model struct
  std::optional<double> gamma;  ///< -g; none: 1/number of features
  std::optional<double> sigma;  ///< --sigma, instead of -g: γ = 1/(2σ²)
  double coef0 = 0;             ///< -r, kept for LIBSVM's model struct
  double c = 1;                 ///< -c
  double nu = 0.5;              ///< -n, which ε-SVR ignores, as LIBSVM does
  double epsilon = 0.1;         ///< -p
  double cache_mb = 100;        ///< -m
  double tolerance = 1e-3;      ///< -e
  bool shrinking = true;        ///< -h 1
  unsigned folds = 0;           ///< -v n: n-fold cross-validation instead of a model; 0: none
  bool quiet = false;           ///< -q
};

const OptionTable<LibsvmFlags>& libsvm_train_option_table();

}  // namespace fogdrift::svr
