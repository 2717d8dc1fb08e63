#include "fogdrift/features/features.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

TEST(FeatureSpec, ParsesTheTextFormAndRoundTrips) {
  const FeatureSpec paper = default_feature_spec();
  EXPECT_EQ(paper.to_string(), "T,dT,grad");
  EXPECT_EQ(paper.names(), (std::vector<std::string>{"T_fog_degc", "T_acc1_degc", "T_acc2_degc",
                                                     "dT_fog_degc_per_s", "dT_acc1_degc_per_s",
                                                     "dT_acc2_degc_per_s", "grad_fog_acc1_degc",
                                                     "grad_fog_acc2_degc", "grad_acc1_acc2_degc"}));
  const FeatureSpec custom = FeatureSpec::parse(" T(fog), dT(acc2,fog) ,dgrad(fog,acc2),t,TdT ");
  EXPECT_EQ(custom.to_string(), "T(fog),dT(fog,acc2),dgrad(fog,acc2),t,TdT");
  EXPECT_EQ(FeatureSpec::parse(custom.to_string()).to_string(), custom.to_string());
  EXPECT_EQ(custom.names(),
            (std::vector<std::string>{"T_fog_degc", "dT_fog_degc_per_s", "dT_acc2_degc_per_s",
                                      "dgrad_fog_acc2_degc_per_s", "t_s", "TdT_fog_degc2_per_s",
                                      "TdT_acc1_degc2_per_s", "TdT_acc2_degc2_per_s"}));
  EXPECT_EQ(FeatureSpec::parse("T(fog,acc1,acc2)").to_string(), "T");
}

// Further thermometers (docs/logs.md, "More thermometers"): numbered after the three in the order
// first named, each term's list in that order, read from temp_NAME_degc.
TEST(FeatureSpec, FurtherThermometersAreNumberedAsFirstNamed) {
  const FeatureSpec spec = FeatureSpec::parse("T(case,fog),dT(top,case),grad(fog,case)");
  EXPECT_EQ(spec.further, (std::vector<std::string>{"case", "top"}));
  EXPECT_EQ(spec.thermometer_count(), 5u);
  EXPECT_EQ(spec.to_string(), "T(fog,case),dT(case,top),grad(fog,case)");
  EXPECT_EQ(FeatureSpec::parse(spec.to_string()).to_string(), spec.to_string());
  EXPECT_EQ(FeatureSpec::parse(spec.to_string()).further, spec.further);
  EXPECT_EQ(spec.names(),
            (std::vector<std::string>{"T_fog_degc", "T_case_degc", "dT_case_degc_per_s",
                                      "dT_top_degc_per_s", "grad_fog_case_degc"}));
  EXPECT_TRUE(spec.reads(static_cast<Thermometer>(4)));
  EXPECT_FALSE(spec.reads(Thermometer::acc1));
  EXPECT_EQ(spec.thermometer_name(static_cast<Thermometer>(4)), "top");
  EXPECT_EQ(thermometer_column("top"), "temp_top_degc");
  // Bare terms read the list given (train --thermometers), written out in the canonical form.
  const FeatureSpec listed = FeatureSpec::parse("T,dT(fog)", {"fog", "case"});
  EXPECT_EQ(listed.to_string(), "T(fog,case),dT(fog)");
  EXPECT_EQ(FeatureSpec::parse("T,dT", {"fog", "acc1", "acc2"}).to_string(), "T,dT");
  EXPECT_EQ(default_feature_spec({"fog", "acc1", "acc2", "case"}).to_string(),
            "T(fog,acc1,acc2,case),dT(fog,acc1,acc2,case),grad(fog,acc1,acc2,case)");
  EXPECT_EQ(parse_thermometers("fog, case_2"), (std::vector<std::string>{"fog", "case_2"}));
  for (const char* bad : {"fog,fog", "fog,,acc1", "fog,Case", ""}) {
    try {
      parse_thermometers(bad);
      ADD_FAILURE() << bad;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "thermometers") << bad;
    }
  }
}

