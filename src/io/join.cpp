#include "fogdrift/io/join.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

constexpr std::array<EnumName<JoinMethod>, 2> kJoinMethodNames = {
    {{JoinMethod::linear, "linear"}, {JoinMethod::nearest, "nearest"}}};

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

/// A column with values: a known one the recording has, or an extra one.
bool holds(const Recording& r, const std::string& name) {
  const std::vector<double>* col = known_column(r, name);
  if (col) return !col->empty();
  return std::any_of(r.extra.begin(), r.extra.end(),
                     [&](const ExtraColumn& e) { return e.name == name; });
}

/// Whether every cell of extra column `e` is a number.
bool numeric(const ExtraColumn& e) {
  return numbers_of(e).has_value();
}

/// The names of a recording's numeric columns but time_s, for messages and defaults.
std::vector<std::string> numeric_columns(const Recording& r) {
  std::vector<std::string> out;
  for (const auto* names : {&required_columns(), &optional_columns()})
    for (const auto& name : *names)
      if (name != "time_s" && holds(r, name)) out.push_back(name);
  for (const ExtraColumn& e : r.extra)
    if (numeric(e)) out.push_back(e.name);
  return out;
}

/// The values of the log's column at the (increasing) times `t`, by `method`; kNoValue where the
/// log has none within `limit_s` (see join.hpp).
std::vector<double> sample(const std::vector<double>& log_t, const std::vector<double>& log_v,
                           const std::vector<double>& t, JoinMethod method, double limit_s) {
  std::vector<double> out(t.size(), kNoValue);
  const std::size_t m = log_t.size();
  std::size_t j = 0;  // log_t[j] <= t[i] < log_t[j + 1], kept by a merge walk
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double ti = t[i];
    while (j + 1 < m && log_t[j + 1] <= ti) ++j;
    if (method == JoinMethod::linear) {
      if (ti < log_t.front() || ti > log_t.back()) continue;
      if (ti == log_t[j]) {
        out[i] = log_v[j];
        continue;
      }
      const double step = log_t[j + 1] - log_t[j];
      if (step > limit_s) continue;
      const double w = (ti - log_t[j]) / step;
      out[i] = log_v[j] + w * (log_v[j + 1] - log_v[j]);
    } else {
      std::size_t best = j;
      if (j + 1 < m && std::fabs(log_t[j + 1] - ti) < std::fabs(log_t[j] - ti)) best = j + 1;
      if (std::fabs(log_t[best] - ti) <= limit_s) out[i] = log_v[best];
    }
  }
  return out;
}

double default_limit(const Recording& log, JoinMethod method) {
  const double median = median_time_step_s(log.time_s);
  return method == JoinMethod::linear ? 1.5 * median : median;
}

}  // namespace

std::string_view to_string(JoinMethod method) {
  return name_in(kJoinMethodNames, method);
}

JoinMethod join_method_from_string(std::string_view text) {
  return parse_in(kJoinMethodNames, text, "method", "a join method");
}

