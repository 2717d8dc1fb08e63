// svm-train's option strings and its -v cross-validation (docs/matlab.md, "LIBSVM's calling
// convention"; docs/svr.md).
#include "fogdrift/svr/libsvm_options.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/svr/libsvm_option_table.hpp"

namespace fogdrift::svr {
namespace {

/// The string's tokens split at spaces and tabs, as the MATLAB interface's strtok does.
std::vector<std::string> tokens_of(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t') ++j;
    if (j > i) out.emplace_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

double number_of(const std::string& flag, const std::string& value) {
  const std::optional<double> v = csv::parse_number(value);
  if (!v || !std::isfinite(*v))
    throw OptionError(flag, fmt::format("must be a finite number (got '{}')", value));
  return *v;
}

int whole_of(const std::string& flag, const std::string& value) {
  const double v = number_of(flag, value);
  if (v != std::floor(v) || std::abs(v) > 1e9)
    throw OptionError(flag, fmt::format("must be a whole number (got '{}')", value));
  return static_cast<int>(v);
}

/// Each flag with its value, a switch (`no_value(flag)`) alone with an empty value.
template <class NoValue, class F>
void for_each_flag(const std::vector<std::string>& t, const char* usage, NoValue no_value, F&& f) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    const std::string& flag = t[i];
    if (flag.size() < 2 || flag[0] != '-')
      throw OptionError(flag, fmt::format("is not an option: {} are '-LETTER VALUE' pairs", usage));
    if (no_value(flag)) {
      f(flag, std::string());
      continue;
    }
    if (i + 1 >= t.size()) throw OptionError(flag, "needs a value after it");
    f(flag, t[++i]);
  }
}

}  // namespace

void check_svm_type(int svm_type) {
  const char* name = svm_type == 0   ? "C-SVC"
                     : svm_type == 1 ? "nu-SVC"
                     : svm_type == 2 ? "one-class SVM"
                     : svm_type == 4 ? "nu-SVR"
                                     : nullptr;
  if (svm_type == 3) return;
  throw OptionError("-s", fmt::format("svm_type {}{} is not supported: fogdrift fits epsilon-SVR "
                                      "(-s 3) only",
                                      svm_type, name ? fmt::format(" ({})", name) : ""));
}

void check_kernel_type(int kernel_type) {
  const char* name = kernel_type == 1   ? "polynomial"
                     : kernel_type == 3 ? "sigmoid"
                     : kernel_type == 4 ? "precomputed"
                                        : nullptr;
  if (kernel_type == 0 || kernel_type == 2) return;
  throw OptionError("-t", fmt::format("kernel_type {}{} is not supported: use 2 (RBF) or 0 "
                                      "(linear)",
                                      kernel_type, name ? fmt::format(" ({})", name) : ""));
}

void check_probability(const std::string& value) {
  const int b = whole_of("-b", value);
  if (b == 1)
    throw OptionError("-b",
                      "probability estimates are not supported: fogdrift's ε-SVR gives the "
                      "regression value only; drop -b 1");
  if (b != 0) throw OptionError("-b", fmt::format("must be 0 or 1 (got '{}')", value));
}

bool is_libsvm_train_switch(const std::string& flag) {
  for (const auto& o : libsvm_train_option_table())
    if (o.spec.flag == flag) return o.spec.type == OptionType::on_off;
  return false;
}

LibsvmTrainOptions parse_libsvm_train_options(std::string_view text, std::size_t features) {
  return parse_libsvm_train_options(tokens_of(text), features);
}