TEST(FeatureSpec, BadSpecsNameTheProblem) {
  auto message = [](const char* text) {
    try {
      FeatureSpec::parse(text);
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), "features");
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("T,dT,gradient").find("'gradient' is not a term"), std::string::npos);
  EXPECT_NE(message("T(fog,Gyro)").find("'Gyro' is not a thermometer"), std::string::npos);
  EXPECT_NE(message("T(fog,2nd)").find("'2nd' is not a thermometer"), std::string::npos);
  EXPECT_NE(message("T,T").find("'T' appears twice"), std::string::npos);
  EXPECT_NE(message("grad(fog)").find("'grad' needs at least two thermometers"), std::string::npos);
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("T,,dT").find("an empty term"), std::string::npos);
  EXPECT_NE(message("T(fog").find("no closing parenthesis"), std::string::npos);
  EXPECT_NE(message("t(fog)").find("'t' takes no thermometers"), std::string::npos);
  EXPECT_NE(message("T(fog,fog)").find("appears twice"), std::string::npos);
  EXPECT_NE(message("dT@0").find("'dT@0': the lag after '@' must be a number of seconds"),
            std::string::npos);
  EXPECT_NE(message("dT@-5").find("must be a number of seconds"), std::string::npos);
  EXPECT_NE(message("dT@600s").find("must be a number of seconds"), std::string::npos);
  EXPECT_NE(message("dT@").find("must be a number of seconds"), std::string::npos);
  EXPECT_NE(message("dT@1e9").find("at most 86400"), std::string::npos);
  EXPECT_NE(message("dT@600,T,dT@600(fog)").find("'dT@600' appears twice"), std::string::npos);
}

// dT@τ (features.hpp, LaggedRate): one term per time constant, its τ in the text and the names.
TEST(FeatureSpec, ALaggedRateCarriesItsTimeConstant) {
  const FeatureSpec spec = FeatureSpec::parse("T,dT@600(fog),dT@90.5(acc1,acc2)");
  EXPECT_EQ(spec.to_string(), "T,dT@600(fog),dT@90.5(acc1,acc2)");
  EXPECT_EQ(FeatureSpec::parse(spec.to_string()).to_string(), spec.to_string());
  EXPECT_EQ(spec.names(), (std::vector<std::string>{
                              "T_fog_degc", "T_acc1_degc", "T_acc2_degc", "dT600s_fog_degc_per_s",
                              "dT90.5s_acc1_degc_per_s", "dT90.5s_acc2_degc_per_s"}));
  const std::vector<FeatureColumn> columns = spec.columns();
  EXPECT_TRUE(columns[3].lagged());
  EXPECT_EQ(columns[3].tau_s, 600);
  EXPECT_EQ(columns[5].tau_s, 90.5);
  EXPECT_EQ(columns[5].a, Thermometer::acc2);
  EXPECT_FALSE(columns[0].lagged());
  // Not a rate of the differentiator: the guard's warm-up keeps it (guard.hpp).
  EXPECT_EQ(spec.rate_inputs(), (std::vector<bool>(6, false)));
  EXPECT_TRUE(spec.reads(Thermometer::acc2));
}

// train's default: the paper's inputs and their rates through the recommended lag, over the
// thermometers the unit has.
TEST(FeatureSpec, TrainsDefaultAddsTheLaggedRates) {
  EXPECT_EQ(recommended_feature_spec({"fog", "acc1", "acc2"}).to_string(), "T,dT,grad,dT@300");
  EXPECT_EQ(recommended_feature_spec({"fog", "acc1", "acc2"}).size(), 12u);
  EXPECT_EQ(recommended_feature_spec({"fog"}).to_string(), "T(fog),dT(fog),dT@300(fog)");
  const FeatureSpec four = recommended_feature_spec({"fog", "acc1", "acc2", "case"});
  EXPECT_EQ(four.to_string(),
            "T(fog,acc1,acc2,case),dT(fog,acc1,acc2,case),"
            "grad(fog,acc1,acc2,case),dT@300(fog,acc1,acc2,case)");
  EXPECT_EQ(four.size(), 18u);
  EXPECT_EQ(default_feature_spec().to_string(), "T,dT,grad");  // the paper's, for fogdrift paper
}

