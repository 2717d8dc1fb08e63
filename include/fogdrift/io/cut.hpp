// Cutting one long log into recordings, the units a campaign lists (docs/logs.md).
//
// A logger that ran through several chamber steps writes one file; the method wants one
// recording per start-up or per stretch of one condition. The rules, applied in this order:
//   gap_s      a time step longer than gap_s ends a recording (the logger or the unit was off);
//   plateaus   a recording ends where a temperature plateau ends, so that each piece is a step
//              of the chamber and the plateau it settles to. The temperature is chamber_degc if
//              the recording has it, else temp_fog_degc; its rate is the slope over ±60 s; a
//              plateau is a stretch of at least plateau_min_s whose |rate| stays below
//              plateau_rate_degc_per_min;
//   window_s   each recording is cut into consecutive windows of window_s (the last, shorter
//              window is kept if it spans at least half a window);
//   (power cycles, where a logger's clock restarts, are split by import --split-at-reset.)
// Pieces keep their time since power-on; pieces shorter than min_samples are dropped.
#pragma once

#include <cstddef>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift {

struct CutOptions {
  double gap_s = 0;       ///< cut at time steps longer than this, s; 0: no cutting at gaps
  double window_s = 0;    ///< cut into windows of this length, s; 0: no windows
  bool plateaus = false;  ///< cut where each temperature plateau ends
  double plateau_rate_degc_per_min = 0.05;  ///< |rate| below this is flat, °C/min, > 0
  double plateau_min_s = 600;               ///< shortest plateau, s, > 0
  std::size_t min_samples = 2;              ///< drop pieces with fewer samples, >= 2
};

struct CutSummary {
  std::size_t gaps = 0;             ///< cuts made at gaps
  std::size_t plateaus = 0;         ///< cuts made at the ends of plateaus
  std::size_t windows = 0;          ///< pieces made by windows
  std::size_t dropped = 0;          ///< pieces dropped as too short
  std::size_t dropped_samples = 0;  ///< the samples in them
  /// Each dropped piece's span, first and last sample's time_s, s, in time order.
  std::vector<std::pair<double, double>> dropped_spans_s;
};

/// The pieces of `recording`, in time order. Throws OptionError naming gap_s, window_s,
/// plateau_rate_degc_per_min, plateau_min_s or min_samples for an impossible option, and InputError
/// naming the recording when no piece is left.
std::vector<Recording> cut(const Recording& recording, const CutOptions& options,
                           CutSummary* summary = nullptr);

}  // namespace fogdrift