OffsetEstimate estimate_offset(const Recording& recording, const Recording& log,
                               const OffsetSearch& search, double centre_s) {
  for (const auto& [r, name, what] : {std::tuple{&recording, &search.recording_column, "recording"},
                                      std::tuple{&log, &search.log_column, "log"}}) {
    if (!holds(*r, *name)) {
      throw OptionError("estimate",
                        fmt::format("the {} {} has no column '{}' (columns: {})", what, r->source,
                                    *name, fmt::join(numeric_columns(*r), ", ")));
    }
  }
  if (!(search.range_s >= 0) || !std::isfinite(search.range_s))
    throw OptionError("estimate",
                      fmt::format("a search range of {} s is not a duration", search.range_s));
  const std::vector<double> x_all = recording.numeric_column(search.recording_column);
  const std::vector<double> y = log.numeric_column(search.log_column);
  const auto& rt = recording.time_s;
  const auto& lt = log.time_s;

  // At most 4000 evenly spread rows of the recording: enough to fix an offset, few enough that a
  // fine search over a day of offsets stays quick.
  const std::size_t stride = std::max<std::size_t>(1, rt.size() / 4000);
  std::vector<double> t, x;
  for (std::size_t i = 0; i < rt.size(); i += stride) {
    t.push_back(rt[i]);
    x.push_back(x_all[i]);
  }
  const auto [lo_x, hi_x] = std::minmax_element(x.begin(), x.end());
  if (*hi_x == *lo_x) {
    throw InputError(recording.source, 0, 0,
                     fmt::format("column '{}' does not vary, so it cannot fix the clock offset; "
                                 "give --offset-s, or estimate from a column that changes",
                                 search.recording_column));
  }
  const double min_overlap_s = 0.5 * std::min(rt.back() - rt.front(), lt.back() - lt.front());
  const double limit = default_limit(log, JoinMethod::linear);
  std::vector<double> shifted(t.size());
  // The variance of the difference at offset d and the rows it compares; infinite where the two
  // overlap too little.
  struct Fit {
    double variance = std::numeric_limits<double>::infinity();
    std::size_t rows = 0;
  };
  auto fit_at = [&](double d) {
    Fit f;
    const double overlap =
        std::min(rt.back(), lt.back() + d) - std::max(rt.front(), lt.front() + d);
    if (overlap < min_overlap_s) return f;
    for (std::size_t i = 0; i < t.size(); ++i) shifted[i] = t[i] - d;
    const std::vector<double> v = sample(lt, y, shifted, JoinMethod::linear, limit);
    double sum = 0, sum2 = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (std::isnan(v[i])) continue;
      const double diff = x[i] - v[i];
      sum += diff;
      sum2 += diff * diff;
      ++n;
    }
    f.rows = n;
    if (n < 10) return f;
    const double mean = sum / static_cast<double>(n);
    f.variance = std::max(0.0, sum2 / static_cast<double>(n) - mean * mean);
    return f;
  };
  auto objective = [&](double d) { return fit_at(d).variance; };

  OffsetEstimate e;
  if (search.range_s > 0) {
    e.searched_from_s = centre_s - search.range_s;
    e.searched_to_s = centre_s + search.range_s;
  } else {  // every offset that leaves the minimum overlap
    e.searched_from_s = rt.front() - lt.back() + min_overlap_s;
    e.searched_to_s = rt.back() - lt.front() - min_overlap_s;
  }
  // A grid of offsets no coarser than the recording's step (or a 4000th of the range), then a
  // golden-section search within one grid step either side of the best.
  const double span = e.searched_to_s - e.searched_from_s;
  const double h = std::max(median_time_step_s(rt), span / 4000.0);
  const auto steps = static_cast<std::size_t>(std::ceil(span / h));
  std::vector<double> grid(steps + 1);
  std::size_t best = 0;
  for (std::size_t k = 0; k <= steps; ++k) {
    grid[k] = objective(std::min(e.searched_from_s + static_cast<double>(k) * h, e.searched_to_s));
    if (grid[k] < grid[best]) best = k;
  }
  if (!std::isfinite(grid[best])) {
    throw InputError(
        log.source, 0, 0,
        fmt::format("no offset in {:.6g} .. {:.6g} s lets it overlap {} by {:.6g} s "
                    "(half the shorter file); check the two time axes (import "
                    "--time-zero) or give --offset-s",
                    e.searched_from_s, e.searched_to_s, recording.source, min_overlap_s));
  }
  e.at_edge = steps > 0 && (best == 0 || best == steps);
  const double at = std::min(e.searched_from_s + static_cast<double>(best) * h, e.searched_to_s);
  double a = std::max(e.searched_from_s, at - h), b = std::min(e.searched_to_s, at + h);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = objective(c), fd = objective(d);
  for (int it = 0; it < 60 && b - a > 1e-6 * std::max(1.0, h); ++it) {
    if (fc <= fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = objective(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = objective(d);
    }
  }
  const double refined = 0.5 * (a + b);
  const Fit at_refined = fit_at(refined);
  const bool refined_better = at_refined.variance <= grid[best];
  e.offset_s = refined_better ? refined : at;
  const Fit chosen = refined_better ? at_refined : fit_at(at);
  e.residual_std = std::sqrt(chosen.variance);
  e.rows_compared = chosen.rows;
  // The two columns over the rows compared at the estimate: their gap, spread and ranges.
  {
    for (std::size_t i = 0; i < t.size(); ++i) shifted[i] = t[i] - e.offset_s;
    const std::vector<double> v = sample(lt, y, shifted, JoinMethod::linear, limit);
    double sum_d = 0, sum_x = 0, sum_x2 = 0, n = 0;
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
    double t_lo = x_lo, t_hi = -x_lo;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (std::isnan(v[i])) continue;
      sum_d += x[i] - v[i];
      sum_x += x[i];
      sum_x2 += x[i] * x[i];
      n += 1;
      x_lo = std::min(x_lo, x[i]), x_hi = std::max(x_hi, x[i]);
      y_lo = std::min(y_lo, v[i]), y_hi = std::max(y_hi, v[i]);
      t_lo = std::min(t_lo, t[i]), t_hi = std::max(t_hi, t[i]);
    }
    if (n > 0) {
      e.mean_difference = sum_d / n;
      const double mean_x = sum_x / n;
      e.recording_std = std::sqrt(std::max(0.0, sum_x2 / n - mean_x * mean_x));
      e.recording_range = x_hi - x_lo;
      e.log_range = y_hi - y_lo;
      e.compared_from_s = t_lo;
      e.compared_to_s = t_hi;
    }
  }
  e.centre_s = centre_s;
  const double f_start = objective(centre_s);
  e.residual_std_at_start = std::isfinite(f_start) ? std::sqrt(f_start) : kNoValue;
  // How sharply the minimum is defined: the run of grid offsets within twice its variance.
  const double within = 2.0 * chosen.variance;
  std::size_t left = best, right = best;
  while (left > 0 && grid[left - 1] <= within) --left;
  while (right < steps && grid[right + 1] <= within) ++right;
  e.half_width_s = std::max(0.5 * static_cast<double>(right - left) * h, 0.5 * h);
  return e;
}