// A ramp T = a·t into the lag from rest: the error e = T − s obeys e_n = (1 − g)(e_(n−1) + a·dt),
// so e_n = a·dt·(1 − g)(1 − (1 − g)^n)/g, tending to the rate a, low-passed, times τ.
TEST(LaggedRate, FollowsARampInClosedForm) {
  const double tau = 300, dt = 1, a = 0.01;
  LaggedRate lag(tau, dt);
  const double q = std::exp(-dt / tau);  // 1 − g
  EXPECT_NEAR(lag.gain(), 1 - q, 1e-16);
  for (int n = 0; n <= 3000; ++n) {
    const double e = a * dt * q * (1 - std::pow(q, n)) / (1 - q);
    ASSERT_NEAR(lag.push(5.0 + a * dt * n), e / tau, 1e-15) << n;
  }
  // Far into the ramp the term is the rate, but for half a step of lag: a·dt/(τ(e^(dt/τ) − 1)).
  double far = 0;
  for (int n = 3001; n <= 12000; ++n) far = lag.push(5.0 + a * dt * n);
  EXPECT_NEAR(far, a * dt / (tau * std::expm1(dt / tau)), 1e-13);
  lag.reset();
  EXPECT_EQ(lag.push(40.0), 0.0);  // from rest again
  EXPECT_THROW(LaggedRate(0, 1), OptionError);
  EXPECT_THROW(LaggedRate(10, 0), OptionError);
}

// Temperatures that are quadratic in time: the centred degree-2 differentiator is exact, so every
// feature's block mean can be computed independently in closed form.
Recording quadratic_recording(std::size_t n, double dt) {
  Recording r;
  r.source = "quadratic.csv";
  for (std::size_t i = 0; i < n; ++i) {
    const double t = dt * static_cast<double>(i + 1);
    r.time_s.push_back(t);
    r.gyro_dph.push_back(0.0);
    r.temp_fog_degc.push_back(-10.0 + 0.02 * t - 1e-6 * t * t);
    r.temp_acc1_degc.push_back(-12.0 + 0.01 * t);
    r.temp_acc2_degc.push_back(-11.0 + 0.015 * t - 2e-6 * t * t);
  }
  return r;
}

