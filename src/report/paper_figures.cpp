#include "report/paper_figures.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "fogdrift/eval/startup.hpp"
#include "fogdrift/features/features.hpp"

namespace fogdrift::report {
namespace {

std::string temp_label(double t) {
  return fmt::format("{}{} °C", t < 0 ? "−" : "", std::abs(t));
}

// Decimated (every `step` samples) centred moving average of a column.
std::vector<double> smoothed(const std::vector<double>& v, std::size_t window, std::size_t step) {
  const std::vector<double> s = eval::moving_average(v, window);
  std::vector<double> out;
  for (std::size_t i = 0; i < s.size(); i += step) out.push_back(s[i]);
  return out;
}

constexpr std::size_t kWindow = 61, kStep = 10;  // 60 s moving average, one point in ten

/// The test repetition's start-ups, 60 s moving average: x from `x_of`, the gyro as y.
template <typename XOf>
Panel test_startups(const FirstSeed& f, Panel panel, XOf x_of) {
  for (std::size_t i = 0; i < f.cal.recordings.size(); ++i) {
    const CampaignEntry& e = f.cal.campaign.recordings[i];
    if (e.role != Role::test) continue;
    const Recording& rec = f.cal.recordings[i];
    panel.series.push_back(
        {temp_label(e.initial_temp_degc), x_of(rec), smoothed(rec.gyro_dph, kWindow, kStep)});
  }
  return panel;
}

}  // namespace

Figure startup_figure(const FirstSeed& f) {
  Figure fig{"fig1_startup", "Fig. 1 — start-up output at every initial temperature", {}};
  fig.panels.push_back(test_startups(f,
                                     {"calibration test repetition, 60 s moving average",
                                      "time since power-on (min)",
                                      "gyro output (°/h)",
                                      {}},
                                     [](const Recording& rec) {
                                       std::vector<double> minutes;
                                       for (std::size_t k = 0; k < rec.time_s.size(); k += kStep)
                                         minutes.push_back(rec.time_s[k] / 60);
                                       return minutes;
                                     }));
  return fig;
}

Figure output_vs_temperature_figure(const FirstSeed& f) {
  Figure fig{"fig2_output_vs_temperature", "Fig. 2 — output against the FOG temperature", {}};
  fig.panels.push_back(test_startups(f,
                                     {"calibration test repetition, 60 s moving average",
                                      "FOG thermometer (°C)",
                                      "gyro output (°/h)",
                                      {}},
                                     [](const Recording& rec) {
                                       return smoothed(rec.numeric_column("temp_fog_degc"), kWindow,
                                                       kStep);
                                     }));
  return fig;
}

Figure features_figure(const PaperResult& r, const FirstSeed& f) {
  // Cycles at 5 and 15 °C before it, so that the power-on is calibration-like.
  sim::CalibrationOptions co = r.options.calibration;
  co.seed = r.seeds.front().seed;
  co.temps_degc = {5, 15, 25};
  co.repetitions = 1;
  co.test_repetitions = 0;
  const auto c = sim::simulate_calibration(r.options.instrument, co);
  const FeatureTable table =
      compute_features(c.recordings.back(), f.dataset.features, f.dataset.preprocessing);
  Figure fig3{"fig3_features_25C",
              "Fig. 3 — temperatures, rates and gradients after power-on at 25 °C",
              {{"temperatures", "time since power-on (min)", "°C", {}},
               {"rates", "time since power-on (min)", "°C/s", {}},
               {"gradients", "time since power-on (min)", "°C", {}}}};
  std::vector<double> minutes;
  for (double t : table.time_s) minutes.push_back(t / 60);
  for (std::size_t c2 = 0; c2 < table.names.size(); ++c2) {
    const std::string& name = table.names[c2];
    const std::size_t panel = name.starts_with("dT") ? 1 : (name.starts_with("grad") ? 2 : 0);
    Series s{name, minutes, {}};
    for (std::size_t k = 0; k < table.rows; ++k)
      s.y.push_back(table.x[k * table.names.size() + c2]);
    fig3.panels[panel].series.push_back(std::move(s));
  }
  return fig3;
}

Figure compensation_figure(const FirstSeed& f) {
  Figure fig8{"fig8_compensation",
              "Fig. 8 — test repetition before and after compensation (each recording's mean "
              "removed)",
              {}};
  Panel p{
      "recordings −40 … 60 °C end to end, 10 s blocks", "hours of powered time", "drift (°/h)", {}};
  Series denoised{"denoised", {}, {}};
  std::vector<Series> comp;
  std::vector<std::vector<double>> predicted;
  for (const Method method : {Method::bp, Method::ssa_svr}) {
    comp.push_back({fmt::format("compensated, {}", to_string(method)), {}, {}});
    predicted.push_back(f.models.at(method).predict_dph(f.test));
  }
  double offset_h = 0;
  for (std::size_t g = 0; g < f.test.groups.size(); ++g) {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < f.test.rows; ++i)
      if (f.test.group[i] == g) rows.push_back(i);
    if (rows.empty()) continue;
    double my = 0;
    std::vector<double> mc(comp.size(), 0.0);
    for (std::size_t i : rows) {
      my += f.test.y[i];
      for (std::size_t m = 0; m < comp.size(); ++m) mc[m] += f.test.y[i] - predicted[m][i];
    }
    my /= static_cast<double>(rows.size());
    for (double& v : mc) v /= static_cast<double>(rows.size());
    for (std::size_t i : rows) {
      const double h = offset_h + f.test.time_s[i] / 3600;
      denoised.x.push_back(h);
      denoised.y.push_back(f.test.y[i] - my);
      for (std::size_t m = 0; m < comp.size(); ++m) {
        comp[m].x.push_back(h);
        comp[m].y.push_back(f.test.y[i] - predicted[m][i] - mc[m]);
      }
    }
    offset_h = denoised.x.back() + 10.0 / 3600;
  }
  p.series.push_back(std::move(denoised));
  for (auto& s : comp) p.series.push_back(std::move(s));
  fig8.panels.push_back(std::move(p));
  return fig8;
}

