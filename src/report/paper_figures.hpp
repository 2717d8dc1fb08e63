// The figures of fogdrift paper, one function a figure (docs/paper.md, "What one run does").
// Internal header of src/report: not installed.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fogdrift/model/dataset.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/report/figure.hpp"
#include "fogdrift/report/paper.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::report {

/// The mean of `v`, 0 when it is empty.
inline double mean_of(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

/// What the first seed keeps for the studies and the figures.
struct FirstSeed {
  sim::SimulatedCampaign cal, nf;
  Dataset train, test;
  DatasetOptions dataset;
  std::map<Method, CompensationModel> models;
};

/// Fig. 1: the test repetition's start-ups against time, 60 s moving average.
Figure startup_figure(const FirstSeed& f);
/// Fig. 2: the same outputs against the FOG thermometer.
Figure output_vs_temperature_figure(const FirstSeed& f);
/// Fig. 3: temperatures, rates and gradients after a calibration-like power-on at 25 °C.
Figure features_figure(const PaperResult& r, const FirstSeed& f);
/// Fig. 8: the test repetition before and after BP and SSA-SVR compensation, end to end.
Figure compensation_figure(const FirstSeed& f);
/// North-finding RMSE per initial temperature, every method, means over the seeds.
Figure northfind_figure(const PaperResult& r);

/// Every figure above, in that order.
std::vector<Figure> paper_figures(const PaperResult& r, const FirstSeed& f);

}  // namespace fogdrift::report
