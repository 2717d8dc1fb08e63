// svm-train's options (libsvm_option_table.hpp). Defaults are LibsvmFlags', svm-train's own.
// What only the fit can judge (C, γ and ε together, the tolerance, the cache) validate(Params)
// checks, naming these flags (libsvm_options.cpp).
#include "fogdrift/svr/libsvm_option_table.hpp"

#include <fmt/format.h>

#include <string>
#include <utility>

#include "fogdrift/svr/libsvm_options.hpp"

namespace fogdrift::svr {
namespace {

using O = LibsvmFlags;

/// A switch spelt by two names, `off` and `on` (--solver libsvm|pairs, -h 0|1); any other text
/// is refused naming both.
template <class Get>
Option<O> two_names(OptionSpec spec, Get get, std::string off, std::string on) {
  return choice_option<O>(
      std::move(spec), get, [off, on](bool v) { return v ? on : off; },
      [off, on](const std::string& text, const std::string& keyword) {
        if (text != off && text != on)
          throw OptionError(keyword, fmt::format("must be {} or {} (got '{}')", off, on, text));
        return text == on;
      });
}

/// A whole number of which `check` refuses, by name, what fogdrift does not fit (-s, -t).
template <class Get, class Check>
Option<O> checked_whole(OptionSpec spec, Get get, Check check) {
  Option<O> option = whole_option<O>(std::move(spec), get);
  option.set = [set = option.set, get, check](O& o, const std::string& text) {
    set(o, text);
    check(static_cast<int>(get(o)));
  };
  return option;
}

OptionTable<O> make_libsvm_table() {
  OptionTable<O> t;
  t.push_back(two_names(
      {"solver",
       "--solver",
       {},
       "",
       "libsvm, pairs",
       "fogdrift's: libsvm visits LIBSVM's working sets one for one, so the model, iterations "
       "and nSV are svm-train's (for audits); pairs is fogdrift's own solver, which its training "
       "uses: svm-train's optimum to the tolerance {tolerance} by another path, about 3x faster "
       "(docs/svr.md)",
       {}},
      [](auto& o) -> auto& { return o.pairs; }, "libsvm", "pairs"));
  t.push_back(checked_whole(
      {"svm_type",
       "-s",
       {},
       "",
       "3 (epsilon-SVR); 0, 1, 2, 4 are refused",
       "The SVM type: fogdrift fits epsilon-SVR only",
       {}},
      [](auto& o) -> auto& { return o.svm_type; }, check_svm_type));
  t.push_back(checked_whole(
      {"kernel_type", "-t", {}, "", "2 (RBF), 0 (linear); 1, 3, 4 are refused", "The kernel", {}},
      [](auto& o) -> auto& { return o.kernel_type; }, check_kernel_type));
  t.push_back(whole_option<O>(
      {"degree",
       "-d",
       {},
       "",
       at_least(0),
       "The polynomial kernel's degree: unused, kept in LIBSVM's model "
       "struct as svm-train keeps it",
       {}},
      [](auto& o) -> auto& { return o.degree; }));
  t.push_back(number_or_none_option<O>(
      {"gamma",
       "-g",
       {},
       "",
       above(0),
       "The RBF kernel's γ in exp(-γ|u-v|²) (none: 1/number of features)",
       {}},
      [](auto& o) -> auto& { return o.gamma; }));
  t.push_back(number_or_none_option<O>(
      {"sigma",
       "--sigma",
       {},
       "",
       above(0),
       "fogdrift's: the RBF width the paper tunes, γ = 1/(2σ²), instead of {gamma}",
       {}},
      [](auto& o) -> auto& { return o.sigma; }));
  t.push_back(number_option<O>(
      {"coef0",
       "-r",
       {},
       "",
       {},
       "The polynomial and sigmoid kernels' coef0: unused, kept in "
       "LIBSVM's model struct",
       {}},
      [](auto& o) -> auto& { return o.coef0; }));
  t.push_back(number_option<O>(
      {"c", "-c", {}, "", above(0), "The cost C", {}}, [](auto& o) -> auto& { return o.c; }));
  t.push_back(number_option<O>(
      {"nu",
       "-n",
       {},
       "",
       {},
       "ν of ν-SVC, one-class and ν-SVR: ε-SVR ignores it, as LIBSVM "
       "does",
       {}},
      [](auto& o) -> auto& { return o.nu; }));
  t.push_back(number_option<O>(
      {"epsilon",
       "-p",
       {},
       "",
       at_least(0),
       "The half-width ε of the insensitive tube, in the target's units (svm-train's default "
       "0.1; train's --epsilon is 0.05 of the standardised target)",
       {}},
      [](auto& o) -> auto& { return o.epsilon; }));
  t.push_back(number_option<O>(
      {"cache_mb", "-m", {}, "MB", above(0), "The kernel cache", {}},
      [](auto& o) -> auto& { return o.cache_mb; }));
  t.push_back(number_option<O>(
      {"tolerance", "-e", {}, "", above(0), "The stopping tolerance", {}},
      [](auto& o) -> auto& { return o.tolerance; }));
  t.push_back(two_names(
      {"shrinking", "-h", {}, "", "0, 1", "Shrinking: 1 on, 0 off", {}},
      [](auto& o) -> auto& { return o.shrinking; }, "0", "1"));
  t.push_back({{"probability",
                "-b",
                OptionType::choice,
                "",
                "0; 1 is refused",
                "Probability estimates: fogdrift's ε-SVR gives the regression value only",
                {}},
               [](const O&) { return std::string("0"); },
               [](O&, const std::string& text) { check_probability(text); }});
  t.push_back(whole_option<O>(
      {"folds",
       "-v",
       {},
       "",
       at_least(2).with("not given: a model"),
       "n-fold cross-validation: the cross-validated mean squared error instead of a model (the "
       "folds are drawn by fogdrift's generator, seed 1)",
       {}},
      [](auto& o) -> auto& { return o.folds; }));
  t.push_back(on_off_option<O>(
      {"quiet", "-q", {}, "", "", "Print nothing", {}}, [](auto& o) -> auto& { return o.quiet; }));
  return t;
}

}  // namespace

const OptionTable<LibsvmFlags>& libsvm_train_option_table() {
  static const OptionTable<LibsvmFlags> table = make_libsvm_table();
  return table;
}

}  // namespace fogdrift::svr
