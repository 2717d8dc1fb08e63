// Studied protocols, priced and chosen (protocol_front.hpp; docs/field.md, "Protocols worth
// their hours").
#include "fogdrift/sim/protocol_front.hpp"

#include <algorithm>
#include <limits>

#include "fogdrift/base/error.hpp"

namespace fogdrift::sim {
namespace {

using Shares = std::array<PopulationShare, 4>;

/// A protocol of `approaches` (the test sweep, calibration, appended) with its soaked, warm and
/// ramping sweeps at `start_up_temps` and its calibration sweeps at `temps` (empty: the paper's
/// eleven set points).
CalibrationOptions protocol_of(std::vector<Approach> approaches,
                               std::vector<double> start_up_temps = {},
                               std::vector<double> temps = {}) {
  CalibrationOptions p;
  approaches.push_back(Approach::calibration);
  p.repetitions = static_cast<int>(approaches.size());
  p.test_repetitions = 1;
  p.approaches = std::move(approaches);
  p.start_up_temps_degc = std::move(start_up_temps);
  if (!temps.empty()) p.temps_degc = std::move(temps);
  return p;
}

constexpr Approach kC = Approach::calibration, kS = Approach::soaked, kW = Approach::warm,
                   kR = Approach::ramping;
const std::vector<double> kFour{-40, -7, 27, 60}, kThree{-40, 10, 60};
const std::vector<SeedRerun> kNoRerun;

// The measurements: bench/population_study.sh build 20 2 2 with POPULATION_CAL_APPROACHES,
// _REPETITIONS, _TEMPS and _START_UP_TEMPS set to each protocol (docs/field.md gives each
// command), 2026-11-28 and 2026-11-29 (seven sweeps). {median, 10th percentile, worst} % per
// condition: calibration, soaked, warm, ramping; then instruments, cells worse than raw (by more
// than 1e-6 of the removable error: a guard that backs off all the way leaves ±1e-13),
// train's median seconds, and the study repeated with other search seeds where it was.
std::vector<StudiedProtocol> measured() {
  std::vector<StudiedProtocol> v;
  // The paper's sweeps teach calibration-like start-ups and no other (a study of the paper's
  // three stopped after 10 instruments).
  v.push_back({"one calibration sweep", protocol_of({kC}),
               Shares{{{97, 48, 15}, {2, -181, -775}, {0, -39, -2204}, {-88, -527, -1271}}},
               Shares{{{96, 64, 38}, {1, -208, -1008}, {-4, -253, -1304}, {-15, -1015, -1439}}}, 20,
               62, 8, kNoRerun});
  v.push_back({"the paper's", protocol_of({kC, kC, kC}),
               Shares{{{99, 55, 26}, {18, -42, -102}, {0, 0, 0}, {-19, -197, -866}}},
               Shares{{{100, 33, 3}, {26, -67, -154}, {-4, -165, -282}, {-23, -348, -812}}}, 10, 21,
               55, kNoRerun});
  // What not to do: the calibration sweep's start-ups carry its 10 °C steps, and service's
  // calibration-like start-ups too; at four set points its steps are 33 °C.
  v.push_back({"every sweep at four set points", protocol_of({kC, kS, kW, kR}, {}, kFour),
               Shares{{{79, -67, -431}, {94, 72, -31}, {90, -91, -262}, {99, 83, 5}}},
               Shares{{{73, -165, -1016}, {94, 70, 7}, {89, 9, -274}, {96, 80, 74}}}, 20, 17, 11,
               kNoRerun});
  // Nor this: no other start-up teaches a ramping one (a study stopped after 11 instruments).
  v.push_back({"four start-up set points, no ramping", protocol_of({kC, kS, kW}, kFour),
               Shares{{{98, 93, 26}, {98, 88, 49}, {95, 85, 6}, {-120, -1478, -1559}}},
               Shares{{{96, 91, 69}, {97, 79, 59}, {97, 85, 34}, {-94, -1476, -1813}}}, 11, 15, 16,
               kNoRerun});
  v.push_back({"three start-up set points", protocol_of({kC, kS, kW, kR}, kThree),
               Shares{{{96, 79, 73}, {94, 42, -17}, {93, 24, -262}, {98, 80, 11}}},
               Shares{{{95, 76, 72}, {92, 46, -7}, {93, 32, -149}, {98, 42, -9}}}, 20, 7, 26,
               kNoRerun});
  v.push_back({"four start-up set points",
               protocol_of({kC, kS, kW, kR}, kFour),
               Shares{{{97, 85, 79}, {95, 70, 48}, {93, 70, -311}, {99, 85, 23}}},
               Shares{{{97, 86, 74}, {96, 70, 57}, {93, 77, -329}, {99, 84, 56}}},
               20,
               2,
               27,
               // The same study with search seeds k + 100 (2026-11-29; again 2026-12-01 with
               // POPULATION_SEARCH_SEED_OFFSET=100, the same figures): the batch soaked 10th
               // percentile is 56 %, not 70.
               {{100, Shares{{{97, 85, 81}, {96, 56, 44}, {92, 70, -323}, {99, 81, 24}}},
                 Shares{{{97, 87, 74}, {96, 64, 56}, {94, 73, -330}, {99, 82, 42}}}, 2}}});
  // The four set points placed elsewhere (2026-12-02; -40, -13, 13, 40 °C again the same night
  // with the cap on the search's fits, and late that night with the kernel in float, docs/svr.md;
  // then 2026-12-03 with one candidate within 0.005 decade, and later that day within 0.01
  // decade, train's default since, docs/tuning.md: these figures, with three sets of search
  // seeds). With search seeds k neither does better than -40, -7, 27 and 60 °C, and each leaves
  // a third cell worse than raw; over every set of seeds the worst 10th percentile of each is
  // 56 % (batch warm with seeds k + 100 here, batch soaked there), and this one's worst share is
  // far less negative (unit 15's warm start-ups -177 against -330 %). The same three studies
  // fitting every distinct candidate gave batch warm 10th percentiles of 66, 56 and 67 %.
  v.push_back({"four start-up set points at -40, -13, 13, 40 °C",
               protocol_of({kC, kS, kW, kR}, {-40, -13, 13, 40}),
               Shares{{{96, 78, 67}, {95, 64, 27}, {95, 65, -177}, {98, 84, 37}}},
               Shares{{{96, 87, 73}, {95, 73, 61}, {95, 78, -160}, {98, 80, 65}}},
               20,
               3,
               20,  // train's median in the k + 200 study (one instrument at a time, 2 cores)
               {{100, Shares{{{97, 85, 68}, {95, 65, 48}, {95, 56, -171}, {98, 85, 10}}},
                 Shares{{{95, 87, 74}, {96, 63, 60}, {95, 75, -162}, {98, 79, 57}}}, 3},
                {200, Shares{{{97, 78, 68}, {95, 66, 21}, {95, 67, -168}, {98, 86, 32}}},
                 Shares{{{96, 86, 71}, {95, 64, 54}, {95, 73, -162}, {98, 77, 51}}}, 3}}});
  v.push_back({"four start-up set points at -40, -5, 25, 55 °C",
               protocol_of({kC, kS, kW, kR}, {-40, -5, 25, 55}),
               Shares{{{98, 85, 77}, {96, 57, 40}, {95, 56, -253}, {99, 88, 6}}},
               Shares{{{97, 79, 76}, {95, 73, -41}, {95, 63, -314}, {98, 84, 58}}}, 20, 3, 24,
               kNoRerun});
  // One more warm sweep at the four set points buys no 10th percentile that other search seeds
  // keep, and does not mend the one instrument whose warm start-ups the four leave worse than
  // raw.
  v.push_back(
      {"four start-up set points, two warm sweeps",
       protocol_of({kC, kS, kW, kR, kW}, kFour),
       Shares{{{97, 80, 74}, {95, 62, 41}, {95, 78, -165}, {99, 84, 30}}},
       Shares{{{97, 85, 74}, {95, 74, 51}, {97, 79, -132}, {99, 80, 58}}},
       20,
       2,
       42,
       // With search seeds k + 100 (2026-12-01): the batch warm 10th percentile is 48 %, not 78.
       {{100, Shares{{{97, 77, 72}, {95, 58, -58}, {95, 48, -139}, {98, 84, 25}}},
         Shares{{{97, 86, 73}, {95, 73, 62}, {97, 81, -94}, {99, 81, 56}}}, 3}}});
  v.push_back({"five sweeps",
               protocol_of({kC, kS, kW, kR}),
               Shares{{{98, 84, 81}, {99, 89, 66}, {99, 79, -15}, {99, 94, 68}}},
               Shares{{{98, 85, 73}, {98, 92, 31}, {98, 83, -35}, {99, 93, 76}}},
               20,
               2,
               84,
               // With search seeds k + 100 (2026-12-02, the flags of 2026-11-28 it was studied
               // with, --search-rows 2500 --thin-from-rows 5000): every median and 10th
               // percentile within 3 points, unit 15's warm start-ups again worse than raw.
               {{100, Shares{{{98, 84, 80}, {99, 89, 69}, {98, 80, -36}, {99, 94, 67}}},
                 Shares{{{98, 85, 71}, {98, 92, 31}, {98, 80, -39}, {99, 94, 75}}}, 2}}});
  // train's defaults since 2026-11-29 search this protocol's folds on every seventh row.
  v.push_back({"seven sweeps",
               protocol_of({kC, kS, kW, kR, kW, kW}),
               Shares{{{98, 85, 80}, {99, 90, 59}, {99, 88, 39}, {99, 93, 74}}},
               Shares{{{97, 85, 79}, {98, 89, 32}, {99, 89, 40}, {99, 92, 80}}},
               20,
               0,
               62,
               // With search seeds k + 100 (2026-12-02, the same defaults): every median and
               // 10th percentile within a point of the first seeds', none worse than raw.
               {{100, Shares{{{98, 84, 80}, {99, 90, 56}, {99, 88, 40}, {99, 92, 70}}},
                 Shares{{{97, 84, 74}, {98, 89, 34}, {99, 89, 47}, {99, 92, 78}}}, 0}}});
  return v;
}

}  // namespace

const std::vector<StudiedProtocol>& studied_protocols() {
  static const std::vector<StudiedProtocol> protocols = measured();
  return protocols;
}

std::vector<PricedProtocol> price_protocols(const Instrument& instrument,
                                            const ChamberOptions& chamber,
                                            const std::vector<Approach>& conditions) {
  if (conditions.empty())
    throw OptionError("service", "needs at least one start-up condition the unit will meet");
  std::vector<std::size_t> columns;
  for (Approach a : conditions) {
    const auto* at = std::find(kServiceConditions.begin(), kServiceConditions.end(), a);
    if (at == kServiceConditions.end())
      throw OptionError("service",
                        "sweep is not a start-up condition a unit meets in service: "
                        "give calibration, soaked, warm or ramping");
    columns.push_back(static_cast<std::size_t>(at - kServiceConditions.begin()));
  }
  bool every_condition = true;
  for (std::size_t c = 0; c < kServiceConditions.size(); ++c)
    every_condition =
        every_condition && std::find(columns.begin(), columns.end(), c) != columns.end();
  std::vector<PricedProtocol> priced;
  for (const StudiedProtocol& s : studied_protocols()) {
    PricedProtocol p;
    p.studied = &s;
    p.schedule = chamber_schedule(instrument, s.protocol, chamber);
    p.service_hours = p.schedule.hours - p.schedule.test_hours;
    p.worst_p10_pct = p.worst_median_pct = p.worst_worst_pct =
        std::numeric_limits<double>::infinity();
    std::vector<const Shares*> paths{&s.batch, &s.causal};
    p.worse_than_raw = s.worse_than_raw;
    for (const SeedRerun& r : s.reruns) {
      paths.push_back(&r.batch);
      paths.push_back(&r.causal);
      p.worse_than_raw = std::max(p.worse_than_raw, r.worse_than_raw);
    }
    for (const Shares* path : paths)
      for (std::size_t c : columns) {
        p.worst_p10_pct = std::min(p.worst_p10_pct, (*path)[c].p10_pct);
        p.worst_median_pct = std::min(p.worst_median_pct, (*path)[c].median_pct);
        p.worst_worst_pct = std::min(p.worst_worst_pct, (*path)[c].worst_pct);
      }
    // The count of cells worse than raw covers all four conditions; the worst share, those the
    // unit meets.
    const bool none_worse = p.worst_worst_pct >= 0 && (!every_condition || p.worse_than_raw == 0);
    p.meets_goal =
        p.worst_median_pct >= kGoalMedianPct && p.worst_p10_pct >= kGoalP10Pct && none_worse;
    priced.push_back(std::move(p));
  }
  std::stable_sort(priced.begin(), priced.end(),
                   [](const auto& a, const auto& b) { return a.service_hours < b.service_hours; });
  double best = -std::numeric_limits<double>::infinity();
  for (PricedProtocol& p : priced) {
    p.on_front = p.worst_p10_pct > best;
    best = std::max(best, p.worst_p10_pct);
  }
  return priced;
}

std::optional<PricedProtocol> choose_protocol(const std::vector<PricedProtocol>& priced,
                                              double hours) {
  std::optional<PricedProtocol> chosen;
  for (const PricedProtocol& p : priced)  // cheapest first: a tie keeps the cheaper
    if (p.service_hours <= hours && (!chosen || p.worst_p10_pct > chosen->worst_p10_pct))
      chosen = p;
  return chosen;
}

std::optional<PricedProtocol> cheapest_meeting_goal(const std::vector<PricedProtocol>& priced) {
  for (const PricedProtocol& p : priced)  // cheapest first
    if (p.meets_goal) return p;
  return std::nullopt;
}

}  // namespace fogdrift::sim
