// fogdrift demo: the main job. Simulates the paper's campaigns (calibration, north-finding at
// seven initial temperatures, stable stage) and prints what the uncompensated instrument does:
// the start-up drift per initial temperature and the raw north-finding accuracy (paper Table 3,
// "raw" row). Model training and compensation join this report as they land.
#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <map>
#include <memory>

#include "commands.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::app {
namespace {

struct DemoArgs {
  std::uint64_t seed = 1;
  std::string out;
  std::size_t window_s = 61;
};

double mean(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

}  // namespace

void add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "demo",
      "Run the main job on the built-in simulator: the paper's calibration campaign, "
      "north-finding\n"
      "at -32..54 °C and the stable stage, with the start-up drift and the raw north-finding\n"
      "accuracy (paper Table 3, raw row) printed beside the paper's values.");
  auto a = std::make_shared<DemoArgs>();
  cmd->add_option("--seed", a->seed, "Random seed")->capture_default_str();
  cmd->add_option("--out,-o", a->out, "Also write the three campaigns into this folder");
  cmd->add_option("--smooth-s", a->window_s, "Moving-average window for the drift figures, samples")
      ->capture_default_str();
  cmd->callback([a] {
    const auto start = std::chrono::steady_clock::now();
    const sim::Instrument instrument;
    sim::CalibrationOptions cal_options;
    cal_options.seed = a->seed;
    sim::NorthfindOptions nf_options;
    nf_options.seed = a->seed;
    sim::NorthfindOptions st_options = sim::stable_defaults();
    st_options.seed = a->seed;
    const auto cal = sim::simulate_calibration(instrument, cal_options);
    const auto nf = sim::simulate_northfind(instrument, nf_options);
    const auto st = sim::simulate_stable(instrument, st_options);
    if (!a->out.empty()) {
      sim::write_campaign(a->out + "/calibration", cal, true);
      sim::write_campaign(a->out + "/northfind", nf, true);
      sim::write_campaign(a->out + "/stable", st, true);
    }

    std::cout << fmt::format(
        "fogdrift demo — simulated north-finding system, seed {}\n\n"
        "Calibration campaign (paper §4.1): {} recordings of 30 powered minutes.\n"
        "Start-up drift per initial temperature, mean over repetitions: STD of the gyro output\n"
        "smoothed over {} s, and of the simulator's true thermal drift; time of the minimum.\n\n",
        a->seed, cal.recordings.size(), a->window_s);
    std::cout << fmt::format("  {:>8} {:>16} {:>16} {:>12}\n", "T0 °C", "smoothed °/h",
                             "true drift °/h", "min at s");
    std::map<double, std::vector<eval::StartupStats>> smooth_by_temp, true_by_temp;
    for (std::size_t i = 0; i < cal.recordings.size(); ++i) {
      const auto& rec = cal.recordings[i];
      const double t0 = cal.campaign.recordings[i].initial_temp_degc;
      smooth_by_temp[t0].push_back(eval::startup_stats(rec.time_s, rec.gyro_dph, a->window_s));
      true_by_temp[t0].push_back(
          eval::startup_stats(rec.time_s, rec.numeric_column("drift_true_dph"), 1));
    }
    std::vector<double> all_smooth, all_true;
    for (const auto& [t0, stats] : smooth_by_temp) {
      std::vector<double> s, t, m;
      for (const auto& x : stats) s.push_back(x.std_dph), m.push_back(x.min_time_s);
      for (const auto& x : true_by_temp[t0]) t.push_back(x.std_dph);
      all_smooth.push_back(mean(s));
      all_true.push_back(mean(t));
      std::cout << fmt::format("  {:>8.0f} {:>16.4f} {:>16.4f} {:>12.0f}\n", t0, mean(s), mean(t),
                               mean(m));
    }
    std::cout << fmt::format("  {:>8} {:>16.4f} {:>16.4f}      (paper, denoised: 0.0134)\n\n",
                             "mean", mean(all_smooth), mean(all_true));

    std::cout << "North-finding, four-position method, uncompensated (paper Table 3, raw row):\n\n";
    std::cout << fmt::format("  {:>8} {:>10} {:>10} {:>10}\n", "T0 °C", "findings", "RMSE °",
                             "paper °");
    const std::map<double, double> paper_raw = {{-32, 0.0284}, {-16, 0.0181}, {-5, 0.0216},
                                                {17, 0.0205},  {28, 0.0303},  {43, 0.0171},
                                                {54, 0.0106}};
    std::vector<double> rmses;
    for (std::size_t i = 0; i < nf.recordings.size(); ++i) {
      const auto& e = nf.campaign.recordings[i];
      const auto errors = eval::northfind_errors_deg(nf.recordings[i], nf.campaign.latitude_deg,
                                                     *e.true_azimuth_deg);
      rmses.push_back(eval::rms(errors));
      const auto it = paper_raw.find(e.initial_temp_degc);
      std::cout << fmt::format("  {:>8.0f} {:>10} {:>10.4f} {:>10}\n", e.initial_temp_degc,
                               errors.size(), rmses.back(),
                               it == paper_raw.end() ? "" : fmt::format("{:.4f}", it->second));
    }
    std::cout << fmt::format("  {:>8} {:>10} {:>10.4f} {:>10.4f}\n", "mean", "", mean(rmses),
                             0.0209);
    const auto stable_errors = eval::northfind_errors_deg(
        st.recordings[0], st.campaign.latitude_deg, *st.campaign.recordings[0].true_azimuth_deg);
    std::cout << fmt::format(
        "\n  stable stage (after 2 h warm-up, {} findings): RMSE {:.4f}° "
        "(paper: 0.012°)\n",
        stable_errors.size(), eval::rms(stable_errors));
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << fmt::format("\nfinished in {:.1f} s\n", elapsed);
  });
}

}  // namespace fogdrift::app
