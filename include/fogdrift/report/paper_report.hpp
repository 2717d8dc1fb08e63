// The paper experiment's results as people and machines read them: report.md and JSON, with the
// paper's own numbers (docs/method.md §3) beside fogdrift's means over seeds.
#pragma once

#include <string>
#include <vector>

#include "fogdrift/report/paper.hpp"

namespace fogdrift::report {

/// Mean and sample standard deviation (SD 0 for one value).
struct MeanSd {
  double mean = 0, sd = 0;
};
MeanSd mean_sd(const std::vector<double>& values);

/// The goals fogdrift holds itself to (docs/paper.md, docs/field.md), judged on the means over
/// seeds: the paper's two Table 2 goals, its Table 3 goal restated against the stable stage and
/// the floor, and the field's: under every start-up condition no worse than raw.
struct PaperVerdict {
  double std_ratio = 0;  ///< SSA-SVR compensated STD / denoised STD (goal ≤ 1/4)
  /// The tuned SVR methods (PSO-, GWO-, SSA-SVR) whose STD is above BP's (goal: none).
  std::vector<std::string> tuned_worse_than_bp;
  double stable_ratio = 0;  ///< SSA-SVR mean RMSE / stable RMSE (goal ≤ 1.2)
  /// SSA-SVR mean RMSE / mean RMSE with the true drift subtracted (goal ≤ 1.15); NaN without it.
  double floor_ratio = 0;
  double northfind_ratio = 0;  ///< SSA-SVR mean RMSE / raw mean RMSE (the paper's "halved")
  /// The floor's mean RMSE / raw mean RMSE: the lowest northfind_ratio possible on this
  /// instrument. NaN when the runs have no true drift.
  double oracle_ratio = 0;
  /// Share of the removable error SSA-SVR removes under each start-up condition
  /// (PaperOptions::start_ups order; eval/field.hpp), guarded; NaN without the floor.
  std::vector<double> ssa_removed;
  /// "METHOD under APPROACH" for every method whose guarded mean RMSE exceeds raw (goal: none).
  std::vector<std::string> worse_than_raw;
  /// SSA-SVR removes at least 60 % under every start-up condition (true with none asked).
  bool start_ups_removed_enough() const;
  bool holds() const;  ///< every goal above
};
PaperVerdict verdict(const PaperResult& result);

/// The machine-readable summary: {"table1": {"C", "C_sd", "sigma", "sigma_sd"},
/// "table2": {METHOD: {"mae_dph", "mae_dph_sd", "std_dph", "std_dph_sd"}}, "table3":
/// {"temps_degc", METHOD: {"rmse_deg", "rmse_deg_sd", "mean_deg", "mean_deg_sd"}},
/// "stable_rmse_deg", "stable_rmse_deg_sd", "seeds", "elapsed_s", plus "seed_values", "goals",
/// "studies", "settings" and "per_seed"}, METHOD among "denoised" (Table 2) or "raw" (Table 3)
/// and kPaperMethods; every value is the mean over seeds, with its SD in the "_sd" companion.
std::string paper_json(const PaperResult& result);

/// report.md: settings, Tables 1–3 as mean ± SD beside the paper's values, the paper's goals,
/// the two studies, per-seed figures and the plots (linked as NAME.png).
std::string paper_markdown(const PaperResult& result);

}  // namespace fogdrift::report
