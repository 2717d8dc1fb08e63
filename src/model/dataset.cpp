#include "fogdrift/model/dataset.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <numeric>

#include "fogdrift/base/earth.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/memory.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/svr/workspace.hpp"

namespace fogdrift {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace

Dataset Dataset::select_groups(std::span<const std::size_t> group_indices) const {
  Dataset out;
  out.feature_names = feature_names;
  out.feature_spec = feature_spec;
  out.groups = groups;
  out.warnings = warnings;
  std::vector<bool> keep(groups.size(), false);
  for (std::size_t g : group_indices) {
    if (g >= groups.size()) throw std::out_of_range("Dataset::select_groups: no such group");
    keep[g] = true;
  }
  const std::size_t c = cols();
  for (std::size_t i = 0; i < rows; ++i) {
    if (!keep[group[i]]) continue;
    out.x.insert(out.x.end(), x.begin() + static_cast<std::ptrdiff_t>(i * c),
                 x.begin() + static_cast<std::ptrdiff_t>((i + 1) * c));
    out.y.push_back(y[i]);
    out.time_s.push_back(time_s[i]);
    out.group.push_back(group[i]);
  }
  out.rows = out.y.size();
  return out;
}

std::vector<double> drift_target(const RecordingInput& input, const DatasetOptions& options,
                                 GroupInfo& info, std::vector<std::string>& warnings) {
  const Recording& rec = input.recording;
  std::vector<double> gyro = target_values(rec, options.target_column);
  if (options.denoise_target) {
    try {
      gyro = signal::denoise(gyro, options.denoise).signal;
    } catch (const OptionError& e) {
      // The setting that cannot be met is the target's denoising, whatever field it names.
      throw OptionError("denoise",
                        fmt::format("{}: {}; the gyro target is wavelet-denoised before training",
                                    rec.source, e.message()));
    }
  }
  const std::size_t n = gyro.size();
  const Target target = target_of(options.target_column);
  std::vector<double> input_rate(n, 0.0);
  const auto reference = input.references.find(target.column);
  if (reference != input.references.end()) {
    info.target = "reference";
    std::fill(input_rate.begin(), input_rate.end(), reference->second);
  } else if (target.kind == TargetKind::gyro && input.input_rate_dph) {
    info.target = "input_rate";
    std::fill(input_rate.begin(), input_rate.end(), *input.input_rate_dph);
  } else if (target.kind == TargetKind::gyro && input.latitude_deg && input.true_azimuth_deg) {
    if (options.target_column != "gyro_dph")
      throw InputError(rec.source, 0, 0,
                       fmt::format("the Earth rate a true azimuth gives is the FOG axis's "
                                   "(gyro_dph), not {}'s; give the rate every axis sensed with "
                                   "fogdrift campaign --input-rate-dph",
                                   options.target_column));
    info.target = "earth_rate";
    const double horizontal = kEarthRateDph * std::cos(*input.latitude_deg * kDegToRad);
    for (std::size_t i = 0; i < n; ++i) {
      const double table = rec.table_deg ? (*rec.table_deg)[i] : 0.0;
      input_rate[i] = horizontal * std::cos((*input.true_azimuth_deg + table) * kDegToRad);
    }
  } else {
    info.target = "mean";
    const double mean = std::accumulate(gyro.begin(), gyro.end(), 0.0) / static_cast<double>(n);
    std::fill(input_rate.begin(), input_rate.end(), mean);
    warnings.push_back(fmt::format(
        "{}: no reference for {} is known, so the target is the {} less its mean ({:.6g} {}); "
        "the turn-on bias is lost (give it with {})",
        info.file, target.column, target.what(), mean, target.symbol(), target.reference_hint()));
  }
  info.reference =
      std::accumulate(input_rate.begin(), input_rate.end(), 0.0) / static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) gyro[i] -= input_rate[i];
  return gyro;
}

Dataset build_dataset(const std::vector<RecordingInput>& inputs, const DatasetOptions& options) {
  Dataset out;
  out.feature_names = options.features.names();
  out.feature_spec = options.features.to_string();
  for (const auto& input : inputs) {
    GroupInfo info = input.info;
    // Data faster than the model's interval: its features and target in the model's blocks
    // (decimate.hpp); the target is formed at the data's rate first.
    std::size_t k = 1;
    try {
      k = decimation_factor(options.preprocessing, sample_interval_s(input.recording), "rate");
    } catch (const OptionError& e) {
      throw InputError(input.recording.source, 0, 0, e.message());
    }
    const FeatureTable table =
        k > 1 ? compute_features(decimate(input.recording, k), options.features,
                                 options.preprocessing)
              : compute_features(input.recording, options.features, options.preprocessing);
    const auto y = decimate(drift_target(input, options, info, out.warnings), k);
    const auto y_blocks = signal::block_average(y, table.block);
    const std::size_t g = out.groups.size();
    info.warm_rows = table.warm_rows;
    out.groups.push_back(std::move(info));
    out.x.insert(out.x.end(), table.x.begin(), table.x.end());
    out.y.insert(out.y.end(), y_blocks.begin(), y_blocks.end());
    out.time_s.insert(out.time_s.end(), table.time_s.begin(), table.time_s.end());
    out.group.insert(out.group.end(), table.rows, g);
    out.rows += table.rows;
  }
  return out;
}

RecordingInput recording_input(const Campaign& campaign, const CampaignEntry& entry,
                               Recording recording) {
  RecordingInput input;
  input.recording = std::move(recording);
  input.info.file = entry.file;
  input.info.scenario = entry.scenario;
  input.info.role = entry.role;
  input.info.repetition = entry.repetition;
  input.info.initial_temp_degc = entry.initial_temp_degc;
  input.input_rate_dph = entry.input_rate_dph;
  input.references = entry.references;
  input.latitude_deg = campaign.latitude_deg;
  input.true_azimuth_deg = entry.true_azimuth_deg;
  return input;
}

