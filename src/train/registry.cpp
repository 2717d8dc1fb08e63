// The registry: the one list of the methods `fogdrift train` knows, each a trainer with the
// regressor it fits, which is the list of regressors a model file can hold (trainers.hpp,
// regress/regressors.hpp). Adding a regressor adds its trainer's include and its name in
// Registered below, nothing else here (docs/architecture.md, "Adding a regressor").
#include "fogdrift/train/bp_trainer.hpp"
#include "fogdrift/train/gp_trainer.hpp"
#include "fogdrift/train/poly_trainer.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/trainers.hpp"

namespace fogdrift {

using Registered = Registry<SvrTrainer, BpTrainer, PolyTrainer, GpTrainer>;

std::span<const TrainerEntry> trainer_entries() {
  return Registered::trainers;
}

std::span<const RegressorEntry> regressor_entries() {
  return Registered::regressors;
}

}  // namespace fogdrift
