// fogdrift northfind: four-position north-finding on a campaign's recordings, raw and with a
// compensation model (paper §4.2, Table 3).
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/eval/findings.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct NorthfindArgs {
  ModelLoadOptions load;
  std::string campaign;
  std::string model;
  bool json = false;
  std::shared_ptr<OptionFlags> flags;  // the finding's options (eval_option_table.hpp)
};

double wrap360(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0 ? w + 360.0 : w;
}

void run(const NorthfindArgs& a) {
  eval::FindingOptions options;
  a.flags->apply(eval::finding_option_table(), options);
  const Campaign campaign = read_campaign(a.campaign);
  std::optional<CompensationModel> model;
  if (!a.model.empty()) {
    // North-finding reads gyro_dph, the FOG axis: of a model set, its gyro_dph model.
    const ModelSet set = load_model_set(a.model, a.load);
    model = set.models.size() == 1 ? set.models.front() : choose_model(set, "gyro_dph", "model");
    if (model->dataset.target_column != "gyro_dph")
      throw OptionError("model", fmt::format("{} compensates {}; north-finding reads gyro_dph, the "
                                             "FOG axis",
                                             a.model, model->dataset.target_column));
  }
  eval::CampaignFindings f;
  try {
    f = eval::find_north(campaign, model ? &*model : nullptr, options);
  } catch (const OptionError& e) {
    throw a.flags->named(e);
  }
  if (a.json) {
    std::cout << eval::to_json(f, a.campaign, a.model) << "\n";
    return;
  }
  std::cout << fmt::format(
      "Four-position north-finding, {}{}\n\n", a.campaign,
      model ? fmt::format(", compensated with {} ({})", a.model, f.method) : "");
  std::cout << fmt::format("  {:<28} {:>7} {:>12} {:>12}{}\n", "recording", "T0 °C", "azimuth °",
                           "error °",
                           model ? fmt::format(" {:>12} {:>12}", "comp. az °", "comp. err °") : "");
  for (const eval::RecordingFindings& r : f.recordings)
    for (std::size_t k = 0; k < r.raw_error_deg.size(); ++k) {
      std::cout << fmt::format(
          "  {:<28} {:>7.0f} {:>12.4f} {:>12.4f}", k ? "" : r.file, r.initial_temp_degc,
          wrap360(r.true_azimuth_deg + r.raw_error_deg[k]), r.raw_error_deg[k]);
      if (model && k < r.compensated_error_deg.size())
        std::cout << fmt::format(" {:>12.4f} {:>12.4f}",
                                 wrap360(r.true_azimuth_deg + r.compensated_error_deg[k]),
                                 r.compensated_error_deg[k]);
      std::cout << "\n";
    }
  // A campaign of stable recordings only has no start-ups for Table 3.
  if (!f.table3.empty()) {
    std::cout << "\nTable 3 view, RMSE per initial temperature (°):\n\n";
    std::cout << fmt::format("  {:>8} {:>10} {:>10}{}\n", "T0 °C", "findings", "raw",
                             model ? fmt::format(" {:>10}", f.method) : "");
    for (const eval::Table3Row& r : f.table3) {
      std::cout << fmt::format("  {:>8.0f} {:>10} {:>10.4f}", r.initial_temp_degc, r.findings,
                               r.raw_rmse_deg);
      if (model) std::cout << fmt::format(" {:>10.4f}", r.compensated_rmse_deg);
      std::cout << "\n";
    }
    std::cout << fmt::format("  {:>8} {:>10} {:>10.4f}", "mean", "", f.raw_mean_rmse_deg());
    if (model) std::cout << fmt::format(" {:>10.4f}", f.compensated_mean_rmse_deg());
    std::cout << "\n";
    if (f.has_floor) {
      std::cout << fmt::format(
          "  {:>8} {:>10} {:>10.4f}   (the recordings' true drift subtracted)\n", "floor", "",
          f.floor_mean_rmse_deg());
      if (model)
        std::cout << fmt::format(
            "\n  {} removes {:.0f} % of the removable error, (raw² − comp²) / (raw² − floor²)\n"
            "  and {:.0f} % of the drift's own error, finding by finding,"
            " 1 − Σ(comp − floor)² / Σ(raw − floor)²\n",
            f.method, 100 * f.share_removed(), 100 * f.drift_error_removed());
    }
  }
  if (model && !f.guarded) std::cout << "  (guard off: the model's full correction everywhere)\n";
  if (!f.stable_error_deg.empty())
    std::cout << fmt::format("\n  stable stage ({} findings): RMSE {:.4f}° (paper: 0.012°)\n",
                             f.stable_error_deg.size(), eval::rms(f.stable_error_deg));
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
      "drift subtracted, and the share of the removable error the model removes, on the\n"
      "RMSEs and finding by finding (docs/field.md, \"Finding by finding\").\n"
      "Example:\n"
      "  fogdrift simulate northfind --out nf && fogdrift northfind nf --model model.json");
  cmd->add_option("campaign", args->campaign, "Campaign folder (or its campaign.json)")->required();
  cmd->add_option("--model", args->model, "Compensation model written by `fogdrift train`");
  add_model_load_flags(cmd, &args->load);
  cmd->add_flag("--json", args->json, "Print the findings and Table 3 as JSON");
  const auto& table = eval::finding_option_table();
  args->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
