// `fogdrift campaign`'s options, described once (option_table.hpp, docs/options.md): which
// recordings are held out and their repetitions, what the target channels sensed, and how one
// long log is cut into recordings (cut.hpp). What the channels sensed is `evaluate`'s too, for
// recording files that have no manifest to say it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/cut.hpp"

namespace fogdrift {

/// What the target channels sensed, the same in every recording (CampaignEntry::input_rate_dph
/// and references).
struct SensedOptions {
  /// The rate the gyro sensed, °/h; none: the Earth rate's projection, from the latitude and the
  /// true azimuth, or, for recording files, not known (train subtracts each recording's mean).
  std::optional<double> input_rate_dph;
  /// What another target channel sensed, in its unit (check_reference).
  std::map<std::string, double> references;
};

/// What `fogdrift campaign` is told besides the recordings and the folder.
struct CampaignOptions {
  /// The recordings held out for evaluate: "last", "none", or 1-based numbers such as 2,5,
  /// counted after cutting (checked against the count, which only the recordings give).
  std::string test = "last";
  std::vector<double> repetitions;  ///< one per recording, whole numbers ≥ 1; empty: all 1
  SensedOptions sensed;
  std::optional<double> latitude_deg;      ///< with the true azimuth, instead of the input rate
  std::optional<double> true_azimuth_deg;  ///< of the horizontal sensitive axis
  CutOptions cut;
};

/// What the channels sensed: `evaluate`'s flags for recording files, and part of campaign's.
const OptionTable<SensedOptions>& sensed_option_table();
/// How one long log is cut.
const OptionTable<CutOptions>& cut_option_table();
/// Every option of `fogdrift campaign`: the test recordings, the repetitions, what was sensed
/// (sensed_option_table), the site, and the cutting (cut_option_table).
const OptionTable<CampaignOptions>& campaign_option_table();

}  // namespace fogdrift
