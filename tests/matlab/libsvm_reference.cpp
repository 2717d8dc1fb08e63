// LIBSVM's C API as the reference for fogdrift.svmtrain in Octave (octave_svm, docs/matlab.md):
//   libsvm_reference TRAIN TEST C GAMMA EPSILON KERNEL SHRINKING
// fits ε-SVR on the LIBSVM-format file TRAIN with svm_train and prints, as a matrix Octave's
// load() reads: [rho n_sv], then [sv_index sv_coef] per support vector (1-based, training
// order), then [prediction 0] for each line of TEST, every number with 17 digits.
#include <svm.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Problem {
  std::vector<double> y;
  std::vector<std::vector<svm_node>> rows;
};

Problem read(const char* path) {
  Problem p;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    double y = 0;
    s >> y;
    p.y.push_back(y);
    std::vector<svm_node> row;
    std::string item;
    while (s >> item) {
      const auto colon = item.find(':');
      row.push_back({std::atoi(item.substr(0, colon).c_str()),
                     std::strtod(item.substr(colon + 1).c_str(), nullptr)});
    }
    row.push_back({-1, 0});
    p.rows.push_back(row);
  }
  return p;
}

void quiet(const char*) {}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: libsvm_reference TRAIN TEST C GAMMA EPSILON KERNEL SHRINKING\n");
    return 2;
  }
  svm_set_print_string_function(quiet);
  Problem train = read(argv[1]);
  Problem test = read(argv[2]);
  std::vector<svm_node*> x;
  for (auto& r : train.rows) x.push_back(r.data());
  svm_problem prob{static_cast<int>(train.y.size()), train.y.data(), x.data()};
  svm_parameter p{};
  p.svm_type = EPSILON_SVR;
  p.kernel_type = std::atoi(argv[6]);
  p.C = std::strtod(argv[3], nullptr);
  p.gamma = std::strtod(argv[4], nullptr);
  p.p = std::strtod(argv[5], nullptr);
  p.shrinking = std::atoi(argv[7]);
  p.eps = 1e-3;
  p.cache_size = 100;
  p.degree = 3;
  if (const char* e = svm_check_parameter(&prob, &p)) {
    std::fprintf(stderr, "%s\n", e);
    return 1;
  }
  svm_model* m = svm_train(&prob, &p);
  std::vector<int> idx(m->l);
  svm_get_sv_indices(m, idx.data());
  std::printf("%.17g %d\n", m->rho[0], m->l);
  for (int k = 0; k < m->l; ++k) std::printf("%d %.17g\n", idx[k], m->sv_coef[0][k]);
  for (auto& r : test.rows) std::printf("%.17g 0\n", svm_predict(m, r.data()));
  svm_free_and_destroy_model(&m);
  return 0;
}
