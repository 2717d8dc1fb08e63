// Methods are a trainer and a search (method.hpp), named by the registry's trainers
// (trainers.hpp); a trainer that lacks a part is not one.
#include "fogdrift/train/method.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "fogdrift/base/error.hpp"
#include "fogdrift/train/trainers.hpp"

namespace fogdrift {
namespace {

// A trainer without its train(): the registry's entry_of<> refuses it at compile time.
struct NoTrain {
  static constexpr std::string_view kName = "none";
  static constexpr std::array<MethodName, 1> kMethods = {{{"none", Search::own, ""}}};
  static Search search(Search s, const TrainOptions&) { return s; }
  static void validate(const TrainOptions&) {}
};
static_assert(!Trainer<NoTrain>);

TEST(Method, EveryNameIsOneMethodAndBack) {
  std::set<std::string_view> names, trainers;
  for (const TrainerEntry& t : trainer_entries()) {
    EXPECT_TRUE(trainers.insert(t.name).second) << t.name;
    bool own = false;
    for (const MethodName& m : t.methods) {
      EXPECT_TRUE(names.insert(m.name).second) << m.name;
      const Method parsed = parse_method(m.name);
      EXPECT_EQ(parsed.trainer, t.name);
      EXPECT_EQ(parsed.search, m.search);
      EXPECT_EQ(to_string(parsed), m.name);
      EXPECT_NE(method_docs().find(std::string(m.name) + " "), std::string::npos) << m.name;
      EXPECT_FALSE(m.doc.empty()) << m.name;
      own = own || m.search == Search::own;
    }
    EXPECT_TRUE(own) << t.name << " has no name for its own search";
  }
  // The paper's methods first, then every other registered one (the registry's order).
  const std::string all = method_names();
  EXPECT_TRUE(all.starts_with("ssa-svr, pso-svr, gwo-svr, svr, bp, poly, gp")) << all;
  EXPECT_EQ(std::count(all.begin(), all.end(), ',') + 1, static_cast<std::ptrdiff_t>(names.size()));
}

TEST(Method, ASearchNotInTheNameIsTheTrainers) {
  EXPECT_EQ(to_string(Method{"gp", Search::pso}), "gp");
  EXPECT_EQ(to_string(Method{"svr", Search::none}), "svr");
  EXPECT_EQ(to_string(Method{"svr", Search::gwo}), "gwo-svr");
  EXPECT_EQ(Method::pso_svr, parse_method("pso-svr"));
  EXPECT_TRUE(Method::svr < Method::pso_svr || Method::pso_svr < Method::svr);
}

TEST(Method, UnknownNamesAreRefusedByOption) {
  try {
    parse_method("rf", "--methods");
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--methods");
    EXPECT_NE(std::string(e.what()).find("ssa-svr, pso-svr"), std::string::npos);
  }
  EXPECT_THROW(to_string(Method{"rf"}), OptionError);
  EXPECT_THROW(parse_search("fast"), OptionError);
  EXPECT_TRUE(is_optimizer(Search::gwo));
  EXPECT_FALSE(is_optimizer(Search::own));
}

}  // namespace
}  // namespace fogdrift
