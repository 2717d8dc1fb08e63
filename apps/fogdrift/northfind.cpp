// fogdrift northfind: four-position north-finding on a campaign's recordings, raw and with a
// compensation model (paper §4.2, Table 3).
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/campaign.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/eval/field.hpp"
#include "fogdrift/eval/startup.hpp"
#include "fogdrift/model.hpp"

namespace fogdrift::app {
namespace {

struct NorthfindArgs {
  bool allow_edited = false;
  std::string campaign;
  std::string model;
  bool json = false;
  bool no_guard = false;
};

double wrap360(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0 ? w + 360.0 : w;
}

void run(const NorthfindArgs& a) {
  const Campaign campaign = read_campaign(a.campaign);
  std::optional<CompensationModel> model;
  if (!a.model.empty()) model = load_compensation_model(a.model, {a.allow_edited});

  struct Row {
    std::string file;
    Scenario scenario;
    double t0;
    double true_az;
    std::vector<double> raw, comp, floor;  // floor: true drift subtracted (simulated data)
  };
  std::vector<Row> rows;
  for (const auto& e : campaign.recordings) {
    if (e.scenario == Scenario::calibration) continue;
    if (!e.true_azimuth_deg)
      throw InputError((campaign.dir / "campaign.json").string(), 0, 0,
                       fmt::format("{}: a north-finding recording needs true_azimuth_deg", e.file));
    Recording rec = read_recording(campaign.path_of(e));
    Row r{e.file, e.scenario, e.initial_temp_degc, *e.true_azimuth_deg, {}, {}, {}};
    r.raw = eval::northfind_errors_deg(rec, campaign.latitude_deg.value(), *e.true_azimuth_deg);
    if (rec.has_column("drift_true_dph")) {
      Recording truth = rec;
      const std::vector<double> d = rec.numeric_column("drift_true_dph");
      for (std::size_t i = 0; i < d.size(); ++i) truth.gyro_dph[i] -= d[i];
      r.floor =
          eval::northfind_errors_deg(truth, campaign.latitude_deg.value(), *e.true_azimuth_deg);
    }
    if (model) {
      const std::vector<double> drift = model->predict_dph(rec, !a.no_guard);
      for (std::size_t i = 0; i < drift.size(); ++i) rec.gyro_dph[i] -= drift[i];
      r.comp = eval::northfind_errors_deg(rec, campaign.latitude_deg.value(), *e.true_azimuth_deg);
    }
    rows.push_back(std::move(r));
  }
  if (rows.empty())
    throw InputError((campaign.dir / "campaign.json").string(), 0, 0,
                     "no northfind or stable recordings to find north with");

  // Table 3: RMSE per initial temperature over the start-up findings.
  std::map<double, std::pair<std::vector<double>, std::vector<double>>> by_temp;
  std::map<double, std::vector<double>> floor_by_temp;
  bool has_floor = true;
  std::vector<double> stable_raw, stable_comp;
  for (const Row& r : rows) {
    if (r.scenario != Scenario::stable) {
      has_floor = has_floor && !r.floor.empty();
      auto& f = floor_by_temp[r.t0];
      f.insert(f.end(), r.floor.begin(), r.floor.end());
    }
    auto& [raw, comp] = by_temp[r.t0];
    auto& dst_raw = r.scenario == Scenario::stable ? stable_raw : raw;
    auto& dst_comp = r.scenario == Scenario::stable ? stable_comp : comp;
    dst_raw.insert(dst_raw.end(), r.raw.begin(), r.raw.end());
    dst_comp.insert(dst_comp.end(), r.comp.begin(), r.comp.end());
  }
  std::erase_if(by_temp, [](const auto& kv) { return kv.second.first.empty(); });
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
  };
  const std::string method = model ? to_string(model->provenance.method) : "";

