// A campaign: a folder of recordings described by a manifest, campaign.json.
//
//   {"format": "fogdrift-campaign/1", "latitude_deg": 30.0,
//    "recordings": [{"file": "cal_rep1_m40C.csv", "scenario": "calibration", "role": "train",
//                    "repetition": 1, "initial_temp_degc": -40, "true_azimuth_deg": 0}, ...]}
//
// Every field is documented in docs/formats.md. Reading is strict: a syntax error gives line and
// column; a wrong, missing or unknown field gives its JSON path ("recordings[3].role") and the
// rule.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fogdrift {

/// The manifest's format tag; a reader refuses any other.
inline constexpr std::string_view kCampaignFormat = "fogdrift-campaign/1";

/// What a recording was made for (docs/method.md §3).
enum class Scenario {
  calibration,  ///< static start-up in the thermal chamber (paper §4.1): the drift to model
  northfind,    ///< four-position north-findings during start-up (paper §4.2)
  stable,       ///< the same north-findings after a long warm-up (the reference accuracy)
};

/// Which side of the train/test split a recording is on.
enum class Role { train, test };

std::string_view to_string(Scenario scenario);
std::string_view to_string(Role role);

struct CampaignEntry {
  std::string file;  ///< recording path relative to the campaign folder
  Scenario scenario = Scenario::calibration;
  Role role = Role::train;
  int repetition = 1;            ///< repetition of the temperature cycle, >= 1
  double initial_temp_degc = 0;  ///< chamber temperature at power-on, °C, in [-70, 100]
  /// Azimuth of the FOG sensitive axis at turntable angle 0, degrees clockwise from true north,
  /// in [0, 360). Required for northfind and stable; for calibration it gives the Earth-rate input.
  std::optional<double> true_azimuth_deg;
  /// Explicit input rate (°/h) seen by the FOG, overriding the Earth-rate projection.
  std::optional<double> input_rate_dph;
  /// What a target channel sensed, per target column, in its unit: an accelerometer's share of
  /// gravity, g; a scale-factor channel's nominal, ppm; a gyro axis's own input rate, °/h
  /// (docs/logs.md, "Other targets"). The target is the channel less it.
  std::map<std::string, double> references;
  std::string notes_json;  ///< free-form "notes" value as JSON text, empty if absent
};

struct Campaign {
  std::filesystem::path dir;  ///< folder holding campaign.json (set by read_campaign)
  /// Site latitude, degrees, in [-90, 90]. Required only where it is used: for northfind and
  /// stable recordings, and for a calibration recording whose input rate comes from its true
  /// azimuth (no input_rate_dph).
  std::optional<double> latitude_deg;
  std::vector<CampaignEntry> recordings;
  std::string generator_json;  ///< "generator" object as JSON text (who made the data), or empty
  std::string notes_json;      ///< free-form "notes" value as JSON text, or empty

  std::filesystem::path path_of(const CampaignEntry& entry) const { return dir / entry.file; }
};

/// Reads `path` (a campaign folder, or its campaign.json). Throws InputError with the manifest's
/// file name and line:column (syntax) or JSON path (content) and the rule broken; also when a
/// recording file is missing or listed twice. Recordings themselves are not read here.
Campaign read_campaign(const std::filesystem::path& path);

/// A manifest given as text whose recordings are held elsewhere (in memory, as Python's
/// fogdrift.simulate returns them): checked as read_campaign checks a file, errors naming
/// `source`, but for the recordings' files, which need not exist; `dir` is empty.
Campaign campaign_from_json(const std::string& text, const std::string& source);

/// The manifest as JSON text (2-space indentation, fields in documented order).
std::string manifest_json(const Campaign& campaign);

/// Writes campaign.json into `dir` atomically.
void write_manifest(const std::filesystem::path& dir, const Campaign& campaign);

}  // namespace fogdrift
