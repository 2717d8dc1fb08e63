// Every training method on a small grouped dataset, and the model file: exact round trips,
// one seed one file, and clear errors for files fogdrift cannot read.
#include "fogdrift/train/train.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/train/bp_trainer.hpp"
#include "fogdrift/train/gp_trainer.hpp"
#include "fogdrift/train/poly_trainer.hpp"
#include "synthetic_dataset.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

TrainOptions quick(Method method, ThreadPool* pool = nullptr) {
  TrainOptions o;
  o.method = method;
  o.tune.optimizer.run.population = 8;
  o.tune.optimizer.run.iterations = 5;
  o.tune.space.c_max = 10;
  o.tune.cv = {tune::CvScheme::repetition};  // the synthetic data's repetitions, as written
  o.tune.pool = pool;
  o.trainers.get<MlpOptions>().max_epochs = 500;
  return o;
}

double rmse_dph(const CompensationModel& m, const Dataset& d) {
  const auto p = m.predict_dph(d);
  double s = 0;
  for (std::size_t i = 0; i < d.rows; ++i) s += std::pow(p[i] - d.y[i], 2);
  return std::sqrt(s / d.rows);
}

double sd(const std::vector<double>& y) {
  double m = 0, s = 0;
  for (double v : y) m += v;
  m /= y.size();
  for (double v : y) s += (v - m) * (v - m);
  return std::sqrt(s / (y.size() - 1));
}

TEST(Train, EveryMethodExplainsTheDrift) {
  const Dataset d = test::synthetic();
  for (Method m :
       {Method::ssa_svr, Method::pso_svr, Method::gwo_svr, Method::svr, Method::bp, Method::poly}) {
    const TrainResult r = train(d, test::kDefaultDataset, quick(m));
    EXPECT_LT(rmse_dph(r.model, d), 0.5 * sd(d.y)) << to_string(m);
    EXPECT_GT(r.summary.fitness_value, 0) << to_string(m);
    EXPECT_LT(r.summary.fitness_value, 0.5) << to_string(m);
    EXPECT_EQ(r.model.provenance.method, to_string(m));
    EXPECT_FALSE(r.summary.hyperparameters.empty());
  }
  // The untuned SVR is LIBSVM's default: C = 1, γ = 1/3.
  const TrainResult svr = train(d, test::kDefaultDataset, quick(Method::svr));
  const auto& model = svr.model.regressor.get<svr::Model>();
  EXPECT_DOUBLE_EQ(model.kernel.gamma, 1.0 / 3);
  EXPECT_EQ(svr.model.provenance.hyperparameters[0], (std::pair<std::string, double>{"C", 1.0}));
}

TEST(Train, OneSeedOneFileWhateverTheThreadCount) {
  const Dataset d = test::synthetic();
  ThreadPool one(1), two(2);
  for (Method m : {Method::ssa_svr, Method::bp}) {
    const std::string a = to_json(train(d, test::kDefaultDataset, quick(m, &one)).model);
    const std::string b = to_json(train(d, test::kDefaultDataset, quick(m, &two)).model);
    EXPECT_EQ(a, b) << to_string(m);
    TrainOptions other = quick(m, &two);
    other.tune.optimizer.run.seed = 9;
    EXPECT_NE(to_json(train(d, test::kDefaultDataset, other).model), a) << to_string(m);
  }
}

TEST(Train, BpStopsOnRecordingsDealtAcrossTemperaturesAndRepetitions) {
  // BP is not refitted after early stopping: a fold of whole temperatures (or a repetition that
  // is a start-up condition of its own) would leave them out of its training, so with temperature
  // or automatic folds it holds out a third of the recordings, dealt across both.
  const Dataset d = test::synthetic();
  TrainOptions by_temperature = quick(Method::bp), automatic = quick(Method::bp),
               by_recording = quick(Method::bp);
  by_temperature.tune.cv = {tune::CvScheme::temperature, 2};
  automatic.tune.cv = {};
  by_recording.tune.cv = {tune::CvScheme::recording, 3};
  const TrainResult t = train(d, test::kDefaultDataset, by_temperature);
  EXPECT_EQ(to_json(t.model), to_json(train(d, test::kDefaultDataset, automatic).model));
  EXPECT_EQ(to_json(t.model), to_json(train(d, test::kDefaultDataset, by_recording).model));
  EXPECT_EQ(t.model.provenance.cv, "early stopping on recordings 3/3");
  // Asked for, a repetition it is.
  EXPECT_EQ(train(d, test::kDefaultDataset, quick(Method::bp)).model.provenance.cv,
            "early stopping on repetition 3");
}

