#include "fogdrift/svr/libsvm_format.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift::svr {
namespace {

std::string data_error(const std::string& text) {
  try {
    parse_libsvm_data(text, "d.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LibsvmData, ParsesSparseLinesIntoDenseRows) {
  const Data d = parse_libsvm_data("1.5 1:2 3:-4\r\n-2 2:0.5\n0\n", "d.txt");
  EXPECT_EQ(d.rows, 3u);
  EXPECT_EQ(d.cols, 3u);
  EXPECT_EQ(d.y, (std::vector<double>{1.5, -2, 0}));
  EXPECT_EQ(d.x, (std::vector<double>{2, 0, -4, 0, 0.5, 0, 0, 0, 0}));
  EXPECT_EQ(parse_libsvm_data("1 1:1\n", "d.txt", 4).cols, 4u);
  EXPECT_EQ(to_libsvm_data(d), "1.5 1:2 3:-4\n-2 2:0.5\n0\n");
}

TEST(LibsvmData, ErrorsNameLineColumnAndRule) {
  EXPECT_EQ(data_error(""), "d.txt: no samples (the file is empty)");
  EXPECT_EQ(data_error("1 1:2\n\n2 1:3\n"),
            "d.txt:2: empty line (each line is TARGET INDEX:VALUE …; remove blank lines)");
  EXPECT_EQ(data_error("1 2:1 1:3\n"),
            "d.txt:1:7: feature index 1 is not above the previous index 2 (indices must "
            "increase)");
  EXPECT_EQ(data_error("1 1:1 1:3\n"),
            "d.txt:1:7: feature index 1 is not above the previous index 1 (indices must "
            "increase)");
  EXPECT_EQ(data_error("nan 1:1\n"), "d.txt:1:1: target 'nan' is not finite");
  EXPECT_EQ(data_error("1 1:inf\n"), "d.txt:1:3: feature value 'inf' is not finite");
  EXPECT_EQ(data_error("1 1:x\n"), "d.txt:1:3: feature value 'x' is not a number");
  EXPECT_EQ(data_error("1 0:1\n"), "d.txt:1:3: feature index '0' is not a positive integer");
  EXPECT_EQ(data_error("1 1 2\n"), "d.txt:1:3: '1' is not INDEX:VALUE");
  EXPECT_EQ(data_error("1,5 1:2\n"), "d.txt:1:1: target '1,5' is not a number");
  // Found by fuzzing: an index that would make the dense matrix larger than memory.
  EXPECT_EQ(data_error("1 9999999999:1\n"),
            "d.txt:1:3: feature index 9999999999 is above the 100000 features fogdrift reads (it "
            "holds features densely)");
  // More values in all than fogdrift holds: an error before the dense matrix is allocated.
  std::string big;
  for (int i = 0; i < 1343; ++i) big += "1 100000:1\n";
  EXPECT_EQ(data_error(big),
            "d.txt: 1343 rows × 100000 features is more than the 134217728 values (1 GiB) "
            "fogdrift holds in memory");
}

TEST(LibsvmModel, ReadsLibsvmsOwnOutputAndRejectsOtherModels) {
  const std::string text =
      "svm_type epsilon_svr\nkernel_type rbf\ngamma 0.5\nnr_class 2\ntotal_sv 2\n"
      "rho -0.25\nSV\n0.75 1:1 2:2 \n-0.5 2:-1 \n";
  const Model m = parse_libsvm_model(text, "m.model");
  EXPECT_EQ(m.kernel, Kernel::rbf_gamma(0.5));
  EXPECT_EQ(m.dims, 2u);
  EXPECT_EQ(m.coef, (std::vector<double>{0.75, -0.5}));
  EXPECT_EQ(m.support_vectors, (std::vector<double>{1, 2, 0, -1}));
  EXPECT_EQ(m.rho, -0.25);
  auto error = [](const std::string& t) {
    try {
      parse_libsvm_model(t, "m.model");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error("svm_type c_svc\n"),
            "m.model:1:10: svm_type 'c_svc' is not a regression model (epsilon_svr or nu_svr)");
  EXPECT_EQ(error("svm_type epsilon_svr\nkernel_type polynomial\n"),
            "m.model:2:13: kernel_type 'polynomial' is not supported (rbf or linear)");
  EXPECT_EQ(error("svm_type epsilon_svr\nkernel_type rbf\nrho 0\nSV\n"),
            "m.model: model header lacks 'gamma'");
  EXPECT_EQ(error("svm_type epsilon_svr\nkernel_type linear\ntotal_sv 3\nrho 0\nSV\n1 1:1\n"),
            "m.model:6: total_sv is 3 but 1 support vectors follow");
  // Found by fuzzing: a count beyond any integer type was cast unchecked.
  EXPECT_EQ(error("svm_type epsilon_svr\ntotal_sv 8e24\n"),
            "m.model:2:10: total_sv must be a whole number ≥ 0");
}

}  // namespace
}  // namespace fogdrift::svr
