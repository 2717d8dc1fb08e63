// What the trainers share (trainer.hpp).
#include "fogdrift/train/trainer.hpp"

#include <fmt/format.h>

namespace fogdrift {

opt::Algorithm optimizer_of(Search s) {
  return s == Search::pso ? opt::Algorithm::pso
                          : (s == Search::gwo ? opt::Algorithm::gwo : opt::Algorithm::ssa);
}

std::string describe_folds(std::span<const tune::Fold> folds) {
  const std::string& first = folds.front().name;
  const char* kind = first.starts_with("repetition")     ? "leave one repetition out"
                     : first.starts_with("temperatures") ? "whole initial temperatures"
                                                         : "whole recordings";
  return fmt::format("{} ({} folds)", kind, folds.size());
}

}  // namespace fogdrift