JoinEvidence judge_alignment(const Recording& recording, const Recording& log,
                             const JoinOptions& options) {
  validate(recording);
  validate(log);
  if (options.offset_s && !std::isfinite(*options.offset_s))
    throw OptionError("offset_s", "must be a finite number of seconds");
  JoinEvidence ev;
  if (options.estimates.empty()) {
    if (!options.offset_s)
      throw OptionError(
          "offset_s",
          fmt::format("nothing ties the clock of {} to that of {}: give the offset (0 when both "
                      "were imported with the same --time-zero), or estimate it from a column "
                      "both hold",
                      log.source, recording.source));
    ev.given = true;
    ev.offset_s = *options.offset_s;
    return ev;
  }
  const double centre = options.offset_s.value_or(0.0);
  double weight_sum = 0, weighted = 0;
  ev.uncertainty_s = std::numeric_limits<double>::infinity();
  for (const OffsetSearch& search : options.estimates) {
    ColumnMatch m{search.recording_column,
                  search.log_column,
                  estimate_offset(recording, log, search, centre),
                  {}};
    const OffsetEstimate& e = m.estimate;
    const std::string pair = search.recording_column == search.log_column
                                 ? search.recording_column
                                 : search.recording_column + "=" + search.log_column;
    const double compared_s = e.compared_to_s - e.compared_from_s;
    if (e.at_edge)
      m.failures.push_back(fmt::format(
          "{}: the estimate {:.6g} s lies at an end of the searched range {:.6g} .. {:.6g} s, so "
          "the best offset may lie beyond it",
          pair, e.offset_s, e.searched_from_s, e.searched_to_s));
    if (!(e.half_width_s <= kJoinSharpShare * compared_s))
      m.failures.push_back(fmt::format(
          "{}: the column fixes the offset only to ±{:.3g} s, more than {:.0f} % of the {:.6g} s "
          "compared (it changes too little, or at a constant rate)",
          pair, e.half_width_s, 100 * kJoinSharpShare, compared_s));
    if (!(e.residual_std <= kJoinResidualShare * e.recording_std))
      m.failures.push_back(fmt::format(
          "{}: the two columns do not move together: their difference has STD {:.4g}, more than "
          "{:.0f} % of the column's own STD {:.4g}",
          pair, e.residual_std, 100 * kJoinResidualShare, e.recording_std));
    const double range = std::max(e.recording_range, e.log_range);
    if (!(std::fabs(e.mean_difference) <= kJoinGapShare * range))
      m.failures.push_back(fmt::format(
          "{}: the columns stand {:.4g} apart on average, more than either varies over the rows "
          "compared ({:.4g} and {:.4g}): two different quantities, not one seen twice",
          pair, e.mean_difference, e.recording_range, e.log_range));
    const double w = 1.0 / std::max(e.half_width_s * e.half_width_s, 1e-300);
    weight_sum += w;
    weighted += w * e.offset_s;
    ev.uncertainty_s = std::min(ev.uncertainty_s, e.half_width_s);
    for (const std::string& f : m.failures) ev.failures.push_back(f);
    ev.matches.push_back(std::move(m));
  }
  ev.offset_s = ev.matches.size() == 1 ? ev.matches[0].estimate.offset_s : weighted / weight_sum;
  // Several pairs must agree: each pair's estimate within the sum of its and the sharpest
  // pair's half-widths of every other.
  for (std::size_t i = 0; i < ev.matches.size(); ++i)
    for (std::size_t j = i + 1; j < ev.matches.size(); ++j) {
      const OffsetEstimate& a = ev.matches[i].estimate;
      const OffsetEstimate& b = ev.matches[j].estimate;
      if (std::fabs(a.offset_s - b.offset_s) > a.half_width_s + b.half_width_s)
        ev.failures.push_back(
            fmt::format("{} and {} disagree: {:.6g} s (±{:.3g}) against {:.6g} s (±{:.3g})",
                        ev.matches[i].recording_column + "=" + ev.matches[i].log_column,
                        ev.matches[j].recording_column + "=" + ev.matches[j].log_column, a.offset_s,
                        a.half_width_s, b.offset_s, b.half_width_s));
    }
  return ev;
}

