#include "fogdrift/io/regrid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

constexpr std::array<EnumName<RegridMethod>, 3> kRegridMethodNames = {
    {{RegridMethod::automatic, "auto"},
     {RegridMethod::mean, "mean"},
     {RegridMethod::linear, "linear"}}};

/// The columns a grid averages or interpolates: every numeric column the recording has but the
/// time and the turntable position (which takes a sample's value, regrid.hpp), known columns
/// first; their values in `numbers` (known columns point into the recording, extras into
/// `parsed`). An extra column with a cell that is not a number is text and is left out.
std::vector<std::string> signal_columns(const Recording& r,
                                        std::vector<const std::vector<double>*>& numbers,
                                        std::vector<std::vector<double>>& parsed) {
  std::vector<std::string> out;
  for (const auto* names : {&required_columns(), &optional_columns()})
    for (const auto& name : *names) {
      const std::vector<double>* col = known_column(r, name);
      if (name == "time_s" || name == "table_deg" || !col || col->empty()) continue;
      out.push_back(name);
      numbers.push_back(col);
    }
  parsed.reserve(r.extra.size());  // stable addresses for `numbers`
  for (const ExtraColumn& e : r.extra) {
    std::optional<std::vector<double>> values = numbers_of(e);
    if (!values) continue;
    parsed.push_back(std::move(*values));
    out.push_back(e.name);
    numbers.push_back(&parsed.back());
  }
  return out;
}

/// A grid sample t_k = k·h, from the source samples i and i + 1 (input samples, or bins):
/// exactly sample i, or v_i + w·(v_{i+1} − v_i).
struct GridPoint {
  long long k = 0;
  std::size_t i = 0;
  double w = 0;
  bool exact = false;
};

/// What the grid is filled from: per signal column, one value per source sample; and the
/// turntable position of a grid point (when the recording has one).
struct Source {
  std::vector<std::string> names;
  std::vector<const std::vector<double>*> values;
  std::function<double(const GridPoint&)> table;
};

