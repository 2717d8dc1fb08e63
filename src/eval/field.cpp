#include "fogdrift/eval/field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "fogdrift/error.hpp"
#include "fogdrift/eval/northfind.hpp"
#include "fogdrift/eval/startup.hpp"

namespace fogdrift::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class Get>
double mean_over(const std::vector<FieldRecording>& rows, Get get) {
  if (rows.empty()) return kNaN;
  double s = 0;
  for (const FieldRecording& r : rows) s += get(r);  // NaN propagates: one unknown, all unknown
  return s / static_cast<double>(rows.size());
}

// RMSE of the findings after subtracting `drift` from the gyro.
double rmse_after(Recording rec, const std::vector<double>& drift, double latitude_deg,
                  double true_azimuth_deg) {
  for (std::size_t k = 0; k < drift.size() && k < rec.gyro_dph.size(); ++k)
    rec.gyro_dph[k] -= drift[k];
  return rms(northfind_errors_deg(rec, latitude_deg, true_azimuth_deg));
}

}  // namespace

double FieldSummary::raw_mean_rmse_deg() const {
  return mean_over(recordings, [](const FieldRecording& r) { return r.raw_rmse_deg; });
}
double FieldSummary::floor_mean_rmse_deg() const {
  return mean_over(recordings, [](const FieldRecording& r) { return r.floor_rmse_deg; });
}
double FieldSummary::comp_mean_rmse_deg() const {
  return mean_over(recordings, [](const FieldRecording& r) { return r.comp_rmse_deg; });
}

double share_removed(double raw, double comp, double floor) {
  if (!std::isfinite(raw) || !std::isfinite(floor) || !std::isfinite(comp) || raw <= floor)
    return kNaN;
  return (raw * raw - comp * comp) / (raw * raw - floor * floor);
}

double FieldSummary::share_removed() const {
  return eval::share_removed(raw_mean_rmse_deg(), comp_mean_rmse_deg(), floor_mean_rmse_deg());
}

void FieldSummary::accumulate(const FieldSummary& other) {
  recordings.insert(recordings.end(), other.recordings.begin(), other.recordings.end());
  worse_than_raw += other.worse_than_raw;
}

FieldSummary field_summary(const Campaign& campaign, const std::vector<Recording>& recordings,
                           const DriftOf& drift) {
  FieldSummary out;
  for (std::size_t i = 0; i < campaign.recordings.size() && i < recordings.size(); ++i) {
    const CampaignEntry& e = campaign.recordings[i];
    if (e.scenario != Scenario::northfind) continue;
    if (!e.true_azimuth_deg)
      throw InputError((campaign.dir / "campaign.json").string(), 0, 0,
                       fmt::format("{}: a north-finding recording needs true_azimuth_deg", e.file));
    const Recording& rec = recordings[i];
    FieldRecording r;
    r.file = e.file;
    r.initial_temp_degc = e.initial_temp_degc;
    r.raw_rmse_deg = rmse_after(rec, {}, campaign.latitude_deg.value(), *e.true_azimuth_deg);
    r.floor_rmse_deg = rec.has_column("drift_true_dph")
                           ? rmse_after(rec, rec.numeric_column("drift_true_dph"),
                                        campaign.latitude_deg.value(), *e.true_azimuth_deg)
                           : kNaN;
    r.comp_rmse_deg =
        drift ? rmse_after(rec, drift(rec), campaign.latitude_deg.value(), *e.true_azimuth_deg)
              : kNaN;
    if (r.comp_rmse_deg > r.raw_rmse_deg) ++out.worse_than_raw;
    out.recordings.push_back(std::move(r));
  }
  return out;
}

}  // namespace fogdrift::eval