TEST(ModelFile, RoundTripsExactly) {
  const Dataset d = test::synthetic();
  test::TempDir dir;
  for (Method m : {Method::ssa_svr, Method::bp, Method::poly}) {
    CompensationModel model = train(d, test::kDefaultDataset, quick(m)).model;
    model.provenance.files = {{"a.csv", std::string(64, 'f')}};
    save(model, dir / "m.json");
    const CompensationModel back = load_compensation_model(dir / "m.json");
    EXPECT_EQ(to_json(back), to_json(model)) << to_string(m);
    const auto p1 = model.predict_dph(d), p2 = back.predict_dph(d);
    for (std::size_t i = 0; i < d.rows; ++i) ASSERT_EQ(p1[i], p2[i]) << to_string(m);
  }
}

std::string error_of(const std::string& text) {
  try {
    compensation_model_from_json(text, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ModelFile, RejectsWhatItCannotRead) {
  const Dataset d = test::synthetic();
  const std::string good = to_json(train(d, test::kDefaultDataset, quick(Method::poly)).model);
  auto edit = [&](auto&& change) {
    auto j = nlohmann::ordered_json::parse(good);
    change(j);
    return j.dump();
  };
  EXPECT_NE(error_of(edit([](auto& j) { j["version"] = 4; })).find("written by a newer fogdrift"),
            std::string::npos);
  // Version 3: content that does not match its checksum is refused, unless the user says the
  // edit was deliberate; line ends changed to CRLF are the same content.
  const std::string edited = edit([](auto& j) { j["scalers"]["drift_dph"]["mean"] = 0.5; });
  EXPECT_NE(error_of(edited).find("m.json: checksum: the content does not match its checksum"),
            std::string::npos);
  EXPECT_EQ(compensation_model_from_json(edited, "m.json", {true}).y_scaler.mean[0], 0.5);
  EXPECT_NO_THROW(compensation_model_from_json(good, "m.json"));
  std::string crlf;
  for (char c : good) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_NO_THROW(compensation_model_from_json(crlf, "m.json"));
  EXPECT_NE(error_of(edit([](auto& j) { j.erase("checksum"); })).find("m.json: checksum: required"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) { j["format"] = "fogdrift-svr"; })).find("m.json: format"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) {
              j["scalers"]["features"]["scale"][0] = 0;
            })).find("scalers.features.scale"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) {
              j["features"]["names"].push_back("extra");
            })).find("features.names"),
            std::string::npos);
  // Bounds on every number (model.hpp, docs/reliability.md "Finite values").
  EXPECT_NE(error_of(edit([](auto& j) {
              j["scalers"]["features"]["scale"][0] = 5e-324;
            })).find("scalers.features.scale"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) {
              j["scalers"]["features"]["mean"][0] = 1.7e308;
            })).find("scalers.features.mean"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) { j["regressor"]["type"] = "forest"; })).find("forest"),
            std::string::npos);
  // The novelty guard (format version 2): its points must fit the features, its policy its rules.
  EXPECT_NE(
      error_of(edit([](auto& j) { j["guard"]["points"].push_back(0.5); })).find("guard.points"),
      std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) { j["guard"]["radius"] = 0; })).find("guard.radius"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) { j["guard"]["zero_at"] = 1.5; })).find("guard.zero_at"),
            std::string::npos);
  EXPECT_NE(error_of(edit([](auto& j) { j["guard"].erase("recover_s"); })).find("m.json: guard"),
            std::string::npos);
  // A version-1 file (before the guard) loads when the user accepts a file with no checksum,
  // and compensates unguarded; the refusal says what the file lacks.
  const std::string v1_text = edit([](auto& j) {
    j["version"] = 1;
    j.erase("guard");
    j.erase("checksum");
  });
  EXPECT_NE(error_of(v1_text).find("m.json: version: format version 1 carries no checksum and no "
                                   "novelty guard"),
            std::string::npos);
  const CompensationModel v1 =
      compensation_model_from_json(v1_text, "v1.json", {.allow_old_format = true});
  EXPECT_TRUE(v1.guard.empty());
  // Found by attack (issue 36, "checksum bypass"): an edited file whose version was lowered to
  // one without checksums is still checked against the checksum it carries.
  for (int version : {1, 2}) {
    const std::string lowered = edit([version](auto& j) {
      j["version"] = version;
      j["scalers"]["drift_dph"]["mean"] = 9.5;
    });
    EXPECT_NE(error_of(lowered).find("m.json: checksum: the content does not match"),
              std::string::npos)
        << version;
    try {
      compensation_model_from_json(lowered, "m.json", {.allow_old_format = true});
      ADD_FAILURE() << "version " << version << " loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << e.what();
    }
  }
  EXPECT_NE(error_of(edit([](auto& j) { j["provenance"].erase("seed"); })).find("provenance"),
            std::string::npos);
  // Found by attack (issue 36, "reader leniency"): the JSON library's tag was shown raw.
  EXPECT_EQ(error_of(edit([](auto& j) { j["provenance"].erase("seed"); })),
            "m.json: provenance: missing or mistyped field (key 'seed' not found)");
  EXPECT_NE(error_of(edit([](auto& j) { j["features"]["spec"] = "T,bogus"; })).find("features"),
            std::string::npos);
  EXPECT_NE(error_of("{\"format\": ").find("m.json:1:"), std::string::npos);
}

