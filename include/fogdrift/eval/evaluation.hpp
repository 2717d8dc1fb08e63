// A compensation model on test recordings: the paper's Table 2 view with what north-finding
// needs beside it (docs/method.md "Evaluation", docs/field.md). What `fogdrift evaluate` prints
// and what Python's fogdrift.evaluate returns, computed once here.
//
// Per recording: the metrics of metrics.hpp against the dataset's target at the model's block
// rate, the novelty guard's view at the recording's own rate (as compensate and stream see it),
// and optionally the Allan noise terms of the gyro output before and after compensation; the
// model beside its baselines (raw, the recording mean, the training rows' line in T) with the
// harm it does (baseline_comparison.hpp); and how far its inputs lie outside the training ranges,
// in their own units (baselines.hpp). Over all recordings: eval::pool of each.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/eval/allan.hpp"
#include "fogdrift/eval/baseline_comparison.hpp"
#include "fogdrift/eval/metrics.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/model/guard.hpp"
#include "fogdrift/model/model.hpp"

namespace fogdrift::eval {

struct EvaluationOptions {
  bool guarded = true;  ///< apply the novelty guard (false: the model's full correction)
  /// Also the Allan noise terms of each recording, raw and compensated: a gyro's alone (its
  /// terms are °/√h, °/h, °/h/√h); another target gets none.
  bool allan = false;
  /// Keep each recording's rows for figures (RecordingEvaluation::series) and the training
  /// region's prototypes (Evaluation::region_*): what `evaluate --figures` draws.
  bool series = false;
};

/// One recording's rows at the model's block rate, for figures.
struct RecordingSeries {
  std::vector<double> time_s;       ///< since power-on, s
  std::vector<double> target;       ///< y, the drift target (raw less the reference)
  std::vector<double> model;        ///< ŷ, the model's drift as applied (guarded when asked)
  std::vector<double> line;         ///< the line in T's drift; empty without a line
  std::vector<double> temperature;  ///< Evaluation::temperature_input; empty without one
  std::vector<double> rate;         ///< Evaluation::rate_input; empty without one
};

/// Datasheet noise terms of a recording's gyro output before and after compensation, from the
/// overlapping Allan deviation at the recording's own rate, 10 points a decade.
struct AllanComparison {
  NoiseTerms raw, compensated;
};

struct RecordingEvaluation {
  GroupInfo info;               ///< file, initial temperature, repetition, ...
  CompensationMetrics metrics;  ///< at the model's block rate
  NoveltySummary novelty;       ///< at the recording's own rate
  std::optional<AllanComparison> allan;
  BaselineComparison baselines;  ///< at the model's block rate, the dataset's rows
  /// Per input, how far the recording's rows lie outside the training ranges (empty when the
  /// model file does not know them), and the share of rows with any input outside.
  std::vector<InputExtrapolation> extrapolation;
  double outside_training_share = 0;
  std::optional<RecordingSeries> series;  ///< with EvaluationOptions::series
  double duration_s = 0;                  ///< last minus first time stamp
  std::size_t samples = 0;                ///< at the recording's own rate
};

struct Evaluation {
  std::string method;  ///< the model's method ("ssa-svr", ...)
  /// The column the model compensates (target.hpp); the metrics are in its unit.
  std::string target = "gyro_dph";
  bool guarded = true;          ///< as EvaluationOptions::guarded
  bool simulated = false;       ///< the recordings are a campaign `fogdrift simulate` wrote
  std::size_t rows = 0;         ///< dataset rows over all recordings
  CompensationMetrics overall;  ///< eval::pool of the recordings' metrics
  std::vector<RecordingEvaluation> recordings;
  BaselineComparison overall_baselines;  ///< eval::pool of the recordings'
  std::string line_input;                ///< the line's temperature input; empty: no line
  bool ranges_known = false;             ///< the model file holds its training ranges
  /// With EvaluationOptions::series: the temperature and rate inputs the figures draw the
  /// training region in (temperature_input_of, baselines.hpp; the first rate of the same
  /// thermometer; empty when the model has none), and the guard's prototypes in those inputs'
  /// own units.
  std::string temperature_input, rate_input;
  std::vector<double> region_temperature, region_rate;
  /// The recordings the model harms (file names), and those it is no better than its
  /// baselines on.
  std::vector<std::string> harmed, no_better;
  std::vector<std::string> warnings;  ///< the dataset builder's
};

/// Evaluates `model` on recordings. Throws InputError naming `model_label` when the model's
/// features differ from those its feature spec gives for this data (a thermometer missing).
Evaluation evaluate(const CompensationModel& model, const std::vector<RecordingInput>& inputs,
                    const EvaluationOptions& options = {},
                    const std::string& model_label = "model");

/// Evaluates `model` on the campaign's calibration recordings with role "test".
Evaluation evaluate(const CompensationModel& model, const Campaign& campaign,
                    const EvaluationOptions& options = {},
                    const std::string& model_label = "model");

/// The overall verdict: "harms" (some recording, or all pooled, made worse), "no better than
/// its baselines", or "beats its baselines" (baseline_comparison.hpp).
std::string verdict(const Evaluation& evaluation);

/// A harm's sentence with "{unit}" replaced by the target's unit symbol.
std::string with_unit(std::string_view text, std::string_view symbol);

/// The JSON `fogdrift evaluate --json` prints: "model" (`model_label`), "method", "source",
/// "overall", "baselines" (the pooled comparison, its "harms" and "no_better_than"), "verdict"
/// ("harms", "no better than its baselines" or "beats its baselines"), "harmed" and "no_better"
/// (file names), "guard", "recordings" (each with its metrics, novelty shares, "baselines",
/// "extrapolation" and, when computed, "allan"), "warnings"; metric keys name their unit: …_dph for
/// a gyro, …_g for an accelerometer, …_ppm for a scale-factor channel.
std::string to_json(const Evaluation& evaluation, const std::string& model_label,
                    const std::string& source);

}  // namespace fogdrift::eval
