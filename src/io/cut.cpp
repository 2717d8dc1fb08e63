#include "fogdrift/io/cut.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

/// The samples of [begin, end) after which a plateau ends (the last sample of each plateau but
/// the final one), in time order.
std::vector<std::size_t> plateau_ends(const Recording& r, std::size_t begin, std::size_t end,
                                      const CutOptions& o) {
  const std::vector<double>& x = r.chamber_degc ? *r.chamber_degc : r.temp_fog_degc;
  const auto& t = r.time_s;
  constexpr double kHalfSpan_s = 60.0;  // the slope is taken over ±60 s
  std::vector<bool> flat(end - begin);
  std::size_t lo = begin, hi = begin;
  for (std::size_t i = begin; i < end; ++i) {
    while (t[i] - t[lo] > kHalfSpan_s) ++lo;
    while (hi + 1 < end && t[hi + 1] - t[i] <= kHalfSpan_s) ++hi;
    const double span = t[hi] - t[lo];
    const double rate_per_min = span > 0 ? 60.0 * (x[hi] - x[lo]) / span : 0.0;
    flat[i - begin] = std::fabs(rate_per_min) < o.plateau_rate_degc_per_min;
  }
  std::vector<std::size_t> ends;
  std::size_t i = begin;
  while (i < end) {
    if (!flat[i - begin]) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j + 1 < end && flat[j + 1 - begin]) ++j;
    if (t[j] - t[i] >= o.plateau_min_s && j + 1 < end) ends.push_back(j);
    i = j + 1;
  }
  return ends;
}

}  // namespace

std::vector<Recording> cut(const Recording& recording, const CutOptions& options,
                           CutSummary* summary) {
  if (!(options.gap_s >= 0) || !std::isfinite(options.gap_s))
    throw OptionError("gap_s", fmt::format("{} s is not a duration >= 0", options.gap_s));
  if (!(options.window_s >= 0) || !std::isfinite(options.window_s))
    throw OptionError("window_s", fmt::format("{} s is not a duration >= 0", options.window_s));
  if (!(options.plateau_rate_degc_per_min > 0) || !std::isfinite(options.plateau_rate_degc_per_min))
    throw OptionError("plateau_rate_degc_per_min", fmt::format("{} °C/min is not a positive rate",
                                                               options.plateau_rate_degc_per_min));
  if (!(options.plateau_min_s > 0) || !std::isfinite(options.plateau_min_s))
    throw OptionError("plateau_min_s",
                      fmt::format("{} s is not a positive duration", options.plateau_min_s));
  if (options.min_samples < 2)
    throw OptionError("min_samples", "a recording needs at least 2 samples");
  CutSummary local;
  CutSummary& s = summary ? *summary : local;
  s = {};
  const auto& t = recording.time_s;
  const std::size_t n = t.size();

  // [begin, end) ranges: first at gaps, then at the ends of plateaus, then into windows.
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  std::size_t begin = 0;
  for (std::size_t i = 1; i <= n; ++i) {
    if (i < n && !(options.gap_s > 0 && t[i] - t[i - 1] > options.gap_s)) continue;
    if (i < n) ++s.gaps;
    pieces.emplace_back(begin, i);
    begin = i;
  }
  if (options.plateaus) {
    std::vector<std::pair<std::size_t, std::size_t>> steps;
    for (const auto& [b, e] : pieces) {
      std::size_t start = b;
      for (std::size_t last : plateau_ends(recording, b, e, options)) {
        steps.emplace_back(start, last + 1);
        ++s.plateaus;
        start = last + 1;
      }
      steps.emplace_back(start, e);
    }
    pieces = std::move(steps);
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
          s.dropped_samples += stop - start;
          s.dropped_spans_s.emplace_back(t[start], t[stop - 1]);
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
      s.dropped_samples += e - b;
      if (e > b) s.dropped_spans_s.emplace_back(t[b], t[e - 1]);
      continue;
    }
    out.push_back(slice(recording, b, e));
  }
  if (out.empty()) {
    throw InputError(recording.source, 0, 0,
                     fmt::format("cutting (gaps > {} s, {}windows of {} s) left no piece of at "
                                 "least {} samples",
                                 options.gap_s, options.plateaus ? "plateaus, " : "",
                                 options.window_s, options.min_samples));
  }
  return out;
}

}  // namespace fogdrift