// Found by attack (issue 36, "infinity"): a model edited to coefficients of 1e308 wrote
// drift_dph = inf. A batch prediction that is not finite is an error naming the recording.
TEST(ModelFile, ADriftThatIsNotFiniteIsAnErrorNotAnOutput) {
  const Dataset d = test::synthetic();
  auto j = nlohmann::ordered_json::parse(
      to_json(train(d, test::kDefaultDataset, quick(Method::poly)).model));
  // Coefficients within the load bounds (1e12) that still give a drift of millions of training
  // STDs: beyond kDriftLimitScales, no drift it can stand by.
  for (auto& c : j["regressor"]["coef"]) c = 1e11;
  const CompensationModel edited = compensation_model_from_json(j.dump(), "m.json", {true});
  try {
    edited.predict_dph(d, false);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(d.groups[0].file + ": at time_s"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("no drift it can stand by"), std::string::npos)
        << e.what();
  }
}

TEST(Train, RejectsImpossibleOptions) {
  const Dataset d = test::synthetic();
  TrainOptions o = quick(Method::poly);
  o.trainers.get<PolyTrainer::Options>().max_degree = 9;
  EXPECT_THROW(train(d, test::kDefaultDataset, o), OptionError);
  EXPECT_THROW(parse_method("rf"), OptionError);
  EXPECT_EQ(parse_method("gwo-svr"), Method::gwo_svr);
  EXPECT_THROW(train(Dataset{}, test::kDefaultDataset, quick(Method::svr)), OptionError);
}

// A method is a regressor and a search: svr searched by pso is pso-svr, to the byte; a gp's
// search may be any optimizer, and its model says which; contradictions name the search.
TEST(Train, AMethodIsARegressorAndASearch) {
  const Dataset d = test::synthetic();
  for (const auto& [search, method] :
       {std::pair{Search::ssa, Method::ssa_svr}, std::pair{Search::pso, Method::pso_svr},
        std::pair{Search::gwo, Method::gwo_svr}}) {
    TrainOptions o = quick(Method::svr);
    o.search = search;
    EXPECT_EQ(resolved(o).method, method);
    EXPECT_EQ(to_json(train(d, test::kDefaultDataset, o).model),
              to_json(train(d, test::kDefaultDataset, quick(method)).model))
        << to_string(search);
    TrainOptions own = quick(method);
    own.search = search;  // the method's own search, said again
    EXPECT_EQ(resolved(own).method, method);
  }
  TrainOptions none = quick(Method::svr);
  none.search = Search::none;
  EXPECT_EQ(resolved(none).method, Method::svr);

  TrainOptions gp = quick(Method{"gp"});
  gp.trainers.get<GpOptions>().max_points = 60;
  gp.search = Search::pso;
  EXPECT_EQ(resolved(gp).tune.optimizer.algorithm, opt::Algorithm::pso);
  const CompensationModel by_pso = train(d, test::kDefaultDataset, gp).model;
  EXPECT_EQ(by_pso.provenance.search, "pso");
  EXPECT_EQ(compensation_model_from_json(to_json(by_pso), "gp").provenance.search, "pso");
  gp.search = Search::own;
  EXPECT_EQ(train(d, test::kDefaultDataset, gp).model.provenance.search, "");
  EXPECT_EQ(to_json(train(d, test::kDefaultDataset, gp).model).find("\"search\""),
            std::string::npos);

  const auto refused = [](Method method, Search search) {
    TrainOptions o = quick(method);
    o.search = search;
    try {
      validate(o);
    } catch (const OptionError& e) {
      return e.option();
    }
    return std::string();
  };
  EXPECT_EQ(refused(Method::ssa_svr, Search::pso), "search");
  EXPECT_EQ(refused(Method::gwo_svr, Search::none), "search");
  EXPECT_EQ(refused(Method::bp, Search::ssa), "search");
  EXPECT_EQ(refused(Method::poly, Search::gwo), "search");
  EXPECT_EQ(refused(Method{"gp"}, Search::none), "search");
  EXPECT_EQ(refused(Method::bp, Search::none), "");
  EXPECT_EQ(parse_search("auto"), Search::own);
  EXPECT_THROW(parse_search("fast"), OptionError);
}

}  // namespace
}  // namespace fogdrift
