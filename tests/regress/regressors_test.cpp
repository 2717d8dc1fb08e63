// AnyRegressor and the registry's lookups (regressors.hpp): a type missing a part does not model
// Regressor, any registered one is held and named, and a type not registered is refused by name.
// Every registered regressor's fit, file and C is the registry's suite (train/registry_test.cpp).
#include "fogdrift/regress/regressors.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/regress/gp.hpp"
#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/regress/poly.hpp"
#include "fogdrift/svr/svr.hpp"

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

TEST(Regressors, HoldsAnyRegistered) {
  Poly p;
  p.inputs = 2, p.degree = 1, p.exponents = monomials(2, 1), p.coef = {1, 2, 3};
  const AnyRegressor r(p);
  const AnyRegressor copy = r;
  const double x[2] = {0.3, -0.7};
  EXPECT_EQ(regressor_type(copy), "poly");
  EXPECT_EQ(input_count(copy), 2u);
  EXPECT_EQ(predict(copy, x), p.predict(x));
  ASSERT_NE(copy.get_if<Poly>(), nullptr);
  EXPECT_EQ(copy.get_if<Mlp>(), nullptr);
  EXPECT_THROW(copy.get<Gp>(), std::logic_error);
  const AnyRegressor empty;
  EXPECT_FALSE(empty.has_value());
  EXPECT_THROW(regressor_type(empty), std::logic_error);
  // The model file's object: "type" first, then the regressor's own fields.
  const std::string text = to_json(r);
  EXPECT_TRUE(text.starts_with(R"({"type":"poly",)")) << text;
  EXPECT_EQ(nlohmann::json::parse(text).at("degree"), 1);
}

TEST(Regressors, AnUnknownTypeIsNamed) {
  EXPECT_FALSE(is_regressor_type("rf"));
  try {
    fogdrift::regressor_from_json("rf", "{}", "m.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'rf' is not " + regressor_types()), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
