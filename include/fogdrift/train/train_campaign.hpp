// Training on a campaign, as `fogdrift train` and the Python package's fogdrift.train do it
// (docs/tuning.md): read the calibration recordings whose role is "train", choose the features
// and preprocessing the recordings allow, build the dataset, train, and record every data
// file's SHA-256 in the model's provenance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fogdrift/io/campaign.hpp"
#include "fogdrift/train/train.hpp"

namespace fogdrift {

/// The dataset settings `train` starts from: DatasetOptions' (the paper's) but for the target,
/// the gyro's block means without wavelet denoising. The denoiser's coarsest approximation
/// smooths the first minutes of a start-up, where a four-position north-finding is most
/// sensitive, and the model learnt that smoothed course; the SVR's own fit averages the noise
/// (docs/field.md, "The target without denoising").
DatasetOptions recommended_dataset();

struct CampaignTrainOptions {
  TrainOptions train;
  /// Preprocessing and target settings. Its features are used as given unless auto_features;
  /// its block, rate window and degree only where block_s, rate_window_s, rate_degree say so.
  DatasetOptions dataset = recommended_dataset();
  /// The recommended inputs over the thermometers every training recording has (features.hpp,
  /// recommended_feature_spec: the paper's and their rates through a lag) instead of
  /// dataset.features.
  bool auto_features = true;
  /// With auto_features, the thermometers the features read (fog, acc1, acc2 or the NAME of a
  /// further column temp_NAME_degc); empty: those of fog, acc1, acc2 every training recording
  /// has. A further thermometer is a feature only when named here or in the spec: a chamber or
  /// test-house thermocouple must not become an input the instrument cannot read in the field
  /// (docs/logs.md, "More thermometers").
  std::vector<std::string> thermometers;
  /// Averaging block, s; unset: fitted to the recordings' sampling (preprocessing_for).
  std::optional<double> block_s;
  /// Temperature-rate window, s; unset: the recommended window for dataset's causality
  /// (signal::recommended_rates) fitted to the sampling and the shortest recording.
  std::optional<double> rate_window_s;
  /// Degree of the differentiator's polynomial, 1..4; unset: the recommended degree for
  /// dataset's causality (2 centred, 1 causal).
  std::optional<int> rate_degree;
};

/// A choice made for the user that differs from the defaults, for the front end to report:
/// `field` is the option that would change it ("features", "block_s", "window_s").
struct CampaignNote {
  std::string field;
  std::string text;
};

struct CampaignTrainResult {
  TrainResult trained;     ///< the model, its provenance holding every data file's SHA-256
  Dataset data;            ///< the training rows, their recordings and any warnings
  DatasetOptions dataset;  ///< the settings used, with everything "auto" resolved
  std::vector<CampaignNote> notes;
};

/// Trains on `campaign`'s training recordings. Throws InputError (no training recording, a bad
/// file) and OptionError (naming the library's field) as the parts it calls do.
CampaignTrainResult train_campaign(const Campaign& campaign, const CampaignTrainOptions& options);

/// The same on a campaign held in memory: `recordings[i]` is the data of
/// `campaign.recordings[i]` (campaign_from_json). The provenance records the digests of the
/// files they would be written as (manifest_json, to_csv), so a campaign trained in memory and
/// the same campaign written and trained give the same model bytes.
CampaignTrainResult train_campaign(const Campaign& campaign,
                                   const std::vector<Recording>& recordings,
                                   const CampaignTrainOptions& options);

}  // namespace fogdrift
