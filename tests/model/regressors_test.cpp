// The registry (regressors.hpp): every registered type models Regressor, a type missing a part
// does not, and model files name and parse each type through one table.
#include "fogdrift/model/regressors.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

// A regressor with every part but its C: the concept refuses it, so the registry would not
// compile with it.
struct WithoutC {
  static constexpr std::string_view kType = "without-c";
  std::size_t inputs = 1;
  double predict(const double* x) const noexcept { return x[0]; }
};
std::size_t input_count(const WithoutC& r) {
  return r.inputs;
}
std::string to_json(const WithoutC&) {
  return "{}";
}
WithoutC regressor_from_json(std::type_identity<WithoutC>, const std::string&, const std::string&) {
  return {};
}
static_assert(!Regressor<WithoutC>);
static_assert(!Regressor<int>);
static_assert(Regressor<svr::Model> && Regressor<Mlp> && Regressor<Poly> && Regressor<Gp>);

AnyRegressor example(std::string_view type) {
  if (type == "svr") {
    svr::Model m;
    m.kernel = svr::Kernel::rbf_gamma(0.5);
    m.dims = 2;
    m.support_vectors = {0.1, 0.2, -0.3, 0.4};
    m.coef = {1.5, -0.5};
    m.rho = 0.25;
    return m;
  }
  if (type == "mlp") {
    Mlp m;
    m.inputs = 2, m.hidden = 1, m.w1 = {0.5, -0.25}, m.b1 = {0.1}, m.w2 = {2}, m.b2 = -0.3;
    return m;
  }
  if (type == "gp") {
    Gp g;
    g.inputs = 2, g.hyper = {0.8, {1.0, 2.0}, 0.01};
    g.points = {0.1, 0.2, -0.3, 0.4}, g.alpha = {0.5, -1.5};
    return g;
  }
  Poly p;
  p.inputs = 2, p.degree = 1, p.exponents = monomials(2, 1), p.coef = {1, 2, 3};
  return p;
}

TEST(Regressors, EachTypeRoundTripsThroughTheRegistry) {
  EXPECT_EQ(regressor_types(), "svr, mlp, poly or gp");
  const double x[2] = {0.3, -0.7};
  for (std::string_view type : {"svr", "mlp", "poly", "gp"}) {
    const AnyRegressor r = example(type);
    EXPECT_EQ(regressor_type(r), type);
    EXPECT_TRUE(is_regressor_type(type));
    EXPECT_EQ(input_count(r), 2u);
    const nlohmann::json j = nlohmann::json::parse(to_json(r));
    EXPECT_EQ(j.at("type"), type);
    nlohmann::json own = j;
    own.erase("type");
    const AnyRegressor back =
        fogdrift::regressor_from_json(std::string(type), own.dump(), "m.json");
    EXPECT_EQ(to_json(back), to_json(r)) << type;
    EXPECT_EQ(std::visit([&](const auto& m) { return m.predict(x); }, back),
              std::visit([&](const auto& m) { return m.predict(x); }, r))
        << type;
    const CRegressor c = to_c(r, {"unit", "UNIT"});
    EXPECT_NE(c.body.find("z"), std::string::npos) << type;
    EXPECT_NE(c.tables.find("unit_"), std::string::npos) << type;
  }
}

TEST(Regressors, AnUnknownTypeIsNamed) {
  EXPECT_FALSE(is_regressor_type("rf"));
  try {
    fogdrift::regressor_from_json("rf", "{}", "m.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'rf' is not svr, mlp, poly or gp"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
