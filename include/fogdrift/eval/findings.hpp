// A campaign's four-position north-findings and the paper's Table 3 (docs/method.md
// "Evaluation"): every northfind and stable recording found raw, with a compensation model's
// drift subtracted, and, on simulated recordings (a drift_true_dph column), with the true drift
// subtracted (the floor). What `fogdrift northfind` prints and Python's fogdrift.northfind
// returns, computed once here.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model.hpp"

namespace fogdrift::eval {

struct RecordingFindings {
  std::string file;  ///< as the manifest names it
  Scenario scenario = Scenario::northfind;
  double initial_temp_degc = 0;
  double true_azimuth_deg = 0;
  std::vector<double> raw_error_deg;  ///< one per finding, azimuth − truth in (−180, 180]
  std::vector<double> compensated_error_deg;  ///< empty without a model
  std::vector<double> floor_error_deg;        ///< empty without drift_true_dph
};

/// Table 3's row for one initial temperature: RMSE over its start-up findings (stable
/// recordings are not in it).
struct Table3Row {
  double initial_temp_degc = 0;
  std::size_t findings = 0;
  double raw_rmse_deg = 0;
  double compensated_rmse_deg = 0;  ///< NaN without a model
  double floor_rmse_deg = 0;        ///< NaN unless every start-up recording has the true drift
};

struct CampaignFindings {
  std::string method;                         ///< the model's method, empty without a model
  bool guarded = true;                        ///< the novelty guard was on
  bool has_floor = false;                     ///< every start-up recording carries drift_true_dph
  std::vector<RecordingFindings> recordings;  ///< northfind and stable, in campaign order
  std::vector<Table3Row> table3;              ///< by ascending initial temperature
  std::vector<double> stable_error_deg;       ///< every finding of the stable recordings

  double raw_mean_rmse_deg() const;          ///< mean over table3, as Table 3's "mean"
  double compensated_mean_rmse_deg() const;  ///< NaN without a model
  double floor_mean_rmse_deg() const;        ///< NaN without a floor
  /// (raw² − comp²) / (raw² − floor²) on the means (field.hpp); NaN without model or floor.
  double share_removed() const;
  /// The share of the drift's own error removed, every start-up finding paired with itself
  /// with the true drift subtracted (field.hpp, drift_error_removed); NaN without model or floor.
  double drift_error_removed() const;
};

/// How north is found (`fogdrift northfind`'s options, northfind_option_table.hpp).
struct FindingOptions {
  bool guarded = true;               ///< the model's drift reduced where its inputs are novel
  SegmentationOptions segmentation;  ///< how the four positions are found in table_deg
};

/// Finds north on the campaign's northfind and stable recordings, subtracting `model`'s drift
/// (guarded or not) when it is given. Throws InputError naming campaign.json when such a
/// recording lacks its true azimuth, or when there is none; OptionError for impossible options.
CampaignFindings find_north(const Campaign& campaign, const CompensationModel* model = nullptr,
                            const FindingOptions& options = {});

/// The same on a campaign held in memory (campaign_from_json): `recordings[i]` is the data of
/// `campaign.recordings[i]`, as Python's fogdrift.simulate returns them.
CampaignFindings find_north(const Campaign& campaign, const std::vector<Recording>& recordings,
                            const CompensationModel* model = nullptr,
                            const FindingOptions& options = {});

/// The JSON `fogdrift northfind --json` prints: "campaign" (`campaign_label`), "model"
/// (`model_label`, with a model) and "method", "recordings", "table3", "guard", and
/// "stable_rmse_deg" when there are stable findings.
std::string to_json(const CampaignFindings& findings, const std::string& campaign_label,
                    const std::string& model_label);

}  // namespace fogdrift::eval
