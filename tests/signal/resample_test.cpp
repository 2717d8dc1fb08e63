#include "fogdrift/signal/resample.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

TEST(Resample, BlockMeansAndTrailingPartialBlockDropped) {
  std::vector<double> x(25);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = double(i);
  const auto means = block_average(x, 10);
  ASSERT_EQ(means.size(), 2u);  // samples 20..24 are a partial block
  EXPECT_DOUBLE_EQ(means[0], 4.5);
  EXPECT_DOUBLE_EQ(means[1], 14.5);
  EXPECT_TRUE(block_average(std::vector<double>(9, 1.0), 10).empty());
  EXPECT_EQ(block_average(x, 1), x);
}

TEST(Resample, BlockLengthMustBeAWholeNumberOfSamples) {
  EXPECT_EQ(block_samples({10.0}, 1.0), 10u);
  EXPECT_EQ(block_samples({10.0}, 0.1), 100u);
  EXPECT_EQ(block_samples({1.0}, 1.0), 1u);
  try {
    block_samples({2.5}, 1.0);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "block_s");
    EXPECT_NE(std::string(e.what()).find("not a whole multiple"), std::string::npos);
  }
  EXPECT_THROW(block_samples({0.5}, 1.0), OptionError);
  EXPECT_THROW(block_samples({0.0}, 1.0), OptionError);
  EXPECT_THROW(block_samples({10.0}, 0.0), OptionError);
  EXPECT_THROW(block_average(std::vector<double>{1.0}, 0), OptionError);
}

}  // namespace
}  // namespace fogdrift::signal
