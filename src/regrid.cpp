#include "fogdrift/regrid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "fogdrift/enum_names.hpp"
#include "fogdrift/error.hpp"

namespace fogdrift {
namespace {

constexpr std::array<EnumName<RegridMethod>, 3> kRegridMethodNames = {
    {{RegridMethod::automatic, "auto"},
     {RegridMethod::mean, "mean"},
     {RegridMethod::linear, "linear"}}};

/// The numeric channels a grid carries, as pointers into one recording (nullptr when absent).
struct Channels {
  std::vector<const std::vector<double>*> in;
  std::vector<std::vector<double>*> out;
};

/// Pairs each averaged or interpolated channel of `from` with the same channel of `to`, creating
/// the optional ones in `to` that `from` has.
Channels channels(const Recording& from, Recording& to) {
  Channels c;
  auto add = [&](const std::vector<double>& a, std::vector<double>& b) {
    c.in.push_back(&a);
    c.out.push_back(&b);
  };
  add(from.gyro_dph, to.gyro_dph);
  add(from.temp_fog_degc, to.temp_fog_degc);
  if (!from.temp_acc1_degc.empty()) add(from.temp_acc1_degc, to.temp_acc1_degc);  // absent: stays
  if (!from.temp_acc2_degc.empty()) add(from.temp_acc2_degc, to.temp_acc2_degc);
  auto optional = [&](const std::optional<std::vector<double>>& a,
                      std::optional<std::vector<double>>& b) {
    if (!a) return;
    b.emplace();
    add(*a, *b);
  };
  optional(from.accel_x_g, to.accel_x_g);
  optional(from.accel_y_g, to.accel_y_g);
  optional(from.chamber_degc, to.chamber_degc);
  return c;
}

/// A grid sample under construction: its index k and either the mean of a bin (mean), or the
/// input samples i, i + 1 and the weight of i + 1 (linear).
struct GridPoint {
  long long k = 0;
  std::size_t i = 0;
  double w = 0;                      ///< weight of sample i + 1 (linear)
  std::size_t first = 0, count = 0;  ///< the bin's samples (mean)
  bool from_bin = false;
};

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
  for (const auto& e : rec.extra) s.dropped_columns.push_back(e.name);
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

  if (s.method == RegridMethod::mean) {
    // Bins in time order: consecutive samples with the same k = round(t / h).
    std::vector<GridPoint> bins;
    for (std::size_t i = 0; i < n; ++i) {
      const auto k = static_cast<long long>(std::floor(t[i] / h + 0.5));
      if (bins.empty() || bins.back().k != k) {
        bins.push_back({k, 0, 0, i, 0, true});
      }
      ++bins.back().count;
    }
    for (std::size_t b = 0; b < bins.size(); ++b) {
      if (b > 0 && bins[b].k > bins[b - 1].k + 1) {
        const std::size_t last = bins[b - 1].first + bins[b - 1].count - 1;
        RegridGap gap{t[last], t[bins[b].first], false, 0};
        gap.bridged = gap.length_s() <= s.max_gap_s;
        if (gap.bridged) {
          for (long long k = bins[b - 1].k + 1; k < bins[b].k; ++k) {
            GridPoint p;
            p.k = k;
            p.i = b - 1;  // interpolated between bins b − 1 and b, filled in below
            p.w = static_cast<double>(k - bins[b - 1].k) /
                  static_cast<double>(bins[b].k - bins[b - 1].k);
            segments.back().push_back(p);
            ++gap.filled;
          }
        } else {
          split();
        }
        s.gaps.push_back(gap);
      }
      segments.back().push_back(bins[b]);
    }
    // Fill: a bin's mean, or the interpolation between the means of the bins either side.
    auto bin_mean = [&](const GridPoint& p, const std::vector<double>& x) {
      double sum = 0;
      for (std::size_t j = p.first; j < p.first + p.count; ++j) sum += x[j];
      return sum / static_cast<double>(p.count);
    };
    for (auto& seg : segments) {
      Recording out;
      Channels ch = channels(rec, out);
      if (rec.table_deg) out.table_deg.emplace();
      for (const auto& p : seg) {
        out.time_s.push_back(static_cast<double>(p.k) * h);
        if (p.from_bin) {
          for (std::size_t c = 0; c < ch.in.size(); ++c)
            ch.out[c]->push_back(bin_mean(p, *ch.in[c]));
          if (rec.table_deg) {
            // The sample nearest the bin centre.
            std::size_t best = p.first;
            for (std::size_t j = p.first; j < p.first + p.count; ++j)
              if (std::fabs(t[j] - out.time_s.back()) < std::fabs(t[best] - out.time_s.back()))
                best = j;
            out.table_deg->push_back((*rec.table_deg)[best]);
          }
        } else {
          const GridPoint& left = bins[p.i];
          const GridPoint& right = bins[p.i + 1];
          for (std::size_t c = 0; c < ch.in.size(); ++c) {
            const double a = bin_mean(left, *ch.in[c]), b = bin_mean(right, *ch.in[c]);
            ch.out[c]->push_back(a + p.w * (b - a));
          }
          if (rec.table_deg) {
            const std::size_t j = p.w < 0.5 ? left.first + left.count - 1 : right.first;
            out.table_deg->push_back((*rec.table_deg)[j]);
          }
        }
      }
      result.segments.push_back(std::move(out));
    }
  } else {
    // Linear: gaps are input steps longer than 1.5 × the median step.
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
      GridPoint p;
      p.k = k;
      p.i = i;
      p.w = std::clamp((tk - t[i]) / step, 0.0, 1.0);
      segments.back().push_back(p);
    }
    for (auto& seg : segments) {
      Recording out;
      Channels ch = channels(rec, out);
      if (rec.table_deg) out.table_deg.emplace();
      for (const auto& p : seg) {
        out.time_s.push_back(static_cast<double>(p.k) * h);
        for (std::size_t c = 0; c < ch.in.size(); ++c) {
          const auto& x = *ch.in[c];
          ch.out[c]->push_back(x[p.i] + p.w * (x[p.i + 1] - x[p.i]));
        }
        if (rec.table_deg) out.table_deg->push_back((*rec.table_deg)[p.w < 0.5 ? p.i : p.i + 1]);
      }
      result.segments.push_back(std::move(out));
    }
  }

  // Keep the segments long enough to use; name them after the source.
  std::vector<Recording> kept;
  for (auto& seg : result.segments) {
    if (seg.size() < options.min_segment_samples) {
      if (seg.size() > 0) ++s.dropped_segments;
      continue;
    }
    seg.source = rec.source;
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