/// One recording per segment of grid points.
std::vector<Recording> fill(const std::vector<std::vector<GridPoint>>& segments, double h,
                            const Source& src) {
  std::vector<Recording> out;
  for (const auto& seg : segments) {
    Recording r;
    std::vector<std::vector<double>*> cols;
    std::vector<std::vector<double>> extras;  // numeric extra columns, written as text below
    extras.reserve(src.names.size());
    for (const auto& name : src.names) {
      std::vector<double>* col = known_column(r, name, true);
      cols.push_back(col ? col : &extras.emplace_back());
    }
    if (src.table) r.table_deg.emplace();
    for (const GridPoint& p : seg) {
      r.time_s.push_back(static_cast<double>(p.k) * h);
      for (std::size_t c = 0; c < cols.size(); ++c) {
        const std::vector<double>& x = *src.values[c];
        cols[c]->push_back(p.exact ? x[p.i] : x[p.i] + p.w * (x[p.i + 1] - x[p.i]));
      }
      if (src.table) r.table_deg->push_back(src.table(p));
    }
    for (std::size_t c = 0, x = 0; c < src.names.size() && x < extras.size(); ++c) {
      if (cols[c] != &extras[x]) continue;  // a known column
      ExtraColumn e{src.names[c], {}};
      e.cells.reserve(extras[x].size());
      for (double v : extras[x]) e.cells.push_back(csv::format_number(v));
      r.extra.push_back(std::move(e));
      ++x;
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace

std::string_view to_string(RegridMethod method) {
  return name_in(kRegridMethodNames, method);
}

RegridMethod regrid_method_from_string(std::string_view text) {
  return parse_in(kRegridMethodNames, text, "method", "a grid method");
}

bool is_uniformly_sampled(const Recording& recording) {
  const auto& t = recording.time_s;
  if (t.size() < 2) return false;
  const double median = median_time_step_s(t);
  for (std::size_t i = 0; i + 1 < t.size(); ++i)
    if (std::fabs(t[i + 1] - t[i] - median) > 0.01 * median) return false;
  return true;
}

RegridResult regrid(const Recording& rec, const RegridOptions& options) {
  if (!(options.step_s >= 1e-3) || options.step_s > 1e6)
    throw OptionError("step_s", fmt::format("a grid step of {} s is outside [0.001, 1e6] s "
                                            "(a rate of 1 µHz to 1 kHz)",
                                            options.step_s));
  if (!std::isfinite(options.max_gap_s))
    throw OptionError("max_gap_s", "must be a finite number of seconds");
  if (options.min_segment_samples < 2)
    throw OptionError("min_segment_samples", "a segment needs at least 2 samples");
  validate(rec);

  const double h = options.step_s;
  const auto& t = rec.time_s;
  const std::size_t n = t.size();
  RegridResult result;
  RegridSummary& s = result.summary;
  s.step_s = h;
  s.max_gap_s = options.max_gap_s < 0 ? 10.0 * h : options.max_gap_s;
  s.input_samples = n;
  s.input_median_step_s = median_time_step_s(t);
  s.method = options.method != RegridMethod::automatic ? options.method
             : s.input_median_step_s <= 0.5 * h        ? RegridMethod::mean
                                                       : RegridMethod::linear;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const double step = t[j + 1] - t[j];
    if (step <= 1.5 * s.input_median_step_s)
      s.input_max_jitter =
          std::max(s.input_max_jitter, std::fabs(step / s.input_median_step_s - 1.0));
  }

  // The grid points of each segment, before values are filled in.
  std::vector<std::vector<GridPoint>> segments(1);
  auto split = [&] {
    if (!segments.back().empty()) segments.emplace_back();
  };

  Source src;
  std::vector<const std::vector<double>*> numbers;
  std::vector<std::vector<double>> parsed_extras;
  src.names = signal_columns(rec, numbers, parsed_extras);
  for (const auto& e : rec.extra)
    if (std::find(src.names.begin(), src.names.end(), e.name) == src.names.end())
      s.dropped_columns.push_back(e.name);
  // The mean method's bins (in time order: consecutive samples with the same k = round(t / h)),
  // their means, and the samples that give their turntable positions.
  struct Bin {
    long long k = 0;
    std::size_t first = 0, count = 0;
  };
  std::vector<Bin> bins;
  std::vector<std::vector<double>> means(src.names.size());
  std::vector<double> nearest, first_table, last_table;

  if (s.method == RegridMethod::mean) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto k = static_cast<long long>(std::floor(t[i] / h + 0.5));
      if (bins.empty() || bins.back().k != k) bins.push_back({k, i, 0});
      ++bins.back().count;
    }
    for (std::size_t c = 0; c < src.names.size(); ++c) {
      const std::vector<double>& x = *numbers[c];
      for (const Bin& bin : bins) {
        double sum = 0;
        for (std::size_t j = bin.first; j < bin.first + bin.count; ++j) sum += x[j];
        means[c].push_back(sum / static_cast<double>(bin.count));
      }
      src.values.push_back(&means[c]);
    }
    if (rec.table_deg) {
      const std::vector<double>& table = *rec.table_deg;
      for (const Bin& bin : bins) {
        // The sample nearest the bin centre; for a bridged gap, the bin's edge samples.
        const double centre = static_cast<double>(bin.k) * h;
        std::size_t best = bin.first;
        for (std::size_t j = bin.first; j < bin.first + bin.count; ++j)
          if (std::fabs(t[j] - centre) < std::fabs(t[best] - centre)) best = j;
        nearest.push_back(table[best]);
        first_table.push_back(table[bin.first]);
        last_table.push_back(table[bin.first + bin.count - 1]);
      }
      src.table = [&](const GridPoint& p) {
        return p.exact ? nearest[p.i] : p.w < 0.5 ? last_table[p.i] : first_table[p.i + 1];
      };
    }
    for (std::size_t b = 0; b < bins.size(); ++b) {
      if (b > 0 && bins[b].k > bins[b - 1].k + 1) {
        const std::size_t last = bins[b - 1].first + bins[b - 1].count - 1;
        RegridGap gap{t[last], t[bins[b].first], false, 0};
        gap.bridged = gap.length_s() <= s.max_gap_s;
        if (gap.bridged) {
          // Interpolated between the means of bins b − 1 and b.
          for (long long k = bins[b - 1].k + 1; k < bins[b].k; ++k) {
            const double w = static_cast<double>(k - bins[b - 1].k) /
                             static_cast<double>(bins[b].k - bins[b - 1].k);
            segments.back().push_back({k, b - 1, w, false});
            ++gap.filled;
          }
        } else {
          split();
        }
        s.gaps.push_back(gap);
      }
      segments.back().push_back({bins[b].k, b, 0.0, true});
    }
  } else {
    // Linear: gaps are input steps longer than 1.5 × the median step.
    src.values = numbers;
    if (rec.table_deg)
      src.table = [&](const GridPoint& p) { return (*rec.table_deg)[p.w < 0.5 ? p.i : p.i + 1]; };
    const double gap_step = 1.5 * s.input_median_step_s;
    const auto k_first = static_cast<long long>(std::ceil(t.front() / h - 1e-9));
    const auto k_last = static_cast<long long>(std::floor(t.back() / h + 1e-9));
    std::size_t i = 0;
    for (std::size_t j = 0; j + 1 < n; ++j) {
      const double step = t[j + 1] - t[j];
      if (step > gap_step) s.gaps.push_back({t[j], t[j + 1], step <= s.max_gap_s, 0});
    }
    std::size_t next_gap = 0;
    for (long long k = k_first; k <= k_last; ++k) {
      const double tk = static_cast<double>(k) * h;
      while (i + 2 < n && t[i + 1] <= tk) ++i;
      // Move past the gaps that end at or before t_k; a split one starts a new segment.
      while (next_gap < s.gaps.size() && s.gaps[next_gap].end_s <= tk) {
        if (!s.gaps[next_gap].bridged) split();
        ++next_gap;
      }
      const double step = t[i + 1] - t[i];
      if (step > gap_step && tk > t[i] && tk < t[i + 1]) {
        auto& gap = s.gaps[next_gap];  // t_k lies inside this gap
        if (!gap.bridged) continue;
        ++gap.filled;
      }
      segments.back().push_back({k, i, std::clamp((tk - t[i]) / step, 0.0, 1.0), false});
    }
  }
  result.segments = fill(segments, h, src);

  // Keep the segments long enough to use; name them after the source.
  std::vector<Recording> kept;
  for (auto& seg : result.segments) {
    if (seg.size() < options.min_segment_samples) {
      if (seg.size() > 0) ++s.dropped_segments;
      continue;
    }
    seg.source = rec.source;
    seg.partial = rec.partial;
    s.output_samples += seg.size();
    kept.push_back(std::move(seg));
  }
  result.segments = std::move(kept);
  if (result.segments.empty()) {
    throw InputError(rec.source, 0, 0,
                     fmt::format("no stretch of at least {} samples on a {} s grid remains "
                                 "between gaps longer than {} s",
                                 options.min_segment_samples, h, s.max_gap_s));
  }
  for (const auto& seg : result.segments) validate(seg);
  return result;
}

}  // namespace fogdrift
