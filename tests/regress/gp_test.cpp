// The Gaussian process against scikit-learn's GaussianProcessRegressor on the same kernel
// (tests/data/gp/make_gp_reference.py, written at build time), scored in agreeing digits.
#include "fogdrift/regress/gp.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "signal/signal_reference.hpp"

namespace fogdrift {
namespace {

using test::agreeing_digits;
using test::relative_error;

const nlohmann::json& gp_reference() {
  static const nlohmann::json reference = [] {
    std::ifstream in(FOGDRIFT_GP_REFERENCE);
    if (!in) throw std::runtime_error("missing " FOGDRIFT_GP_REFERENCE " (python3-sklearn)");
    return nlohmann::json::parse(in);
  }();
  return reference;
}

Data data_of(const nlohmann::json& c) {
  Data d;
  d.rows = c.at("rows").get<std::size_t>();
  d.cols = c.at("cols").get<std::size_t>();
  d.x = c.at("x").get<std::vector<double>>();
  d.y = c.at("y").get<std::vector<double>>();
  return d;
}

GpHyper hyper_of(const nlohmann::json& c) {
  return {c.at("signal_variance").get<double>(), c.at("length_scale").get<std::vector<double>>(),
          c.at("noise_variance").get<double>()};
}

TEST(Gp, AgreesWithScikitLearnAtGivenHyperparameters) {
  for (const auto& c : gp_reference().at("cases")) {
    const std::string name = c.at("name").get<std::string>();
    const bool ard = c.at("ard").get<bool>();
    const Data data = data_of(c);
    const GpHyper hyper = hyper_of(c);
    const GpLikelihood l = log_marginal_likelihood(data, hyper, ard);
    const double expected = c.at("log_likelihood").get<double>();
    EXPECT_GE(agreeing_digits(std::abs(l.value - expected) / std::abs(expected)), 11) << name;
    const auto gradient = c.at("gradient").get<std::vector<double>>();
    EXPECT_GE(agreeing_digits(relative_error(l.gradient, gradient)), 10) << name;

    const GpPosterior post = fit_gp(data, hyper);
    const auto x = c.at("x_test").get<std::vector<double>>();
    const auto mean = c.at("mean").get<std::vector<double>>();
    const auto std_with_noise = c.at("std_with_noise").get<std::vector<double>>();
    std::vector<double> m, s;
    for (std::size_t i = 0; i < mean.size(); ++i) {
      m.push_back(post.gp.predict(x.data() + i * data.cols));
      // scikit-learn's standard deviation is of y: the latent variance plus the white noise.
      s.push_back(std::sqrt(post.variance(x.data() + i * data.cols) + hyper.noise_variance));
    }
    EXPECT_LE(relative_error(m, mean), 1e-8) << name;
    EXPECT_LE(relative_error(s, std_with_noise), 1e-8) << name;
    // The factor rebuilt from the model alone gives the same variance.
    const GpPosterior again = factor(post.gp);
    EXPECT_DOUBLE_EQ(again.variance(x.data()), post.variance(x.data())) << name;
  }
}

// From the same start and within the same bounds, the likelihood search reaches scikit-learn's
// optimum (its L-BFGS-B): the same likelihood to 6 digits and the same hyperparameters to 2-3.
TEST(Gp, FindsScikitLearnsOptimum) {
  for (const auto& c : gp_reference().at("cases")) {
    const std::string name = c.at("name").get<std::string>();
    const Data data = data_of(c);
    GpOptions o;
    o.selection = GpSelection::likelihood;
    o.ard = c.at("ard").get<bool>();
    o.max_iterations = 1000;
    const GpFit fit = train_gp(data, o);
    const auto& opt = c.at("optimised");
    const double best = opt.at("log_likelihood").get<double>();
    EXPECT_TRUE(fit.summary.converged) << name;
    EXPECT_EQ(fit.summary.points, data.rows);
    EXPECT_GE(fit.summary.log_likelihood, best - 1e-6 * std::abs(best)) << name;
    EXPECT_NEAR(fit.summary.log_likelihood, best, 1e-5 * std::abs(best)) << name;
    const GpHyper h = fit.posterior.gp.hyper;
    EXPECT_NEAR(std::log(h.signal_variance), std::log(opt.at("signal_variance").get<double>()),
                1e-2)
        << name;
    EXPECT_NEAR(std::log(h.noise_variance), std::log(opt.at("noise_variance").get<double>()), 1e-2)
        << name;
    const auto length = opt.at("length_scale").get<std::vector<double>>();
    for (std::size_t k = 0; k < length.size(); ++k)
      EXPECT_NEAR(std::log(h.length_scale[k]), std::log(length[k]), 1e-2) << name << " ℓ" << k;
  }
}

// The likelihood's gradient against central differences of the likelihood itself.
TEST(Gp, GradientIsTheLikelihoodsSlope) {
  const auto& c = gp_reference().at("cases").at(0);
  const Data data = data_of(c);
  const GpHyper h0 = hyper_of(c);
  const GpLikelihood l = log_marginal_likelihood(data, h0);
  const std::size_t p = l.gradient.size();
  for (std::size_t i = 0; i < p; ++i) {
    auto at = [&](double step) {
      GpHyper h = h0;
      double& v = i == 0       ? h.signal_variance
                  : i + 1 == p ? h.noise_variance
                               : h.length_scale[i - 1];
      v *= std::exp(step);
      return log_marginal_likelihood(data, h).value;
    };
    const double step = 1e-5;
    EXPECT_NEAR(l.gradient[i], (at(step) - at(-step)) / (2 * step),
                1e-5 * (1 + std::abs(l.gradient[i])))
        << i;
  }
}

TEST(Gp, KeepsEvenlySpacedRows) {
  EXPECT_EQ(gp_rows(5, 800), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(gp_rows(10, 4), (std::vector<std::size_t>{0, 2, 5, 7}));
  const auto rows = gp_rows(10000, 800);
  ASSERT_EQ(rows.size(), 800u);
  for (std::size_t i = 1; i < rows.size(); ++i)
    EXPECT_TRUE(rows[i] - rows[i - 1] == 12 || rows[i] - rows[i - 1] == 13) << i;
  EXPECT_EQ(rows.back(), 9987u);
}

TEST(Gp, JsonRoundTripPredictsTheSame) {
  const auto& c = gp_reference().at("cases").at(1);
  const GpPosterior post = fit_gp(data_of(c), hyper_of(c));
  const Gp back = regressor_from_json(std::type_identity<Gp>{}, to_json(post.gp), "gp.json");
  EXPECT_EQ(to_json(back), to_json(post.gp));
  const auto x = c.at("x_test").get<std::vector<double>>();
  for (std::size_t i = 0; i < x.size() / back.inputs; ++i)
    EXPECT_EQ(back.predict(x.data() + i * back.inputs),
              post.gp.predict(x.data() + i * back.inputs));
}

TEST(Gp, RejectsBadFilesAndOptionsByName) {
  const std::string good =
      R"({"inputs":2,"signal_variance":1,"length_scale":[1,2],"noise_variance":0.1,)"
      R"("points":[0,0,1,1],"alpha":[0.5,-0.5]})";
  EXPECT_NO_THROW(regressor_from_json(std::type_identity<Gp>{}, good, "m.json"));
  auto message = [](const std::string& text) {
    try {
      regressor_from_json(std::type_identity<Gp>{}, text, "m.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return message(t);
  };
  EXPECT_NE(with("\"length_scale\":[1,2]", "\"length_scale\":[1]").find("length_scale"),
            std::string::npos);
  EXPECT_NE(with("\"noise_variance\":0.1", "\"noise_variance\":0").find("noise_variance"),
            std::string::npos);
  EXPECT_NE(with("\"points\":[0,0,1,1]", "\"points\":[0,0,1]").find("points"), std::string::npos);
  EXPECT_NE(with("\"alpha\":[0.5,-0.5]", "\"alpha\":\"x\"").find("alpha"), std::string::npos);
  EXPECT_NE(with("\"inputs\":2", "\"inputs\":2.5").find("inputs"), std::string::npos);
  EXPECT_NE(message(good).find("no error"), std::string::npos);

  GpOptions o;
  o.max_points = 5;
  EXPECT_THROW(validate(o), OptionError);
  o.max_points = 800;
  o.max_iterations = 0;
  EXPECT_THROW(validate(o), OptionError);
  // Repeated rows without noise cannot be factored: an error that says so, not a NaN model.
  Data twice;
  twice.rows = 2, twice.cols = 1, twice.x = {1, 1}, twice.y = {0, 1};
  EXPECT_THROW(fit_gp(twice, {1, {1}, 1e-300}), OptionError);
}

}  // namespace
}  // namespace fogdrift
