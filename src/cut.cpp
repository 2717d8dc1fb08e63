#include "fogdrift/cut.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/error.hpp"

namespace fogdrift {

std::vector<Recording> cut(const Recording& recording, const CutOptions& options,
                           CutSummary* summary) {
  if (!(options.gap_s >= 0) || !std::isfinite(options.gap_s))
    throw OptionError("gap_s", fmt::format("{} s is not a duration >= 0", options.gap_s));
  if (!(options.window_s >= 0) || !std::isfinite(options.window_s))
    throw OptionError("window_s", fmt::format("{} s is not a duration >= 0", options.window_s));
  if (options.min_samples < 2)
    throw OptionError("min_samples", "a recording needs at least 2 samples");
  CutSummary local;
  CutSummary& s = summary ? *summary : local;
  s = {};
  const auto& t = recording.time_s;
  const std::size_t n = t.size();

  // [begin, end) ranges: first at gaps, then into windows.
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= n; ++i) {
    if (i < n && !(options.gap_s > 0 && t[i] - t[i - 1] > options.gap_s)) continue;
    if (i < n) ++s.gaps;
    pieces.emplace_back(begin, i);
    begin = i;
  }
  if (options.window_s > 0) {
    std::vector<std::pair<std::size_t, std::size_t>> windows;
    for (const auto& [b, e] : pieces) {
      std::size_t start = b;
      while (start < e) {
        std::size_t stop = start;
        while (stop < e && t[stop] - t[start] < options.window_s) ++stop;
        // A last window shorter than half a window joins nothing and stands alone only if long
        // enough; otherwise it is dropped.
        const bool last = stop == e;
        if (!last || t[e - 1] - t[start] >= 0.5 * options.window_s) {
          windows.emplace_back(start, stop);
          ++s.windows;
        } else {
          ++s.dropped;
        }
        start = stop;
      }
    }
    pieces = std::move(windows);
  }

  std::vector<Recording> out;
  for (const auto& [b, e] : pieces) {
    if (e - b < options.min_samples) {
      ++s.dropped;
      continue;
    }
    out.push_back(slice(recording, b, e));
  }
  if (out.empty()) {
    throw InputError(recording.source, 0, 0,
                     fmt::format("cutting (gaps > {} s, windows of {} s) left no piece of at least "
                                 "{} samples",
                                 options.gap_s, options.window_s, options.min_samples));
  }
  return out;
}

}  // namespace fogdrift
