#include "fogdrift/eval/field.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "fogdrift/base/error.hpp"
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

double drift_error_removed(std::span<const double> raw_deg, std::span<const double> comp_deg,
                           std::span<const double> floor_deg) {
  if (comp_deg.size() != raw_deg.size() || floor_deg.size() != raw_deg.size())
    throw std::invalid_argument(fmt::format(
        "drift_error_removed: {} raw, {} compensated and {} floor errors are not paired",
        raw_deg.size(), comp_deg.size(), floor_deg.size()));
  double drift_sq = 0, left_sq = 0;
  for (std::size_t i = 0; i < raw_deg.size(); ++i) {
    // Two azimuth errors apart the short way round (northfind.hpp).
    const double d = angle_difference_deg(raw_deg[i], floor_deg[i]),
                 e = angle_difference_deg(comp_deg[i], floor_deg[i]);
    drift_sq += d * d;
    left_sq += e * e;
  }
  if (!std::isfinite(drift_sq) || !std::isfinite(left_sq) || !(drift_sq > 0)) return kNaN;
  return 1 - left_sq / drift_sq;
}

double FieldSummary::share_removed() const {
  return eval::share_removed(raw_mean_rmse_deg(), comp_mean_rmse_deg(), floor_mean_rmse_deg());
}

double FieldSummary::drift_error_removed() const {
  std::vector<double> raw, comp, floor;
  for (const FieldRecording& r : recordings) {
    if (r.floor_error_deg.empty() || r.comp_error_deg.empty()) return kNaN;
    raw.insert(raw.end(), r.raw_error_deg.begin(), r.raw_error_deg.end());
    comp.insert(comp.end(), r.comp_error_deg.begin(), r.comp_error_deg.end());
    floor.insert(floor.end(), r.floor_error_deg.begin(), r.floor_error_deg.end());
  }
  return raw.empty() ? kNaN : eval::drift_error_removed(raw, comp, floor);
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
    const double latitude = campaign.latitude_deg.value(), truth = *e.true_azimuth_deg;
    r.raw_error_deg = northfind_errors_deg(rec, latitude, truth);
    r.raw_rmse_deg = rms(r.raw_error_deg);
    r.floor_rmse_deg = kNaN;
    if (rec.has_column("drift_true_dph")) {
      r.floor_error_deg =
          northfind_errors_deg(rec, rec.numeric_column("drift_true_dph"), latitude, truth);
      r.floor_rmse_deg = rms(r.floor_error_deg);
    }
    r.comp_rmse_deg = kNaN;
    if (drift) {
      r.comp_error_deg = northfind_errors_deg(rec, drift(rec), latitude, truth);
      r.comp_rmse_deg = rms(r.comp_error_deg);
    }
    if (r.comp_rmse_deg > r.raw_rmse_deg) ++out.worse_than_raw;
    out.recordings.push_back(std::move(r));
  }
  return out;
}

}  // namespace fogdrift::eval
