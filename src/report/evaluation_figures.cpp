// A user's own evaluation drawn (evaluation_figures.hpp).
#include "fogdrift/report/evaluation_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "fogdrift/io/target.hpp"

namespace fogdrift::report {
namespace {

/// y − p, row by row.
std::vector<double> left_by(const std::vector<double>& y, const std::vector<double>& p) {
  std::vector<double> out(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i] - p[i];
  return out;
}

/// A dashed box's sides: the training range of x against that of y.
Series box(const std::string& name, double x0, double x1, double y0, double y1) {
  return {name, {x0, x1, x1, x0, x0}, {y0, y0, y1, y1, y0}, false, true};
}

}  // namespace

std::vector<Figure> evaluation_figures(const eval::Evaluation& e,
                                       const TrainingBaselines& baselines,
                                       const std::vector<std::string>& feature_names,
                                       const std::string& prefix) {
  for (const eval::RecordingEvaluation& r : e.recordings)
    if (!r.series) throw std::invalid_argument("evaluation_figures: the evaluation kept no series");
  const Target target = target_of(e.target);
  const std::string unit(target.symbol());
  const std::string line = e.line_input.empty() ? "" : "line in " + e.line_input;
  std::vector<Figure> out;

  Figure rec{prefix + "recordings",
             fmt::format("{}: each recording raw and compensated ({}, verdict: {})", e.target,
                         e.method, eval::verdict(e)),
             {}};
  for (const eval::RecordingEvaluation& r : e.recordings) {
    const eval::RecordingSeries& s = *r.series;
    std::vector<double> minutes(s.time_s.size());
    std::transform(s.time_s.begin(), s.time_s.end(), minutes.begin(),
                   [](double t) { return t / 60.0; });
    Panel p{fmt::format("{} ({})", r.info.file,
                        r.baselines.harms.empty()
                            ? (r.baselines.no_better_than.empty() ? "better than its baselines"
                                                                  : "no better than its baselines")
                            : "HARMED"),
            "minutes since power-on",
            fmt::format("{} less its reference, {}", e.target, unit),
            {}};
    p.series.push_back({"raw", minutes, s.target});
    if (!s.line.empty())
      p.series.push_back({"after the " + line, minutes, left_by(s.target, s.line)});
    p.series.push_back({"after the model", minutes, left_by(s.target, s.model)});
    rec.panels.push_back(std::move(p));
  }
  out.push_back(std::move(rec));

  if (!e.temperature_input.empty()) {
    Figure res{
        prefix + "residual_vs_T",
        fmt::format("{}: what compensation leaves against {}", e.target, e.temperature_input),
        {}};
    Panel p{"every recording's rows", e.temperature_input, fmt::format("residual, {}", unit), {}};
    Series model{"model", {}, {}}, by_line{line, {}, {}};
    model.scatter = by_line.scatter = true;
    for (const eval::RecordingEvaluation& r : e.recordings) {
      const eval::RecordingSeries& s = *r.series;
      for (std::size_t i = 0; i < s.temperature.size(); ++i) {
        model.x.push_back(s.temperature[i]);
        model.y.push_back(s.target[i] - s.model[i]);
        if (!s.line.empty()) {
          by_line.x.push_back(s.temperature[i]);
          by_line.y.push_back(s.target[i] - s.line[i]);
        }
      }
    }
    if (!by_line.x.empty()) p.series.push_back(std::move(by_line));
    p.series.push_back(std::move(model));
    res.panels.push_back(std::move(p));
    out.push_back(std::move(res));
  }

  if (!e.temperature_input.empty() && !e.rate_input.empty()) {
    Figure reg{prefix + "region",
               fmt::format("{}: the held-out rows over the training region", e.target),
               {}};
    Panel p{"training region: the guard's prototypes; training ranges dashed",
            e.temperature_input,
            e.rate_input,
            {}};
    if (!e.region_temperature.empty()) {
      p.series.push_back({"training (prototypes)", e.region_temperature, e.region_rate});
      p.series.back().scatter = true;
    }
    const auto t = std::find(feature_names.begin(), feature_names.end(), e.temperature_input);
    const auto r = std::find(feature_names.begin(), feature_names.end(), e.rate_input);
    if (baselines.has_ranges() && t != feature_names.end() && r != feature_names.end()) {
      const auto kt = static_cast<std::size_t>(t - feature_names.begin());
      const auto kr = static_cast<std::size_t>(r - feature_names.begin());
      p.series.push_back(box("training ranges", baselines.input_min[kt], baselines.input_max[kt],
                             baselines.input_min[kr], baselines.input_max[kr]));
    }
    for (const eval::RecordingEvaluation& rec : e.recordings) {
      p.series.push_back({rec.info.file, rec.series->temperature, rec.series->rate});
      p.series.back().scatter = true;
    }
    reg.panels.push_back(std::move(p));
    out.push_back(std::move(reg));
  }
  return out;
}

}  // namespace fogdrift::report
