// svm-train's option strings and -v cross-validation: the options against svm-train's meaning
// of each flag, the refusals by name, and each fold's predictions against LIBSVM's C API fitted
// on the same rows.
#include "fogdrift/svr/libsvm_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "libsvm_oracle.hpp"

namespace fogdrift::svr {
namespace {

Data wave(std::size_t rows, std::uint64_t seed) {
  Data d;
  d.rows = rows;
  d.cols = 2;
  Rng rng(seed);
  for (std::size_t i = 0; i < rows; ++i) {
    const double a = rng.uniform(-2, 2), b = rng.uniform(-1, 1);
    d.x.push_back(a);
    d.x.push_back(b);
    d.y.push_back(std::sin(2 * a) + 0.5 * b + 0.05 * rng.normal());
  }
  return d;
}

std::string message_of(const std::string& text, std::size_t features = 2) {
  try {
    parse_libsvm_train_options(text, features);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "";
}

TEST(LibsvmOptions, ReadsSvmTrainsFlagsWithItsDefaults) {
  const LibsvmTrainOptions d = parse_libsvm_train_options("", 4);
  EXPECT_EQ(d.params.kernel, Kernel::rbf_gamma(0.25));  // 1/number of features
  EXPECT_EQ(d.params.c, 1.0);
  EXPECT_EQ(d.params.epsilon, 0.1);
  EXPECT_EQ(d.params.tolerance, 1e-3);
  EXPECT_EQ(d.params.cache_mb, 100.0);
  EXPECT_TRUE(d.params.shrinking);
  EXPECT_TRUE(d.params.libsvm_path);
  EXPECT_EQ(d.folds, 0);
  EXPECT_FALSE(d.quiet);

  const LibsvmTrainOptions o = parse_libsvm_train_options(
      " -s 3 -t 2\t-c 10 -g 0.1 -p 0.05 -h 0 -e 1e-4 -m 50 -d 2 -r 0.5 -n 0.3 -b 0 -v 5 -q "
      "--solver pairs",
      4);
  EXPECT_EQ(o.params.kernel, Kernel::rbf_gamma(0.1));
  EXPECT_TRUE(o.gamma_given);
  EXPECT_EQ(o.params.c, 10.0);
  EXPECT_EQ(o.params.epsilon, 0.05);
  EXPECT_EQ(o.params.tolerance, 1e-4);
  EXPECT_EQ(o.params.cache_mb, 50.0);
  EXPECT_FALSE(o.params.shrinking);
  EXPECT_FALSE(o.params.libsvm_path);
  EXPECT_EQ(o.degree, 2);
  EXPECT_EQ(o.coef0, 0.5);
  EXPECT_EQ(o.folds, 5);
  EXPECT_TRUE(o.quiet);
  EXPECT_EQ(parse_libsvm_train_options("-t 0", 3).params.kernel, Kernel::linear());
}

TEST(LibsvmOptions, RefusesWhatFogdriftDoesNotFitByName) {
  EXPECT_NE(message_of("-s 0").find("option -s: svm_type 0 (C-SVC) is not supported"),
            std::string::npos);
  EXPECT_NE(message_of("-s 4").find("(nu-SVR)"), std::string::npos);
  EXPECT_NE(message_of("-t 1").find("option -t: kernel_type 1 (polynomial) is not supported"),
            std::string::npos);
  EXPECT_NE(message_of("-t 4").find("precomputed"), std::string::npos);
  EXPECT_NE(message_of("-b 1").find("probability estimates are not supported"), std::string::npos);
  EXPECT_NE(message_of("-w1 2").find("option -w1: class weights apply to classification only"),
            std::string::npos);
  EXPECT_NE(message_of("-c ten").find("option -c: 'ten' is not a finite number"),
            std::string::npos);
  EXPECT_NE(message_of("-c 0").find("option -c: 0 must be > 0"), std::string::npos);
  EXPECT_NE(message_of("-g -1").find("option -g:"), std::string::npos);
  EXPECT_NE(message_of("-h 2").find("option -h: must be 0 or 1"), std::string::npos);
  EXPECT_NE(message_of("-s 3.5").find("option -s: '3.5' is not a whole number"), std::string::npos);
  EXPECT_NE(message_of("-c").find("option -c: needs a value after it"), std::string::npos);
  EXPECT_NE(message_of("-v 1").find("option -v: 1 must be ≥ 2"), std::string::npos);
  EXPECT_NE(message_of("-x 1").find("option -x: is not one of svm-train's options"),
            std::string::npos);
  EXPECT_NE(message_of("c 10").find("option c: is not an option"), std::string::npos);
  EXPECT_NE(message_of("--solver smo").find("must be libsvm or pairs"), std::string::npos);

  EXPECT_TRUE(parse_libsvm_predict_options("-q -b 0"));
  EXPECT_FALSE(parse_libsvm_predict_options(""));
  EXPECT_THROW(parse_libsvm_predict_options("-b 1"), OptionError);
  EXPECT_THROW(parse_libsvm_predict_options("-c 1"), OptionError);
}

TEST(LibsvmOptions, CrossValidationPredictsEachFoldAsLibsvmFitOnTheOthers) {
  const Data d = wave(203, 7);
  const LibsvmTrainOptions o = parse_libsvm_train_options("-c 4 -g 0.7 -p 0.05", d.cols);
  const CrossValidation cv = cross_validate(d, o.params, 5, 11);
  ASSERT_EQ(cv.predictions.size(), d.rows);
  // The folds rebuilt as documented (Fisher–Yates with the same seed, contiguous folds of that
  // order), each fitted by LIBSVM on the other rows.
  std::vector<std::size_t> order(d.rows);
  std::iota(order.begin(), order.end(), std::size_t{0});
  Rng rng(11);
  for (std::size_t i = 0; i + 1 < d.rows; ++i)
    std::swap(order[i], order[i + rng.next_u64() % (d.rows - i)]);
  double se = 0, worst = 0;
  for (std::size_t k = 0; k < 5; ++k) {
    const std::size_t begin = k * d.rows / 5, end = (k + 1) * d.rows / 5;
    std::vector<std::size_t> train(order.begin(), order.begin() + begin);
    train.insert(train.end(), order.begin() + end, order.end());
    testing::OracleFit oracle;
    testing::libsvm_train(d.subset(train), o.params, oracle);
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t r = order[i];
      const double f = oracle.predict(d.row(r), d.cols);
      worst = std::max(worst, std::abs(f - cv.predictions[r]) / (1 + std::abs(f)));
      se += (f - d.y[r]) * (f - d.y[r]);
    }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(cv.mean_squared_error, se / static_cast<double>(d.rows), 1e-12);
  EXPECT_GT(cv.squared_correlation, 0.5);
  EXPECT_LE(cv.squared_correlation, 1.0);
  // More folds than rows: leave one out.
  const Data small = wave(6, 3);
  EXPECT_EQ(cross_validate(small, o.params, 50).predictions.size(), 6U);
  EXPECT_THROW(cross_validate(small, o.params, 1), OptionError);
}

TEST(LibsvmOptions, SquaredCorrelationIsSvmPredictsAndNanWhenConstant) {
  EXPECT_DOUBLE_EQ(squared_correlation({1, 2, 3}, {2, 4, 6}), 1.0);
  EXPECT_NEAR(squared_correlation({1, 2, 3, 4}, {1, 3, 2, 4}), 0.64, 1e-15);
  EXPECT_TRUE(std::isnan(squared_correlation({1, 1, 1}, {1, 2, 3})));
}

}  // namespace
}  // namespace fogdrift::svr