// A further thermometer's column gives its features as the three give theirs: a recording whose
// fourth thermometer repeats acc2 has the same acc2 and "case" features; a recording without the
// column, or with text in it, is refused naming the column.
TEST(Features, AFurtherThermometerIsReadFromItsColumn) {
  Recording r = quadratic_recording(605, 1.0);
  ExtraColumn column{"temp_case_degc", {}};
  for (double v : r.temp_acc2_degc) column.cells.push_back(fmt::format("{:.17g}", v));
  r.extra.push_back(column);
  EXPECT_EQ(further_thermometers_of(r), std::vector<std::string>{"case"});
  const FeatureTable t = compute_features(r, FeatureSpec::parse("T(acc2,case),dT(acc2,case)"));
  ASSERT_EQ(t.names, (std::vector<std::string>{"T_acc2_degc", "T_case_degc", "dT_acc2_degc_per_s",
                                               "dT_case_degc_per_s"}));
  for (std::size_t row = 0; row < t.rows; ++row) {
    EXPECT_EQ(t.x[row * 4 + 0], t.x[row * 4 + 1]) << row;
    EXPECT_EQ(t.x[row * 4 + 2], t.x[row * 4 + 3]) << row;
  }
  try {
    compute_features(r, FeatureSpec::parse("T(fog,top)"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no temp_top_degc column, which the feature "
                                         "T_top_degc reads"),
              std::string::npos)
        << e.what();
  }
  r.extra.back().cells[7] = "n/a";
  try {
    compute_features(r, FeatureSpec::parse("T(fog,case)"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("quadratic.csv:9"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("temp_case_degc"), std::string::npos) << e.what();
  }
}

TEST(Features, BlockMeansOfExactFeatures) {
  const double dt = 1.0;
  const Recording r = quadratic_recording(605, dt);
  const FeatureSpec spec = FeatureSpec::parse("T,dT,grad,dgrad(fog,acc2),t,TdT(acc1)");
  const FeatureTable table = compute_features(r, spec);
  ASSERT_EQ(table.block, 10u);
  ASSERT_EQ(table.rows, 60u);  // 605 samples: the last 5 are a partial block
  ASSERT_EQ(table.names.size(), 12u);
  auto temp = [](int k, double t) {
    return k == 0 ? -10.0 + 0.02 * t - 1e-6 * t * t
                  : (k == 1 ? -12.0 + 0.01 * t : -11.0 + 0.015 * t - 2e-6 * t * t);
  };
  auto rate = [](int k, double t) {
    return k == 0 ? 0.02 - 2e-6 * t : (k == 1 ? 0.01 : 0.015 - 4e-6 * t);
  };
  for (std::size_t b = 0; b < table.rows; ++b) {
    std::vector<double> expect(12, 0.0);
    for (std::size_t j = 0; j < 10; ++j) {
      const double t = dt * static_cast<double>(b * 10 + j + 1);
      const double v[] = {temp(0, t),
                          temp(1, t),
                          temp(2, t),
                          rate(0, t),
                          rate(1, t),
                          rate(2, t),
                          temp(0, t) - temp(1, t),
                          temp(0, t) - temp(2, t),
                          temp(1, t) - temp(2, t),
                          rate(0, t) - rate(2, t),
                          t,
                          temp(1, t) * rate(1, t)};
      for (std::size_t c = 0; c < 12; ++c) expect[c] += v[c] / 10.0;
    }
    EXPECT_NEAR(table.time_s[b], expect[10], 1e-9);
    for (std::size_t c = 0; c < 12; ++c) {
      ASSERT_NEAR(table.x[b * 12 + c], expect[c], 1e-9) << table.names[c] << " block " << b;
    }
  }
}

// The lagged rate's block means are those of the recursion run on the recording's samples.
TEST(Features, ALaggedRateIsRunOnTheSamples) {
  const Recording r = quadratic_recording(605, 1.0);
  const FeatureTable table = compute_features(r, FeatureSpec::parse("T(fog),dT@120(fog,acc2)"));
  ASSERT_EQ(table.names, (std::vector<std::string>{"T_fog_degc", "dT120s_fog_degc_per_s",
                                                   "dT120s_acc2_degc_per_s"}));
  LaggedRate fog(120, 1.0), acc2(120, 1.0);
  std::vector<double> fog_rate, acc2_rate;
  for (std::size_t i = 0; i < r.size(); ++i) {
    fog_rate.push_back(fog.push(r.temp_fog_degc[i]));
    acc2_rate.push_back(acc2.push(r.temp_acc2_degc[i]));
  }
  for (std::size_t b = 0; b < table.rows; ++b) {
    double f = 0, g = 0;
    for (std::size_t j = 0; j < 10; ++j)
      f += fog_rate[b * 10 + j] / 10, g += acc2_rate[b * 10 + j] / 10;
    ASSERT_NEAR(table.x[b * 3 + 1], f, 1e-15) << b;
    ASSERT_NEAR(table.x[b * 3 + 2], g, 1e-15) << b;
  }
  // After 5 time constants the fog's term is its rate, 0.02 − 2e-6·t °C/s, a time constant late,
  // to 1.5 % (the start's e^(−5), the half step of lag).
  EXPECT_NEAR(table.x[59 * 3 + 1], 0.02 - 2e-6 * (595.5 - 120), 3e-4);
}

TEST(Features, IrregularSamplingIsAnInputErrorWithTheLine) {
  Recording r = quadratic_recording(300, 1.0);
  r.time_s[100] += 0.5;  // sample 100 is on line 102; its step is the first irregular one
  try {
    compute_features(r, default_feature_spec());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "quadratic.csv");
    EXPECT_EQ(e.line(), 102u);
    EXPECT_NE(e.message().find("uniform sampling"), std::string::npos);
  }
}

TEST(Features, TooShortForTheWindowOrABlock) {
  const Recording r = quadratic_recording(100, 1.0);
  try {
    compute_features(r, default_feature_spec());  // 121 s centred window
    FAIL();
  } catch (const OptionError& e) {
    // The setting a user can change, and the recording that cannot meet it.
    EXPECT_EQ(e.option(), "window_s");
    EXPECT_NE(e.message().find("window of 121 samples is longer than the signal (100"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.message().find("quadratic.csv"), std::string::npos) << e.what();
  }
  FeatureOptions options;
  options.rates.window_s = 5.0;
  options.block.block_s = 200.0;
  try {
    compute_features(r, default_feature_spec(), options);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("fewer than one averaging block"), std::string::npos);
  }
  options.block.block_s = 2.5;
  EXPECT_THROW(compute_features(r, default_feature_spec(), options), OptionError);
}

}  // namespace
}  // namespace fogdrift