LibsvmTrainOptions parse_libsvm_train_options(const std::vector<std::string>& tokens,
                                              std::size_t features) {
  const OptionTable<LibsvmFlags>& table = libsvm_train_option_table();
  const auto find = [&](const std::string& flag) {
    return std::find_if(table.begin(), table.end(),
                        [&](const auto& o) { return o.spec.flag == flag; });
  };
  LibsvmFlags f;
  // A flag the table lacks takes no value here, so that it is named below for what it is.
  const auto no_value = [&](const std::string& flag) {
    return find(flag) == table.end() || is_libsvm_train_switch(flag);
  };
  for_each_flag(tokens, "svm-train's options", no_value,
                [&](const std::string& flag, const std::string& value) {
                  if (flag.size() > 2 && flag[1] == 'w')
                    throw OptionError(flag,
                                      "class weights apply to classification only; epsilon-SVR "
                                      "has none (give each sample a weight instead)");
                  const auto option = find(flag);
                  if (option == table.end()) {
                    std::vector<std::string> flags;
                    for (const auto& o : table) flags.push_back(o.spec.flag);
                    throw OptionError(flag, fmt::format("is not one of svm-train's options ({})",
                                                        fmt::join(flags, " ")));
                  }
                  try {
                    option->set(f, option->spec.type == OptionType::on_off ? "true" : value);
                  } catch (const OptionError& e) {
                    // The table names its options by keyword; a user of svm-train knows them by
                    // flag.
                    if (e.option() == option->spec.keyword) throw OptionError(flag, e.message());
                    throw;
                  }
                });
  if (f.sigma && f.gamma) throw OptionError("--sigma", "give either -g or --sigma");
  LibsvmTrainOptions o;
  o.params.libsvm_path = !f.pairs;
  o.params.c = f.c;
  o.params.epsilon = f.epsilon;
  o.params.cache_mb = f.cache_mb;
  o.params.tolerance = f.tolerance;
  o.params.shrinking = f.shrinking;
  o.degree = static_cast<int>(f.degree);
  o.coef0 = f.coef0;
  o.folds = static_cast<int>(f.folds);
  o.quiet = f.quiet;
  o.sigma_given = f.sigma.has_value();
  o.gamma_given = f.gamma || f.sigma;
  o.gamma = f.sigma   ? Kernel::rbf_sigma(*f.sigma).gamma
            : f.gamma ? *f.gamma
                      : 1.0 / static_cast<double>(std::max<std::size_t>(1, features));
  o.params.kernel = f.kernel_type == 0 ? Kernel::linear()
                    : f.sigma          ? Kernel::rbf_sigma(*f.sigma)
                                       : Kernel::rbf_gamma(o.gamma);
  validate(o.params,
           ParamNames{"-c", o.sigma_given ? "--sigma" : "-g", "-p", "-e", "-m", "max_iterations"});
  return o;
}

bool parse_libsvm_predict_options(std::string_view text) {
  bool quiet = false;
  for_each_flag(
      tokens_of(text), "svm-predict's options",
      [](const std::string& flag) { return flag == "-q"; },
      [&](const std::string& flag, const std::string& v) {
        if (flag == "-q")
          quiet = true;
        else if (flag == "-b")
          check_probability(v);
        else
          throw OptionError(flag, "is not one of svm-predict's options (-b 0, -q)");
      });
  return quiet;
}

double squared_correlation(const std::vector<double>& f, const std::vector<double>& y) {
  double sy = 0, sf = 0, syy = 0, sff = 0, syf = 0;
  const double n = static_cast<double>(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    sy += y[i];
    sf += f[i];
    syy += y[i] * y[i];
    sff += f[i] * f[i];
    syf += y[i] * f[i];
  }
  const double num = (n * syf - sf * sy) * (n * syf - sf * sy);
  const double den = (n * sff - sf * sf) * (n * syy - sy * sy);
  return den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN();
}

CrossValidation cross_validate(const Data& data, const Params& params, int folds,
                               std::uint64_t seed) {
  if (folds < 2)
    throw OptionError("-v",
                      fmt::format("n-fold cross validation: n must be at least 2 (got {})", folds));
  validate(data);
  const std::size_t l = data.rows;
  const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(folds), l);
  std::vector<std::size_t> order(l);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Rng rng(seed);
  for (std::size_t i = 0; i + 1 < l; ++i) std::swap(order[i], order[i + rng.next_u64() % (l - i)]);
  CrossValidation cv;
  cv.predictions.assign(l, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t begin = k * l / n, end = (k + 1) * l / n;
    std::vector<std::size_t> train(order.begin(), order.begin() + begin);
    train.insert(train.end(), order.begin() + end, order.end());
    const TrainingSet set(data.subset(train));
    const Model m = fit(set, params).model;
    for (std::size_t i = begin; i < end; ++i)
      cv.predictions[order[i]] = m.predict(data.row(order[i]));
  }
  double se = 0;
  for (std::size_t i = 0; i < l; ++i)
    se += (cv.predictions[i] - data.y[i]) * (cv.predictions[i] - data.y[i]);
  cv.mean_squared_error = se / static_cast<double>(l);
  cv.squared_correlation = squared_correlation(cv.predictions, data.y);
  return cv;
}

}  // namespace fogdrift::svr
