// What the trainers share (trainer.hpp): the optimizer of a search, and how held-out folds are
// described in model files and reports.
#include "fogdrift/train/trainer.hpp"

#include <gtest/gtest.h>

namespace fogdrift {
namespace {

TEST(Trainer, EachSearchHasItsOptimizer) {
  EXPECT_EQ(optimizer_of(Search::ssa), opt::Algorithm::ssa);
  EXPECT_EQ(optimizer_of(Search::pso), opt::Algorithm::pso);
  EXPECT_EQ(optimizer_of(Search::gwo), opt::Algorithm::gwo);
}

TEST(Trainer, FoldsAreDescribedByWhatTheyHoldOut) {
  const auto folds = [](const char* first, std::size_t n) {
    std::vector<tune::Fold> f(n);
    f[0].name = first;
    return f;
  };
  EXPECT_EQ(describe_folds(folds("repetition 2", 4)), "leave one repetition out (4 folds)");
  EXPECT_EQ(describe_folds(folds("temperatures 1/3", 3)), "whole initial temperatures (3 folds)");
  EXPECT_EQ(describe_folds(folds("recordings 1/3", 3)), "whole recordings (3 folds)");
}

}  // namespace
}  // namespace fogdrift
