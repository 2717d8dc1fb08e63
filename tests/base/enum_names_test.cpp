#include "fogdrift/base/enum_names.hpp"

#include <gtest/gtest.h>

#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/signal/dwt.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift {
namespace {

enum class Colour { red, green };
constexpr std::array<EnumName<Colour>, 3> kColourNames = {
    {{Colour::red, "red"}, {Colour::green, "green"}, {Colour::red, "rouge"}}};

TEST(EnumNames, CanonicalNamesAliasesAndMessages) {
  EXPECT_EQ(name_in(kColourNames, Colour::red), "red");  // the first entry, not the alias
  EXPECT_EQ(find_in(kColourNames, "rouge"), Colour::red);
  EXPECT_FALSE(find_in(kColourNames, "blue").has_value());
  EXPECT_EQ(names_in(kColourNames), "red, green");  // aliases are not listed
  try {
    parse_in(kColourNames, "blue", "--colour", "a colour");
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--colour");
    EXPECT_EQ(e.message(), "'blue' is not a colour (red, green)");
  }
}

// Every value of the library's enums has a name that parses back to it.
TEST(EnumNames, LibraryEnumsRoundTrip) {
  for (auto f : {tune::Fitness::cv, tune::Fitness::train})
    EXPECT_EQ(tune::parse_fitness(tune::to_string(f)), f);
  for (auto c : {tune::CvScheme::automatic, tune::CvScheme::repetition, tune::CvScheme::recording,
                 tune::CvScheme::temperature})
    EXPECT_EQ(tune::parse_cv_scheme(tune::to_string(c)), c);
  for (auto a : sim::kApproaches)
    EXPECT_EQ(sim::approach_from_string(sim::to_string(a), "--approach"), a);
  for (auto e : {signal::Extension::symmetric, signal::Extension::periodization,
                 signal::Extension::zero, signal::Extension::periodic})
    EXPECT_EQ(signal::parse_extension(signal::to_string(e)), e);
  EXPECT_EQ(signal::parse_causality("centered"), signal::Causality::centred);
  EXPECT_EQ(signal::parse_causality("online"), signal::Causality::causal);
  EXPECT_EQ(to_string(Scenario::northfind), "northfind");
  EXPECT_EQ(to_string(Role::test), "test");
}

}  // namespace
}  // namespace fogdrift
