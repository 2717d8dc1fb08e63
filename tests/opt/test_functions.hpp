// Standard test functions for the optimizers (minimum 0), optionally shifted so that the
// minimum is not at the origin: SSA's producer rule contracts towards the origin, so an
// unshifted function flatters it.
#pragma once

#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

namespace fogdrift::test {

struct TestFunction {
  std::string name;
  double (*f)(std::span<const double>);
  double lower, upper;  // the usual box, the same in every coordinate
};

inline double sphere(std::span<const double> x) {
  double s = 0;
  for (double v : x) s += v * v;
  return s;
}
inline double rosenbrock(std::span<const double> x) {
  double s = 0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i + 1] - x[i] * x[i], b = 1 - x[i];
    s += 100 * a * a + b * b;
  }
  return s;
}
inline double rastrigin(std::span<const double> x) {
  double s = 10.0 * static_cast<double>(x.size());
  for (double v : x) s += v * v - 10 * std::cos(2 * std::numbers::pi * v);
  return s;
}
inline double ackley(std::span<const double> x) {
  double a = 0, b = 0;
  for (double v : x) a += v * v, b += std::cos(2 * std::numbers::pi * v);
  const double n = static_cast<double>(x.size());
  return -20 * std::exp(-0.2 * std::sqrt(a / n)) - std::exp(b / n) + 20 + std::numbers::e;
}
inline double griewank(std::span<const double> x) {
  double s = 0, p = 1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    s += x[i] * x[i] / 4000;
    p *= std::cos(x[i] / std::sqrt(static_cast<double>(i + 1)));
  }
  return s - p + 1;
}

inline const std::vector<TestFunction>& test_functions() {
  static const std::vector<TestFunction> all = {{"sphere", sphere, -100, 100},
                                                {"rosenbrock", rosenbrock, -30, 30},
                                                {"rastrigin", rastrigin, -5.12, 5.12},
                                                {"ackley", ackley, -32, 32},
                                                {"griewank", griewank, -600, 600}};
  return all;
}

/// f(x − s) with s = shift_fraction·(upper − lower)/2 in every coordinate.
inline double shifted(const TestFunction& fn, std::span<const double> x, double shift_fraction) {
  const double s = shift_fraction * (fn.upper - fn.lower) / 2;
  std::vector<double> y(x.begin(), x.end());
  for (double& v : y) v -= s;
  return fn.f(y);
}

}  // namespace fogdrift::test
