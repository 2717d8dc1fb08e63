// A compensation model: everything needed to turn a recording into predicted drift, in one
// versioned JSON file (docs/architecture.md, invariants):
//   features  the FeatureSpec text and names, the differentiator and block settings
//   target    how the training target was formed (wavelet denoising settings)
//   scalers   feature and target standardisation fitted on the training rows
//   regressor one of the registry's (regressors.hpp): ε-SVR (support vectors, coefficients, γ,
//              ρ), BP network weights, polynomial, or Gaussian process
//   baselines  the training rows' input ranges and line in T (baselines.hpp), for evaluate
//   provenance method, fitness, hyperparameters, seed, optimizer budget, training files with
//              their SHA-256, fogdrift version. Nothing depends on the clock, so one seed gives
//              one file, byte for byte.
// Numbers are written with the shortest text that reads back to the same double.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "fogdrift/model/baselines.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/model/guard.hpp"
#include "fogdrift/regress/regressors.hpp"

namespace fogdrift {

struct SourceFile {
  std::string path;    ///< as the campaign manifest names it
  std::string sha256;  ///< lowercase hex
};

struct Provenance {
  /// The method's name as train gives it ("ssa-svr", "gp"; train/method.hpp).
  std::string method;
  std::string fitness;       ///< "cv", "train", "validation" (BP's early-stopping set)
  double fitness_value = 0;  ///< RMSE on the standardised target
  std::string cv;            ///< fold description, e.g. "repetition (3 folds)"
  /// Named hyperparameters: C, sigma, gamma, epsilon; hidden, epochs; degree.
  std::vector<std::pair<std::string, double>> hyperparameters;
  std::uint64_t seed = 0;
  std::size_t population = 0, iterations = 0;  ///< optimizer budget (0 when none)
  /// The search, where it is not the method's own (gp searched by "pso" or "gwo"); empty
  /// otherwise, and then not written.
  std::string search;
  std::size_t training_rows = 0;
  std::vector<SourceFile> files;
  std::string fogdrift_version;
};

/// A drift more than this many of the training drift's standard deviations from its mean is no
/// drift a model learned: a model file edited to absurd numbers, or inputs far beyond its
/// training. Every path treats it as a drift that is not a number (docs/reliability.md,
/// "Finite values"): the batch paths stop with an error, the streaming paths (StreamingCompensator,
/// the C header's PREFIX_DRIFT_LIMIT) hold the last good drift or stop the correction, flagged.
inline constexpr double kDriftLimitScales = 1e3;

/// The largest magnitude of a number a model file's scalers may hold (feature means and scales,
/// the drift's mean and scale, the guard's prototypes and radius), and the smallest feature
/// scale: bounds that keep every finite input's standardised value and novelty finite.
inline constexpr double kModelScalerLimit = 1e7;
inline constexpr double kModelSmallestScale = 1e-9;
/// The largest magnitude of any number in a model file's regressor (coefficients, weights,
/// support vectors, kernel widths).
inline constexpr double kModelRegressorLimit = 1e12;

/// One sample's drift as the model predicts it, with the novelty guard's view of it (guard.hpp).
struct DriftPrediction {
  double drift_dph = 0;      ///< f(x), the model's drift, °/h, unguarded
  double novelty = 0;        ///< ν of the sample's inputs; NaN when the model has no guard
  double target_weight = 1;  ///< v for that ν (1 without a guard)
};

/// Drift at every sample of a recording, with the guard's view of each.
struct RecordingPrediction {
  std::vector<double> drift_dph;        ///< the drift to subtract, °/h (guarded when asked)
  std::vector<double> model_drift_dph;  ///< f, the model's drift before the guard, °/h
  std::vector<double> novelty;          ///< ν per sample (NaN without a guard)
  std::vector<double> weight;           ///< w per sample, the share of the correction applied
};

struct CompensationModel {
  DatasetOptions dataset;  ///< features, preprocessing and target settings
  std::vector<std::string> feature_names;
  Standardizer x_scaler;
  Standardizer y_scaler;  ///< one column, "drift_dph"
  AnyRegressor regressor;
  Provenance provenance;
  /// The region of feature space the model was trained on (guard.hpp); empty in files written
  /// before format version 2, which then compensate unguarded.
  NoveltyGuard guard;
  /// What evaluate judges the model against (baselines.hpp); empty in files written before it.
  TrainingBaselines baselines;

  std::size_t inputs() const { return feature_names.size(); }
  /// One row of features in their own units, unguarded; `work` holds inputs() doubles.
  /// `warming`: the row's rates come from the causal differentiator's warm-up, and its novelty
  /// is measured without them (guard.hpp).
  DriftPrediction predict(std::span<const double> features, std::span<double> work,
                          bool warming = false) const;
  /// predict(...).drift_dph.
  double predict_dph(std::span<const double> features, std::span<double> work) const;
  /// ȳ + w·(f − ȳ): a drift f with the share w of its correction applied (guard.hpp).
  double guarded_dph(double drift_dph, double weight) const noexcept;
  /// Drift for every row of a dataset built with this model's DatasetOptions; with `guarded`
  /// the guard's weight runs over each recording's rows in order (GuardFilter).
  std::vector<double> predict_dph(const Dataset& data, bool guarded = true) const;
  /// Drift at every sample of a recording, °/h: the features are computed at the recording's own
  /// rate (blocks of one sample) with the model's differentiator, so the compensated output
  /// keeps the recording's rate. Throws InputError naming the recording when it is too short
  /// for the differentiator or not uniformly sampled. With `guarded` (and a guard in the model)
  /// the correction is reduced where the inputs are novel, causally (guard.hpp).
  RecordingPrediction predict(const Recording& recording, bool guarded = true) const;
  /// predict(recording, guarded).drift_dph.
  std::vector<double> predict_dph(const Recording& recording, bool guarded = true) const;
};

/// Version 2 adds the novelty guard; version 3 a checksum of the content. Versions 1 and 2 still
/// load (version 1 unguarded), without a checksum to verify.
inline constexpr int kCompensationModelVersion = 3;

/// The model file's text. Its last field, "checksum", is "sha256:" and the SHA-256 of the file's
/// text before that field, up to and without the comma that ends the field before it (carriage
/// returns left out). Any tool can check it; docs/tuning.md shows one line of Python.
std::string to_json(const CompensationModel& model);

struct ModelLoadOptions {
  /// Load a file whose content no longer matches its checksum (an edit the user made on
  /// purpose). The fields are still validated.
  bool allow_edited = false;
  /// Load a file of format version 1 or 2, written before model files carried a checksum (and,
  /// version 1, before the novelty guard): nothing shows whether it was edited since.
  bool allow_old_format = false;
};

/// Parses to_json's text; `source` names it in errors. A newer version, another format, a
/// missing or mistyped field, sizes that do not agree, a checksum the content does not match
/// (whatever version the file claims), or a version before 3 without allow_old_format is an
/// InputError naming the field.
CompensationModel compensation_model_from_json(const std::string& text, const std::string& source,
                                               const ModelLoadOptions& options = {});
void save(const CompensationModel& model, const std::filesystem::path& path);  ///< atomic
/// The C99 header for firmware is in c_header.hpp.

CompensationModel load_compensation_model(const std::filesystem::path& path,
                                          const ModelLoadOptions& options = {});

}  // namespace fogdrift
