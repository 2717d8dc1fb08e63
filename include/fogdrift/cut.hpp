// Cutting one long log into recordings, the units a campaign lists (docs/logs.md).
//
// A logger that ran through several chamber steps writes one file; the method wants one
// recording per start-up or per stretch of one condition. Three rules, applied in this order:
//   gap_s      a time step longer than gap_s ends a recording (the logger or the unit was off);
//   window_s   each recording is cut into consecutive windows of window_s (the last, shorter
//              window is kept if it holds at least half a window);
//   (power cycles, where a logger's clock restarts, are split by import --split-at-reset.)
// Pieces keep their time since power-on; pieces shorter than min_samples are dropped.
#pragma once

#include <cstddef>
#include <vector>

#include "fogdrift/recording.hpp"

namespace fogdrift {

struct CutOptions {
  double gap_s = 0;             ///< cut at time steps longer than this, s; 0: no cutting at gaps
  double window_s = 0;          ///< cut into windows of this length, s; 0: no windows
  std::size_t min_samples = 2;  ///< drop pieces with fewer samples, >= 2
};

struct CutSummary {
  std::size_t gaps = 0;     ///< cuts made at gaps
  std::size_t windows = 0;  ///< pieces made by windows
  std::size_t dropped = 0;  ///< pieces dropped as too short
};

/// The pieces of `recording`, in time order. Throws OptionError naming gap_s, window_s or
/// min_samples for an impossible option, and InputError naming the recording when no piece is
/// left.
std::vector<Recording> cut(const Recording& recording, const CutOptions& options,
                           CutSummary* summary = nullptr);

}  // namespace fogdrift
