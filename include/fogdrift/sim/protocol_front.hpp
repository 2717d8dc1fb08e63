// Calibration protocols worth their chamber hours (docs/field.md, "Protocols worth their hours").
//
// Each protocol here was run on the same population of instruments (bench/population_study.sh,
// 20 instruments of `simulate population --seed 2`, train's defaults, batch and causal, guard
// on, 90 findings a condition), and what it removed is recorded with it: the median, 10th
// percentile and worst share of the removable north-finding error removed under each start-up
// condition. The figures are measurements, reproduced by the command docs/field.md gives for
// each protocol; the hours are not stored but computed for the instrument and chamber at hand
// (chamber.hpp), so the same choice reads in that chamber's hours.
//
// choose_protocol picks, among the protocols whose service hours (the test repetitions left
// out: a unit calibrated for service does without them) fit the budget, the one whose worst
// 10th percentile over the start-up conditions the unit will meet, batch and causal, is
// highest; a tie goes to the cheaper. Where a study was repeated with other search seeds, the
// worst is taken over every repetition: a protocol is not credited with a lucky search.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "fogdrift/sim/chamber.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::sim {

/// The start-up conditions a protocol is measured under, in the order of the shares below.
inline constexpr std::array<Approach, 4> kServiceConditions = {
    Approach::calibration, Approach::soaked, Approach::warm, Approach::ramping};

/// docs/field.md's goal on the population: every median and every 10th percentile at least
/// these, under each start-up condition the unit meets, batch and causal, and no instrument
/// worse than raw under any of them.
inline constexpr double kGoalMedianPct = 85, kGoalP10Pct = 60;

/// The share of the removable north-finding error removed over the population, %.
struct PopulationShare {
  double median_pct = 0;
  double p10_pct = 0;  ///< the 10th percentile
  double worst_pct = 0;
};

/// The same study run again with other search seeds: `train --seed k + search_seed_offset` for
/// instrument k (bench/population_study.sh, POPULATION_SEARCH_SEED_OFFSET), the same campaigns.
/// How far its shares lie from the first study's is the search's luck, not the protocol's.
struct SeedRerun {
  int search_seed_offset = 0;
  std::array<PopulationShare, 4> batch, causal;  ///< per kServiceConditions
  int worse_than_raw = 0;
};

struct StudiedProtocol {
  std::string name;             ///< a few words: "the paper's", "four start-up set points"
  CalibrationOptions protocol;  ///< what simulate calibration runs, the test sweep last
  std::array<PopulationShare, 4> batch, causal;  ///< per kServiceConditions, search seeds k
  int instruments = 20;                          ///< of the population the study finished
  int worse_than_raw = 0;     ///< instrument × condition × path cells worse than raw
  double train_median_s = 0;  ///< train's median time on one thread over the population
  /// The study with other search seeds, where it was run. A claim made of the protocol (the
  /// worst figures of PricedProtocol) is the lowest over every set of seeds studied.
  std::vector<SeedRerun> reruns;
};

/// Every studied protocol, in no order that matters (price_protocols sorts them by hours).
const std::vector<StudiedProtocol>& studied_protocols();

/// A studied protocol priced for one instrument and chamber.
struct PricedProtocol {
  const StudiedProtocol* studied = nullptr;
  ChamberSchedule schedule;
  double service_hours = 0;  ///< schedule.hours without the test repetitions
  /// The lowest 10th percentile (and median, worst) over `conditions`, batch and causal, and
  /// every set of search seeds studied (StudiedProtocol::reruns).
  double worst_p10_pct = 0, worst_median_pct = 0, worst_worst_pct = 0;
  int worse_than_raw = 0;  ///< the most cells worse than raw of any set of search seeds
  bool on_front = false;   ///< no cheaper protocol has a worst 10th percentile as high
  /// The worst median and 10th percentile reach kGoalMedianPct and kGoalP10Pct, and no
  /// instrument is worse than raw: the worst share is not below 0 (to the whole percent it was
  /// recorded in) and, under all four conditions, worse_than_raw is 0.
  bool meets_goal = false;
};

/// Every studied protocol priced, cheapest first, the front marked, under the start-up
/// conditions `conditions` (a subset of kServiceConditions; OptionError "service" if empty or
/// holding sweep).
std::vector<PricedProtocol> price_protocols(const Instrument& instrument,
                                            const ChamberOptions& chamber,
                                            const std::vector<Approach>& conditions);

/// The protocol `hours` of service chamber time buys (header), or nullopt when none fits.
std::optional<PricedProtocol> choose_protocol(const std::vector<PricedProtocol>& priced,
                                              double hours);

/// The cheapest protocol that meets the goal, or nullopt when none does.
std::optional<PricedProtocol> cheapest_meeting_goal(const std::vector<PricedProtocol>& priced);

}  // namespace fogdrift::sim
