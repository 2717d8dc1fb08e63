// A population of instruments: each drawn at random, seeded, from documented ranges around the
// default instrument, so that a default chosen on the population is not tuned to one unit
// (docs/simulator.md §6, "A population of instruments").
//
// Every range is listed once in population_ranges(), by the instrument field's JSON path
// (instrument.hpp); the draw, the documentation table and the tests all come from there. A
// positive scale (a capacity, a conductance, a power, a lag, a noise level) is drawn
// log-uniformly, so that half and twice the default are equally likely; a signed coefficient of
// the drift law is drawn uniformly over a range symmetric about zero, so that an instrument may
// have it of either sign or not at all. The form of the drift law varies with them: the
// filtered-rate and electronics terms, absent from the default, are drawn like the rest.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fogdrift/sim/instrument.hpp"

namespace fogdrift::sim {

struct PopulationRange {
  std::string path;  ///< the instrument field (InstrumentField::path)
  double low = 0, high = 0;
  bool log_uniform = false;  ///< else uniform
  std::string why;           ///< what the range stands for
};

/// The ranges, in the order they are drawn.
const std::vector<PopulationRange>& population_ranges();

/// Instrument number `index` (1, 2, …) of the population of `seed`: the default instrument with
/// every ranged field drawn. The same seed and index give the same instrument, whatever the count
/// drawn before it.
Instrument draw_instrument(std::uint64_t seed, std::uint64_t index);

/// Where the default instrument lies in each range, as a share 0 … 1 of it (log for log-uniform
/// ranges): the check that the default is one ordinary member.
std::vector<double> default_positions();

/// Markdown table of the ranges (used to write docs/simulator.md).
std::string population_table_markdown();

}  // namespace fogdrift::sim
