#include "fogdrift/regress/poly.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>
#include <string>

#include "base/c_text.hpp"
#include "base/json_number.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift {

std::vector<std::uint8_t> monomials(std::size_t inputs, std::size_t degree) {
  std::vector<std::uint8_t> out(inputs, 0);  // the constant
  std::vector<std::uint8_t> e(inputs, 0);
  // For each total degree, enumerate exponent vectors in lexicographic order (first variable
  // highest first).
  for (std::size_t total = 1; total <= degree; ++total) {
    auto emit = [&](auto&& self, std::size_t k, std::size_t left) -> void {
      if (k + 1 == inputs) {
        e[k] = static_cast<std::uint8_t>(left);
        out.insert(out.end(), e.begin(), e.end());
        return;
      }
      for (std::size_t p = left + 1; p-- > 0;) {
        e[k] = static_cast<std::uint8_t>(p);
        self(self, k + 1, left - p);
      }
    };
    if (inputs > 0) emit(emit, 0, total);
  }
  return out;
}

double Poly::predict(const double* x) const noexcept {
  double y = 0;
  for (std::size_t m = 0; m < coef.size(); ++m) {
    double term = coef[m];
    for (std::size_t k = 0; k < inputs; ++k)
      for (std::uint8_t p = exponents[m * inputs + k]; p > 0; --p) term *= x[k];
    y += term;
  }
  return y;
}

Poly fit_poly(const Data& train, std::size_t degree, double ridge) {
  if (degree < 1 || degree > 6)
    throw OptionError("degree", fmt::format("{} is outside 1 … 6", degree));
  validate(train, "polynomial training data");
  Poly p;
  p.inputs = train.cols;
  p.degree = degree;
  p.exponents = monomials(train.cols, degree);
  const std::size_t terms = p.exponents.size() / std::max<std::size_t>(1, train.cols);
  if (train.rows < terms)
    throw OptionError("degree", fmt::format("degree {} in {} features has {} terms but there are "
                                            "only {} training rows",
                                            degree, train.cols, terms, train.rows));
  Eigen::MatrixXd a(static_cast<Eigen::Index>(train.rows), static_cast<Eigen::Index>(terms));
  for (std::size_t i = 0; i < train.rows; ++i) {
    const double* x = train.row(i);
    for (std::size_t m = 0; m < terms; ++m) {
      double v = 1;
      for (std::size_t k = 0; k < train.cols; ++k)
        for (std::uint8_t e = p.exponents[m * train.cols + k]; e > 0; --e) v *= x[k];
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(m)) = v;
    }
  }
  const Eigen::Map<const Eigen::VectorXd> y(train.y.data(), static_cast<Eigen::Index>(train.rows));
  Eigen::MatrixXd normal = a.transpose() * a;
  const double lambda = ridge * normal.diagonal().mean();
  for (Eigen::Index m = 1; m < normal.rows(); ++m) normal(m, m) += lambda;
  const Eigen::VectorXd c = normal.ldlt().solve(a.transpose() * y);
  p.coef.assign(c.data(), c.data() + c.size());
  return p;
}

std::string to_json(const Poly& p) {
  nlohmann::ordered_json exps = nlohmann::ordered_json::array();
  for (std::size_t t = 0; t < p.terms(); ++t)
    exps.push_back(
        std::vector<int>(p.exponents.begin() + static_cast<std::ptrdiff_t>(t * p.inputs),
                         p.exponents.begin() + static_cast<std::ptrdiff_t>((t + 1) * p.inputs)));
  const nlohmann::ordered_json j = {
      {"inputs", p.inputs}, {"degree", p.degree}, {"exponents", exps}, {"coef", p.coef}};
  return j.dump();
}

Poly poly_from_json(const std::string& text, const std::string& source) {
  auto fail = [&](const std::string& where, const std::string& rule) {
    throw InputError(source, 0, 0, fmt::format("{}: {}", where, rule));
  };
  check_json_nesting(source, text);
  Poly p;
  std::vector<std::vector<int>> exps;
  std::string where = "(top level)";
  try {
    const auto r = nlohmann::json::parse(text);
    where = "inputs";
    p.inputs = fogdrift::detail::whole_number<std::size_t>(r.at("inputs"));
    where = "degree";
    p.degree = fogdrift::detail::whole_number<std::size_t>(r.at("degree"));
    where = "coef";
    p.coef = r.at("coef").get<std::vector<double>>();
    where = "exponents";
    exps = r.at("exponents").get<std::vector<std::vector<int>>>();
  } catch (const nlohmann::json::exception& e) {
    fail(where, fmt::format("missing or mistyped field ({})", json_error_text(e)));
  }
  if (exps.size() != p.coef.size()) fail("exponents", "must hold one row per coefficient");
  for (const auto& e : exps) {
    if (e.size() != p.inputs) fail("exponents", "each row needs one exponent per input");
    for (int v : e) {
      if (v < 0 || v > static_cast<int>(p.degree))
        fail("exponents", fmt::format("exponent {} is outside 0 … degree", v));
      p.exponents.push_back(static_cast<std::uint8_t>(v));
    }
  }
  return p;
}

}  // namespace fogdrift

namespace fogdrift {

CRegressor to_c(const Poly& poly, const CNames& names) {
  const std::string& prefix = names.prefix;
  const std::string& upper = names.upper;
  CRegressor out;
  out.tables = fmt::format("#define {}_N_TERMS {}\n", upper, poly.terms());
  out.tables += fmt::format("static const unsigned char {}_exponents[{}] = {{", prefix,
                            poly.exponents.size());
  for (std::size_t i = 0; i < poly.exponents.size(); ++i)
    out.tables += fmt::format("{}{}{}", i % 20 == 0 ? "\n    " : "", poly.exponents[i],
                              i + 1 < poly.exponents.size() ? ", " : "");
  out.tables += "};\n";
  out.tables += fmt::format("static const @REAL@ {}_poly_coef[{}] = {{{}}};\n\n", prefix,
                            poly.terms(), detail::c_array(poly.coef));
  out.body = fmt::format(
      "  @REAL@ z = 0.0;\n"
      "  int t, k, e;\n"
      "  for (t = 0; t < {1}_N_TERMS; ++t) {{\n"
      "    @REAL@ term = {0}_poly_coef[t];\n"
      "    for (k = 0; k < {1}_N_FEATURES; ++k)\n"
      "      for (e = {0}_exponents[t * {1}_N_FEATURES + k]; e > 0; --e) term *= x[k];\n"
      "    z += term;\n"
      "  }}\n",
      prefix, upper);
  return out;
}

}  // namespace fogdrift
