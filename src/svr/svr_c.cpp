// The C of an ε-SVR's f(x) for the header (c_header.hpp, regressor.hpp).
#include <fmt/format.h>

#include <algorithm>

#include "base/c_text.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr {

CRegressor to_c(const Model& m, const CNames& names) {
  const std::string& prefix = names.prefix;
  const std::string& upper = names.upper;
  const std::size_t n = m.size(), d = m.dims;
  CRegressor out;
  out.tables = fmt::format("#define {}_N_SV {}\n", upper, n);
  out.tables += fmt::format("static const @REAL@ {}_sv[{}] = {{{}}};\n", prefix,
                            std::max<std::size_t>(1, n * d),
                            n ? fogdrift::detail::c_array(m.support_vectors) : "0");
  out.tables +=
      fmt::format("static const @REAL@ {}_coef[{}] = {{{}}};\n", prefix,
                  std::max<std::size_t>(1, n), n ? fogdrift::detail::c_array(m.coef) : "0");
  out.tables += fmt::format(
      "static const @REAL@ {}_gamma = {};\nstatic const @REAL@ {}_rho = {};\n\n", prefix,
      fogdrift::detail::c_number(m.kernel.gamma), prefix, fogdrift::detail::c_number(m.rho));
  const bool rbf = m.kernel.type == KernelType::rbf;
  out.body = fmt::format(
      "  @REAL@ z = -{0}_rho, carry = 0.0; /* compensated sum (Kahan): terms of C in the\n"
      "                                      hundreds cancel to a z of order 1 */\n"
      "  int i, k;\n"
      "  for (i = 0; i < {1}_N_SV; ++i) {{\n"
      "    const @REAL@* s = {0}_sv + i * {1}_N_FEATURES;\n"
      "    @REAL@ acc = 0.0, term, sum;\n"
      "    for (k = 0; k < {1}_N_FEATURES; ++k) {{\n"
      "{2}"
      "    }}\n"
      "    term = {0}_coef[i] * {3} - carry;\n"
      "    sum = z + term;\n"
      "    carry = (sum - z) - term;\n"
      "    z = sum;\n"
      "  }}\n",
      prefix, upper,
      rbf ? "      const @REAL@ e = x[k] - s[k];\n      acc += e * e;\n"
          : "      acc += x[k] * s[k];\n",
      rbf ? fmt::format("exp@F@(-{}_gamma * acc)", prefix) : "acc");
  return out;
}

}  // namespace fogdrift::svr