  if (a.json) {
    nlohmann::ordered_json j;
    j["campaign"] = a.campaign;
    if (model) j["model"] = a.model, j["method"] = method;
    for (const Row& r : rows) {
      nlohmann::ordered_json f;
      f["file"] = r.file;
      f["scenario"] = std::string(to_string(r.scenario));
      f["initial_temp_degc"] = r.t0;
      f["true_azimuth_deg"] = r.true_az;
      f["raw_error_deg"] = r.raw;
      if (model) f["compensated_error_deg"] = r.comp;
      if (!r.floor.empty()) f["true_drift_subtracted_error_deg"] = r.floor;
      j["recordings"].push_back(f);
    }
    nlohmann::ordered_json t;
    std::vector<double> temps, raw, comp;
    for (const auto& [t0, e] : by_temp) {
      temps.push_back(t0);
      raw.push_back(eval::rms(e.first));
      if (model) comp.push_back(eval::rms(e.second));
    }
    t["temps_degc"] = temps;
    t["raw_rmse_deg"] = raw;
    if (model) t["compensated_rmse_deg"] = comp;
    if (has_floor && !by_temp.empty()) {
      std::vector<double> floor;
      for (const auto& [t0, e] : by_temp) floor.push_back(eval::rms(floor_by_temp[t0]));
      t["true_drift_subtracted_rmse_deg"] = floor;
      if (model)
        t["removable_error_removed"] = eval::share_removed(mean(raw), mean(comp), mean(floor));
    }
    j["table3"] = t;
    if (model) j["guard"] = !a.no_guard;
    if (!stable_raw.empty()) j["stable_rmse_deg"] = eval::rms(stable_raw);
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("Four-position north-finding, {}{}\n\n", a.campaign,
                           model ? fmt::format(", compensated with {} ({})", a.model, method) : "");
  std::cout << fmt::format("  {:<28} {:>7} {:>12} {:>12}{}\n", "recording", "T0 °C", "azimuth °",
                           "error °",
                           model ? fmt::format(" {:>12} {:>12}", "comp. az °", "comp. err °") : "");
  for (const Row& r : rows)
    for (std::size_t k = 0; k < r.raw.size(); ++k) {
      std::cout << fmt::format("  {:<28} {:>7.0f} {:>12.4f} {:>12.4f}", k ? "" : r.file, r.t0,
                               wrap360(r.true_az + r.raw[k]), r.raw[k]);
      if (model && k < r.comp.size())
        std::cout << fmt::format(" {:>12.4f} {:>12.4f}", wrap360(r.true_az + r.comp[k]), r.comp[k]);
      std::cout << "\n";
    }
  std::cout << "\nTable 3 view, RMSE per initial temperature (°):\n\n";
  std::cout << fmt::format("  {:>8} {:>10} {:>10}{}\n", "T0 °C", "findings", "raw",
                           model ? fmt::format(" {:>10}", method) : "");
  std::vector<double> raw_rmse, comp_rmse;
  for (const auto& [t0, e] : by_temp) {
    raw_rmse.push_back(eval::rms(e.first));
    std::cout << fmt::format("  {:>8.0f} {:>10} {:>10.4f}", t0, e.first.size(), raw_rmse.back());
    if (model) {
      comp_rmse.push_back(eval::rms(e.second));
      std::cout << fmt::format(" {:>10.4f}", comp_rmse.back());
    }
    std::cout << "\n";
  }
  std::cout << fmt::format("  {:>8} {:>10} {:>10.4f}", "mean", "", mean(raw_rmse));
  if (model) std::cout << fmt::format(" {:>10.4f}", mean(comp_rmse));
  std::cout << "\n";
  if (has_floor && !by_temp.empty()) {
    std::vector<double> floor;
    for (const auto& [t0, e] : by_temp) floor.push_back(eval::rms(floor_by_temp[t0]));
    std::cout << fmt::format("  {:>8} {:>10} {:>10.4f}   (the recordings' true drift subtracted)\n",
                             "floor", "", mean(floor));
    if (model)
      std::cout << fmt::format(
          "\n  {} removes {:.0f} % of the removable error, (raw² − comp²) / (raw² − floor²)\n",
          method, 100 * eval::share_removed(mean(raw_rmse), mean(comp_rmse), mean(floor)));
  }
  if (model && a.no_guard) std::cout << "  (guard off: the model's full correction everywhere)\n";
  if (!stable_raw.empty())
    std::cout << fmt::format("\n  stable stage ({} findings): RMSE {:.4f}° (paper: 0.012°)\n",
                             stable_raw.size(), eval::rms(stable_raw));
}

}  // namespace

void add_northfind(CLI::App& app) {
  auto args = std::make_shared<NorthfindArgs>();
  auto* cmd = app.add_subcommand(
      "northfind",
      "Find north with the four-position method on a campaign's northfind and stable recordings:\n"
      "mean gyro rate at 0°, 90°, 180° and 270° (detected from table_deg, rotations excluded),\n"
      "tilt from the accelerometers, azimuth by the exact geometry. Prints every finding's\n"
      "azimuth and error against the manifest's true azimuth, raw and (with --model) after\n"
      "subtracting the model's drift, and the RMSE per initial temperature (paper Table 3).\n"
      "On simulated recordings (a drift_true_dph column) also the floor, the RMSE with the true\n"
      "drift subtracted, and the share of the removable error the model removes.\n"
      "Example:\n"
      "  fogdrift simulate northfind --out nf && fogdrift northfind nf --model model.json");
  cmd->add_option("campaign", args->campaign, "Campaign folder (or its campaign.json)")->required();
  cmd->add_option("--model", args->model, "Compensation model written by `fogdrift train`");
  cmd->add_flag("--allow-edited", args->allow_edited,
                "Load a model file whose content no longer matches its checksum (an edit made on "
                "purpose); its fields are still checked");
  cmd->add_flag("--json", args->json, "Print the findings and Table 3 as JSON");
  cmd->add_flag("--no-guard", args->no_guard,
                "Apply the model's full correction even where its inputs are novel");
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
