// The registry's lookup (trainers.hpp).
#include "fogdrift/train/trainers.hpp"

#include <fmt/format.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift {

const TrainerEntry& trainer(std::string_view name, std::string_view option) {
  for (const TrainerEntry& t : trainer_entries())
    if (t.name == name) return t;
  throw OptionError(std::string(option),
                    fmt::format("'{}' is not a method ({})", name, method_names()));
}

}  // namespace fogdrift
