// The options of `fogdrift train` and Python's fogdrift.train, described once (option_table.hpp,
// docs/options.md): everything that decides the model a campaign gives. What only decides how a
// front end runs or reports (threads, --targets or target, --json, progress) each front end
// declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/train/train_campaign.hpp"

namespace fogdrift {

/// The table, in the order options are applied (thermometers before features, which reads them).
const OptionTable<CampaignTrainOptions>& train_option_table();

}  // namespace fogdrift
