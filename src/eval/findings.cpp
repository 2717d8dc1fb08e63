// A campaign's north-findings and Table 3 (findings.hpp).
#include "fogdrift/eval/findings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "fogdrift/base/error.hpp"
#include "fogdrift/eval/field.hpp"
#include "fogdrift/eval/startup.hpp"

namespace fogdrift::eval {
namespace {

// NaN: a figure that is not known (no model, no floor).
constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

double mean_of(const std::vector<Table3Row>& rows, double Table3Row::*field) {
  if (rows.empty()) return kUnknown;
  double s = 0;
  for (const Table3Row& r : rows) s += r.*field;
  return s / static_cast<double>(rows.size());
}

}  // namespace

double CampaignFindings::raw_mean_rmse_deg() const {
  return mean_of(table3, &Table3Row::raw_rmse_deg);
}
double CampaignFindings::compensated_mean_rmse_deg() const {
  return method.empty() ? kUnknown : mean_of(table3, &Table3Row::compensated_rmse_deg);
}
double CampaignFindings::floor_mean_rmse_deg() const {
  return has_floor ? mean_of(table3, &Table3Row::floor_rmse_deg) : kUnknown;
}
double CampaignFindings::share_removed() const {
  if (method.empty() || !has_floor || table3.empty()) return kUnknown;
  return eval::share_removed(raw_mean_rmse_deg(), compensated_mean_rmse_deg(),
                             floor_mean_rmse_deg());
}

double CampaignFindings::drift_error_removed() const {
  if (method.empty() || !has_floor) return kUnknown;
  std::vector<double> raw, comp, floor;
  for (const RecordingFindings& r : recordings) {
    if (r.scenario == Scenario::stable) continue;  // as in Table 3
    raw.insert(raw.end(), r.raw_error_deg.begin(), r.raw_error_deg.end());
    comp.insert(comp.end(), r.compensated_error_deg.begin(), r.compensated_error_deg.end());
    floor.insert(floor.end(), r.floor_error_deg.begin(), r.floor_error_deg.end());
  }
  return raw.empty() ? kUnknown : eval::drift_error_removed(raw, comp, floor);
}

namespace {

// find_north on the recordings given (in memory), or read from the campaign's folder.
CampaignFindings find_north_in(const Campaign& campaign, const std::vector<Recording>* held,
                               const CompensationModel* model, const FindingOptions& options) {
  validate(options.segmentation);
  const bool guarded = options.guarded;
  const SegmentationOptions& segmentation = options.segmentation;
  const std::string manifest = (campaign.dir / "campaign.json").string();
  CampaignFindings out;
  out.guarded = guarded;
  if (model != nullptr) out.method = std::string(model->provenance.method);
  for (std::size_t i = 0; i < campaign.recordings.size(); ++i) {
    const CampaignEntry& e = campaign.recordings[i];
    if (e.scenario == Scenario::calibration) continue;
    if (!e.true_azimuth_deg)
      throw InputError(manifest, 0, 0,
                       fmt::format("{}: a north-finding recording needs true_azimuth_deg", e.file));
    const double latitude = campaign.latitude_deg.value();
    const Recording rec = held ? (*held)[i] : read_recording(campaign.path_of(e));
    const double truth = *e.true_azimuth_deg;
    RecordingFindings r{e.file, e.scenario, e.initial_temp_degc, truth, {}, {}, {}};
    r.raw_error_deg = northfind_errors_deg(rec, latitude, truth, segmentation);
    if (rec.has_column("drift_true_dph"))
      r.floor_error_deg = northfind_errors_deg(rec, rec.numeric_column("drift_true_dph"), latitude,
                                               truth, segmentation);
    if (model != nullptr)
      r.compensated_error_deg = northfind_errors_deg(rec, model->predict_dph(rec, guarded),
                                                     latitude, truth, segmentation);
    out.recordings.push_back(std::move(r));
  }
  if (out.recordings.empty())
    throw InputError(manifest, 0, 0, "no northfind or stable recordings to find north with");

  // Table 3 pools the start-up findings by initial temperature; stable ones are apart.
  struct Pooled {
    std::vector<double> raw, comp, floor;
  };
  std::map<double, Pooled> by_temp;
  out.has_floor = true;
  for (const RecordingFindings& r : out.recordings) {
    if (r.scenario == Scenario::stable) {
      out.stable_error_deg.insert(out.stable_error_deg.end(), r.raw_error_deg.begin(),
                                  r.raw_error_deg.end());
      continue;
    }
    out.has_floor = out.has_floor && !r.floor_error_deg.empty();
    Pooled& p = by_temp[r.initial_temp_degc];
    p.raw.insert(p.raw.end(), r.raw_error_deg.begin(), r.raw_error_deg.end());
    p.comp.insert(p.comp.end(), r.compensated_error_deg.begin(), r.compensated_error_deg.end());
    p.floor.insert(p.floor.end(), r.floor_error_deg.begin(), r.floor_error_deg.end());
  }
  for (const auto& [t0, p] : by_temp) {
    if (p.raw.empty()) continue;
    out.table3.push_back({t0, p.raw.size(), rms(p.raw), model != nullptr ? rms(p.comp) : kUnknown,
                          out.has_floor ? rms(p.floor) : kUnknown});
  }
  return out;
}

}  // namespace

CampaignFindings find_north(const Campaign& campaign, const CompensationModel* model,
                            const FindingOptions& options) {
  return find_north_in(campaign, nullptr, model, options);
}

CampaignFindings find_north(const Campaign& campaign, const std::vector<Recording>& recordings,
                            const CompensationModel* model, const FindingOptions& options) {
  if (recordings.size() != campaign.recordings.size())
    throw OptionError("recordings", fmt::format("{} recordings for a manifest of {}",
                                                recordings.size(), campaign.recordings.size()));
  return find_north_in(campaign, &recordings, model, options);
}

std::string to_json(const CampaignFindings& f, const std::string& campaign_label,
                    const std::string& model_label) {
  const bool model = !f.method.empty();
  nlohmann::ordered_json j;
  j["campaign"] = campaign_label;
  if (model) j["model"] = model_label, j["method"] = f.method;
  j["recordings"] = nlohmann::ordered_json::array();
  for (const RecordingFindings& r : f.recordings) {
    nlohmann::ordered_json o;
    o["file"] = r.file;
    o["scenario"] = std::string(to_string(r.scenario));
    o["initial_temp_degc"] = r.initial_temp_degc;
    o["true_azimuth_deg"] = r.true_azimuth_deg;
    o["raw_error_deg"] = r.raw_error_deg;
    if (model) o["compensated_error_deg"] = r.compensated_error_deg;
    if (!r.floor_error_deg.empty()) o["true_drift_subtracted_error_deg"] = r.floor_error_deg;
    j["recordings"].push_back(std::move(o));
  }
  nlohmann::ordered_json t;
  std::vector<double> temps, raw, comp, floor;
  for (const Table3Row& r : f.table3) {
    temps.push_back(r.initial_temp_degc);
    raw.push_back(r.raw_rmse_deg);
    comp.push_back(r.compensated_rmse_deg);
    floor.push_back(r.floor_rmse_deg);
  }
  t["temps_degc"] = temps;
  t["raw_rmse_deg"] = raw;
  if (model) t["compensated_rmse_deg"] = comp;
  if (f.has_floor && !f.table3.empty()) {
    t["true_drift_subtracted_rmse_deg"] = floor;
    if (model) {
      t["removable_error_removed"] = f.share_removed();
      t["drift_error_removed"] = f.drift_error_removed();
    }
  }
  j["table3"] = t;
  if (model) j["guard"] = f.guarded;
  if (!f.stable_error_deg.empty()) j["stable_rmse_deg"] = rms(f.stable_error_deg);
  return j.dump(2);
}

}  // namespace fogdrift::eval