std::vector<RecordingInput> recording_inputs(const Campaign& campaign,
                                             std::span<const Recording> recordings,
                                             std::optional<Role> role, Scenario scenario) {
  if (recordings.size() != campaign.recordings.size())
    throw InputError("campaign", 0, 0,
                     fmt::format("has {} recordings in its manifest and {} given",
                                 campaign.recordings.size(), recordings.size()));
  std::vector<RecordingInput> inputs;
  for (std::size_t i = 0; i < recordings.size(); ++i) {
    const CampaignEntry& e = campaign.recordings[i];
    if (e.scenario == scenario && (!role || e.role == *role))
      inputs.push_back(recording_input(campaign, e, recordings[i]));
  }
  return inputs;
}

std::vector<RecordingInput> read_inputs(const Campaign& campaign, std::optional<Role> role,
                                        Scenario scenario) {
  std::vector<const CampaignEntry*> chosen;
  std::uint64_t file_bytes = 0;
  for (const auto& entry : campaign.recordings) {
    if (entry.scenario != scenario || (role && entry.role != *role)) continue;
    chosen.push_back(&entry);
    std::error_code ec;
    const auto size = std::filesystem::file_size(campaign.path_of(entry), ec);
    if (!ec) file_bytes += size;
  }
  // Checked before the first recording is read, so that a campaign too large for this machine
  // fails at once instead of after minutes of reading (docs/reliability.md, "Size limits").
  const std::uint64_t need = kMemoryPerCsvByte * file_bytes;
  svr::require_memory_beside_reserve(
      need,
      fmt::format("{}: {} {} recording{} ({} of CSV)", (campaign.dir / "campaign.json").string(),
                  chosen.size(), to_string(scenario), chosen.size() == 1 ? "" : "s",
                  format_bytes(file_bytes)),
      "Fewer recordings (a campaign.json that lists a subset), or recordings resampled to a "
      "lower rate (import --rate-hz), would fit.");
  std::vector<RecordingInput> inputs;
  for (const CampaignEntry* entry : chosen)
    inputs.push_back(recording_input(campaign, *entry, read_recording(campaign.path_of(*entry))));
  if (inputs.empty()) {
    throw InputError((campaign.dir / "campaign.json").string(), 0, 0,
                     fmt::format("no {} recordings{} in the campaign", to_string(scenario),
                                 role ? fmt::format(" with role {}", to_string(*role)) : ""));
  }
  return inputs;
}

Dataset build_dataset(const Campaign& campaign, std::optional<Role> role, Scenario scenario,
                      const DatasetOptions& options) {
  return build_dataset(read_inputs(campaign, role, scenario), options);
}

namespace {
const DatasetOptions kDefaultOptions;
}  // namespace

Dataset build_dataset(const std::vector<RecordingInput>& inputs) {
  return build_dataset(inputs, kDefaultOptions);
}

Dataset build_dataset(const Campaign& campaign, std::optional<Role> role, Scenario scenario) {
  return build_dataset(campaign, role, scenario, kDefaultOptions);
}

Standardizer Standardizer::fit(std::span<const double> x, std::size_t cols,
                               std::vector<std::string> names) {
  if (cols == 0 || x.size() % cols != 0 || names.size() != cols) {
    throw std::invalid_argument("Standardizer::fit: shape does not match the names");
  }
  const std::size_t rows = x.size() / cols;
  if (rows < 2) throw OptionError("features", "standardisation needs at least 2 training rows");
  Standardizer s;
  s.names = std::move(names);
  s.mean.assign(cols, 0.0);
  s.scale.assign(cols, 0.0);
  for (std::size_t c = 0; c < cols; ++c) {
    double sum = 0.0;
    for (std::size_t r = 0; r < rows; ++r) sum += x[r * cols + c];
    const double mean = sum / static_cast<double>(rows);
    double ss = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      const double d = x[r * cols + c] - mean;
      ss += d * d;
    }
    const double sd = std::sqrt(ss / static_cast<double>(rows - 1));
    if (!std::isfinite(mean) || !std::isfinite(sd)) {
      throw OptionError("features", fmt::format("column {} has a non-finite value", s.names[c]));
    }
    if (!(sd > 1e-12 * std::max(1.0, std::fabs(mean)))) {
      // The drift's own scaler (drift_dph, drift_NAME_UNIT): the target is what is constant.
      if (s.names[c].rfind("drift", 0) == 0)
        throw OptionError("targets",
                          fmt::format("the drift to learn, {}, is constant ({:.6g}) over the {} "
                                      "training rows: the target column the recordings hold "
                                      "does not change (an all-zero or stuck log?); check it "
                                      "with fogdrift inspect",
                                      s.names[c], mean, rows));
      throw OptionError("features",
                        fmt::format("{} is constant ({:.6g}) over the {} training rows; it carries "
                                    "no information, drop it from the feature spec",
                                    s.names[c], mean, rows));
    }
    s.mean[c] = mean;
    s.scale[c] = sd;
  }
  return s;
}

void Standardizer::apply(std::span<double> x) const {
  const std::size_t cols = mean.size();
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = (x[i] - mean[i % cols]) / scale[i % cols];
}

void Standardizer::invert(std::span<double> x) const {
  const std::size_t cols = mean.size();
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = x[i] * scale[i % cols] + mean[i % cols];
}

}  // namespace fogdrift
