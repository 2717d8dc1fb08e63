#include "fogdrift/train/train_campaign.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/sha256.hpp"
#include "fogdrift/features/features.hpp"

namespace fogdrift {

DatasetOptions recommended_dataset() {
  DatasetOptions o;
  o.denoise_target = false;
  return o;
}

namespace {

// Everything but the provenance's file digests, from the training recordings; `manifest` names
// the campaign in errors.
CampaignTrainResult train_inputs(const std::vector<RecordingInput>& inputs,
                                 const std::string& manifest, const CampaignTrainOptions& options) {
  CampaignTrainResult out;
  DatasetOptions& dataset = out.dataset;
  dataset = options.dataset;
  // Preprocessing fitted to the recordings' sampling, unless the user fixed it.
  const double dt_s = sample_interval_s(inputs.front().recording);
  std::size_t shortest = inputs.front().recording.size();
  for (const auto& in : inputs) shortest = std::min(shortest, in.recording.size());
  const FeatureOptions fitted = preprocessing_for(dt_s, shortest, dataset.preprocessing);
  if (options.auto_features && !options.thermometers.empty()) {
    dataset.features = recommended_feature_spec(options.thermometers);
  } else if (options.auto_features) {
    // The recommended inputs over those of fog, acc1, acc2 every training recording has.
    std::vector<std::string> common = {"fog", "acc1", "acc2"};
    for (const auto& in : inputs) {
      const auto has = thermometers_of(in.recording);
      std::erase_if(common, [&](const std::string& k) {
        return std::find(has.begin(), has.end(), k) == has.end();
      });
    }
    dataset.features = recommended_feature_spec(common);
    if (common.size() < 3)
      out.notes.push_back(
          {"features", fmt::format("{} thermometer{}: features '{}'", common.size(),
                                   common.size() == 1 ? "" : "s", dataset.features.to_string())});
  }
  // Further thermometers the recordings hold and the features do not read, said once.
  std::vector<std::string> unread;
  for (const std::string& name : further_thermometers_of(inputs.front().recording)) {
    const auto& f = dataset.features.further;
    if (std::find(f.begin(), f.end(), name) == f.end()) unread.push_back(thermometer_column(name));
  }
  if (!unread.empty())
    out.notes.push_back(
        {"thermometers",
         fmt::format("{} not read by the features '{}': a further thermometer becomes a "
                     "feature when named, e.g. fog,acc1,acc2,{}, and the model then needs its "
                     "reading wherever it runs (docs/logs.md, \"More thermometers\")",
                     fmt::join(unread, ", "), dataset.features.to_string(),
                     unread.front().substr(5, unread.front().size() - 10))});
  const FeatureOptions defaults;
  const signal::DifferentiatorOptions recommended =
      signal::recommended_rates(dataset.preprocessing.rates.causality);
  dataset.preprocessing.block.block_s = options.block_s.value_or(fitted.block.block_s);
  dataset.preprocessing.rates.window_s = options.rate_window_s.value_or(fitted.rates.window_s);
  dataset.preprocessing.rates.poly_order = options.rate_degree.value_or(fitted.rates.poly_order);
  dataset.preprocessing.sample_interval_s = fitted.sample_interval_s;  // decimate.hpp
  if (!options.block_s && fitted.block.block_s != defaults.block.block_s)
    out.notes.push_back(
        {"block_s", fmt::format("recordings sampled every {:.6g} s: blocks of "
                                "{:.6g} s, not {} s",
                                dt_s, fitted.block.block_s, defaults.block.block_s)});
  // The rate window is said only for a model that reads rates (poly in T alone reads none).
  const std::vector<bool> rates = dataset.features.rate_inputs();
  const bool reads_rates = std::find(rates.begin(), rates.end(), true) != rates.end();
  if (reads_rates && !options.rate_window_s && fitted.rates.window_s != recommended.window_s)
    out.notes.push_back(
        {"window_s", fmt::format("recordings sampled every {:.6g} s, shortest {} samples: "
                                 "temperature rates over {:.6g} s, not {} s",
                                 dt_s, shortest, fitted.rates.window_s, recommended.window_s)});
  out.data = build_dataset(inputs, dataset);
  if (out.data.rows == 0)
    throw InputError(manifest, 0, 0,
                     "no calibration recording has role \"train\"; nothing to train on");
  out.trained = train(out.data, dataset, options.train);
  return out;
}

}  // namespace

CampaignTrainResult train_campaign(const Campaign& campaign, const CampaignTrainOptions& options) {
  validate(options.train);  // an impossible option is refused before the recordings are read
  const std::string manifest = (campaign.dir / "campaign.json").string();
  CampaignTrainResult out =
      train_inputs(read_inputs(campaign, Role::train, Scenario::calibration), manifest, options);
  Provenance& p = out.trained.model.provenance;
  p.files.push_back({"campaign.json", sha256_file_hex(campaign.dir / "campaign.json")});
  for (const GroupInfo& g : out.data.groups)
    p.files.push_back({g.file, sha256_file_hex(campaign.dir / g.file)});
  return out;
}

CampaignTrainResult train_campaign(const Campaign& campaign,
                                   const std::vector<Recording>& recordings,
                                   const CampaignTrainOptions& options) {
  validate(options.train);
  const std::vector<RecordingInput> inputs = recording_inputs(campaign, recordings, Role::train);
  if (inputs.empty())
    throw InputError("campaign", 0, 0, "no calibration recordings with role train in the campaign");
  CampaignTrainResult out = train_inputs(inputs, "campaign", options);
  // The digests of the files these would be: the same as training on the written campaign.
  Provenance& p = out.trained.model.provenance;
  p.files.push_back({"campaign.json", sha256_hex(manifest_json(campaign))});
  for (std::size_t g = 0; g < out.data.groups.size(); ++g)
    p.files.push_back({out.data.groups[g].file, sha256_hex(to_csv(inputs[g].recording))});
  return out;
}

}  // namespace fogdrift