Figure northfind_figure(const PaperResult& r) {
  Figure fig{"fig_northfind",
             fmt::format("North-finding RMSE per initial temperature (mean of {} seed{})",
                         r.seeds.size(), r.seeds.size() == 1 ? "" : "s"),
             {{"five findings during the start-up at each temperature",
               "initial temperature (°C)",
               "RMSE (°)",
               {}}}};
  auto& series = fig.panels[0].series;
  const std::size_t n = r.northfind_temps_degc.size();
  auto mean_over_seeds = [&](auto get) {
    std::vector<double> y(n, 0.0);
    for (const SeedRun& s : r.seeds) {
      const std::vector<double>& v = get(s);
      for (std::size_t k = 0; k < n; ++k) y[k] += v[k] / static_cast<double>(r.seeds.size());
    }
    return y;
  };
  series.push_back({"raw", r.northfind_temps_degc,
                    mean_over_seeds([](const SeedRun& s) -> const std::vector<double>& {
                      return s.raw_rmse_deg;
                    }),
                    true});
  for (const Method method : r.options.methods) {
    series.push_back({to_string(method), r.northfind_temps_degc,
                      mean_over_seeds([method](const SeedRun& s) -> const std::vector<double>& {
                        return s.method(method).rmse_deg;
                      }),
                      true});
  }
  if (!r.seeds.front().oracle_rmse_deg.empty()) {
    series.push_back({"true drift subtracted", r.northfind_temps_degc,
                      mean_over_seeds([](const SeedRun& s) -> const std::vector<double>& {
                        return s.oracle_rmse_deg;
                      }),
                      true});
  }
  std::vector<double> stable;
  for (const SeedRun& s : r.seeds) stable.push_back(s.stable_rmse_deg);
  const double st = mean_of(stable);
  series.push_back({"stable stage",
                    {r.northfind_temps_degc.front(), r.northfind_temps_degc.back()},
                    {st, st},
                    false,
                    true});
  return fig;
}

std::vector<Figure> paper_figures(const PaperResult& r, const FirstSeed& f) {
  std::vector<Figure> out;
  out.push_back(startup_figure(f));
  out.push_back(output_vs_temperature_figure(f));
  out.push_back(features_figure(r, f));
  out.push_back(compensation_figure(f));
  out.push_back(northfind_figure(r));
  return out;
}

}  // namespace fogdrift::report