JoinResult join(const Recording& recording, const Recording& log, const JoinOptions& options) {
  return join(recording, log, options, judge_alignment(recording, log, options));
}

JoinResult join(const Recording& recording, const Recording& log, const JoinOptions& options,
                const JoinEvidence& evidence) {
  validate(recording);
  validate(log);
  for (const auto& [value, name] :
       {std::pair{options.max_step_s, "max_step_s"}, std::pair{options.max_age_s, "max_age_s"}}) {
    if (value && !(std::isfinite(*value) && *value > 0))
      throw OptionError(name, fmt::format("{} s must be > 0", *value));
  }
  if (options.method == JoinMethod::linear && options.max_age_s)
    throw OptionError("max_age_s", "applies to the nearest method; linear takes max_step_s");
  if (options.method == JoinMethod::nearest && options.max_step_s)
    throw OptionError("max_step_s", "applies to the linear method; nearest takes max_age_s");

  JoinResult result;
  JoinSummary& s = result.summary;
  s.method = options.method;
  s.rows_in = recording.size();

  // The columns to bring in.
  const std::vector<std::string> available = numeric_columns(log);
  if (options.columns.empty()) {
    for (const std::string& name : available)
      (holds(recording, name) && !options.replace ? s.kept : s.columns).push_back(name);
    for (const ExtraColumn& e : log.extra)
      if (!numeric(e)) s.skipped.push_back(e.name);
  } else {
    for (const std::string& name : options.columns) {
      if (name == "time_s" || !holds(log, name)) {
        throw OptionError("columns", fmt::format("the log {} has no column '{}' to bring in "
                                                 "(columns: {})",
                                                 log.source, name, fmt::join(available, ", ")));
      }
      if (std::find(available.begin(), available.end(), name) == available.end())
        throw OptionError("columns", fmt::format("column '{}' of {} holds text; only numbers are "
                                                 "joined",
                                                 name, log.source));
      if (std::find(s.columns.begin(), s.columns.end(), name) != s.columns.end())
        throw OptionError("columns", fmt::format("'{}' is named twice", name));
      s.columns.push_back(name);
    }
  }
  if (s.columns.empty())
    throw OptionError(
        "columns", s.kept.empty()
                       ? fmt::format("the log {} has no numeric column besides time_s", log.source)
                       : fmt::format("every numeric column of the log {} ({}) is in the "
                                     "recording already; replace them with the log's, or "
                                     "name the ones to bring in",
                                     log.source, fmt::join(s.kept, ", ")));
  for (const std::string& name : s.columns) {
    if (holds(recording, name) && !options.replace) {
      throw OptionError("columns",
                        fmt::format("the recording {} has a column '{}' already; leave it out of "
                                    "the columns joined, or replace it with the log's",
                                    recording.source, name));
    }
  }

  // The offset, the limit, and which rows have values.
  s.evidence = evidence;
  s.offset_s = evidence.offset_s;
  if (!evidence.founded()) {
    if (!options.force)
      throw InputError(
          log.source, 0, 0,
          fmt::format("its alignment with {} is not founded, so nothing was written: {}. Give the "
                      "offset if you know it, estimate from a column both files truly share, or "
                      "write anyway with --force (the evidence is then printed with the result)",
                      recording.source, fmt::join(evidence.failures, "; ")));
    s.forced = true;
  }
  const std::optional<double>& requested =
      options.method == JoinMethod::linear ? options.max_step_s : options.max_age_s;
  s.limit_s = requested ? *requested : default_limit(log, options.method);
  s.log_from_s = log.time_s.front() + s.offset_s;
  s.log_to_s = log.time_s.back() + s.offset_s;
  for (double tl : log.time_s) {
    const double tr = tl + s.offset_s;
    if (tr >= recording.time_s.front() && tr <= recording.time_s.back()) ++s.log_rows_used;
  }
  std::vector<double> query(recording.size());
  for (std::size_t i = 0; i < query.size(); ++i) query[i] = recording.time_s[i] - s.offset_s;
  std::vector<std::vector<double>> values;
  for (const std::string& name : s.columns)
    values.push_back(
        sample(log.time_s, log.numeric_column(name), query, options.method, s.limit_s));
  const std::vector<double>& mask = values.front();  // every column has the log's times

  // Runs of joinable rows; the rows before the first and after the last are dropped.
  std::size_t first = 0, last = recording.size();
  while (first < last && std::isnan(mask[first])) ++first;
  while (last > first && std::isnan(mask[last - 1])) --last;
  if (first == last) {
    throw InputError(
        log.source, 0, 0,
        fmt::format("covers no row of {}: on the recording's time axis (offset {:.6g} s) it spans "
                    "{:.6g} .. {:.6g} s and the recording {:.6g} .. {:.6g} s{}",
                    recording.source, s.offset_s, s.log_from_s, s.log_to_s,
                    recording.time_s.front(), recording.time_s.back(),
                    s.log_to_s < recording.time_s.front() || s.log_from_s > recording.time_s.back()
                        ? "; import both with the same --time-zero, or give the clock offset"
                        : "; its samples are farther apart than the limit"));
  }
  s.dropped_before = first;
  s.dropped_after = recording.size() - last;
  for (std::size_t b = first; b < last;) {
    std::size_t e = b;
    while (e < last && !std::isnan(mask[e])) ++e;
    if (e - b >= 2) {
      Recording seg = slice(recording, b, e);
      for (std::size_t c = 0; c < s.columns.size(); ++c) {
        const std::string& name = s.columns[c];
        std::vector<double> v(values[c].begin() + static_cast<std::ptrdiff_t>(b),
                              values[c].begin() + static_cast<std::ptrdiff_t>(e));
        if (std::vector<double>* col = known_column(seg, name, true)) {
          *col = std::move(v);
          continue;
        }
        ExtraColumn extra{name, {}};
        for (double value : v) extra.cells.push_back(csv::format_number(value));
        auto it = std::find_if(seg.extra.begin(), seg.extra.end(),
                               [&](const ExtraColumn& x) { return x.name == name; });
        if (it != seg.extra.end())
          *it = std::move(extra);
        else
          seg.extra.push_back(std::move(extra));
      }
      seg.partial = seg.partial && !missing_required(seg).empty();
      validate(seg);
      s.rows_out += seg.size();
      result.segments.push_back(std::move(seg));
    } else {
      s.dropped_inside += e - b;
    }
    while (e < last && std::isnan(mask[e])) {
      ++s.dropped_inside;
      ++e;
    }
    b = e;
  }
  if (result.segments.empty()) {
    throw InputError(log.source, 0, 0,
                     fmt::format("leaves no run of 2 joinable rows in {}: its samples are farther "
                                 "apart than the limit, {:.6g} s",
                                 recording.source, s.limit_s));
  }
  return result;
}

}  // namespace fogdrift
