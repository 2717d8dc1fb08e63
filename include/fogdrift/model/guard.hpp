// The novelty guard (docs/field.md): a model records the region of feature space it was trained
// on, and where a sample's inputs lie outside it — a start-up unlike any the calibration showed —
// its correction is reduced, so that a model that is extrapolating cannot make a start-up worse
// than no compensation.
//
// Region. The training rows, standardised with the model's feature scaler, are summarised by K
// prototypes chosen by farthest-point sampling (Gonzalez 1985: start at the first row, then
// repeatedly add the row farthest from the prototypes so far). Deterministic, O(N·K·d).
//
// Unit. How far is far? A start-up at a calibration temperature the model was not trained on
// lies between the trajectories of its neighbours, and should count as familiar. So the unit r
// is set by the training data's own spacing: for each training row, the distance to the nearest
// row of another calibration temperature (its label); the 90th percentile of those distances
// (over at most 4000 evenly spread rows). Likewise a start-up between two start-up conditions
// the calibration held at one temperature (its repetitions, when each repetition starts up
// another way: docs/field.md) should count as familiar: the 90th percentile of the distance to
// the nearest row of the same temperature and another condition. r is the larger of the two,
// and at least the prototypes' cover radius (the largest distance of a training row to its
// nearest prototype). Repetitions that start up alike (the paper's protocol) lie close together
// and leave r at the temperatures' spacing. Without two labels, r is the cover radius (the
// conditions then widen nothing: a model calibrated at one temperature knows nothing of another).
//
// Novelty of a sample with standardised inputs z:   ν = min_p ‖z − p‖ / r.
// A start-up like calibration's at a new temperature has ν of about 1 or less.
//
// Policy. The target weight of the model's correction at a sample
//     v = 1                                   ν ≤ full_at
//     v = (zero_at − ν) / (zero_at − full_at)  between
//     v = 0                                   ν ≥ zero_at
// and the weight applied, causally over a start-up (GuardFilter): it falls to v at once and
// rises towards it by at most Δt / recover_s per sample (not at all when recover_s = 0),
//     w_t = min(v_t, w_{t−1} + Δt / recover_s),   w before the first sample = 1,
// so that a model is not switched on and off from sample to sample: a weight that changes
// between the positions of a four-position finding is itself a drift (docs/field.md). The
// guarded drift is  ȳ + w·(f(x) − ȳ),  with ȳ the training target's mean (the turn-on bias,
// which a north-finding and a compensated STD do not see). At w = 0 the output is the
// uncompensated gyro shifted by a constant. Inputs that are not numbers are near no prototype
// (ν = ∞, or NaN) and so v = 0: the correction stops, latched like any other, rather than
// passing a NaN on.
//
// Warm-up (docs/field.md, "The guard at power-on"). A causal differentiator's first W − 1 rates
// come from fits to fewer samples: at power-on they are noise, ν of 10-50 on a start-up like
// the calibration's, and the latch would switch the model off for the whole start-up. While the
// rate window fills, ν is therefore measured over the inputs that read no rate (temperatures,
// gradients, time):  ν_warm = min_p ‖z_S − p_S‖ / r,  S = those inputs (`warmup_inputs`).
// Novel temperatures or gradients still reduce the correction from the first sample; novel
// rates do so from the first full window on. ν_warm ≤ ν, with the same unit r.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace fogdrift {

/// How a NoveltyGuard is fitted and where its policy acts; stored in the model.
struct GuardSettings {
  /// Prototypes K kept to describe the training region, 1 … 4096. More describe it more closely
  /// (smaller r) at K·d multiply-adds per sample.
  std::size_t prototypes = 256;
  /// ν up to which the correction is applied in full, > 0 (docs/field.md: chosen by measurement).
  double full_at = 1.5;
  /// ν at and beyond which no correction is applied, > full_at.
  double zero_at = 2.5;
  /// Time for the weight to recover from 0 to 1 once the inputs are familiar again, s, ≥ 0.
  /// 0 (the default): never within a start-up; the weight is latched at its lowest until the
  /// next power-on (docs/field.md: a start-up seen to be novel stays novel, since its drift
  /// depends on a history the model has not seen, even when its inputs later look familiar).
  double recover_s = 0.0;
};

/// Throws OptionError naming the field (guard.prototypes, guard.full_at, guard.zero_at,
/// guard.recover_s) and the rule.
void validate(const GuardSettings& settings);

struct NoveltyGuard {
  GuardSettings settings;
  std::size_t dims = 0;
  std::vector<double> prototypes;  ///< K × dims, row-major, standardised units
  double radius = 0;               ///< the unit r of ν, standardised units (> 0)
  /// Per input, 1 where ν counts it during the differentiator's warm-up: the inputs that read no
  /// rate. Derived from the model's features (set_warmup_inputs), not stored in the model file.
  std::vector<unsigned char> warmup_inputs;

  /// Fits the region to `z`, rows × dims standardised training inputs (rows ≥ 1); `labels`
  /// (one per row, e.g. the index of its calibration temperature, or empty) and `conditions`
  /// (one per row, e.g. its repetition, or empty) set the unit r.
  static NoveltyGuard fit(std::span<const double> z, std::size_t dims,
                          std::span<const std::size_t> labels = {},
                          std::span<const std::size_t> conditions = {},
                          const GuardSettings& settings = {});
  bool empty() const { return prototypes.empty(); }
  std::size_t size() const { return dims ? prototypes.size() / dims : 0; }
  /// ν of one standardised input row (dims values); during the warm-up (`warming`) ν_warm, over
  /// `warmup_inputs` only (all inputs when that is empty).
  double novelty(std::span<const double> z, bool warming = false) const noexcept;
  /// Marks the inputs ν_warm counts: `reads_rate[k]` true for an input that reads a rate.
  void set_warmup_inputs(const std::vector<bool>& reads_rate);
  /// v for a novelty ν (the policy above); 0 for NaN.
  double target_weight(double novelty) const noexcept;
};

/// The applied weight w over one start-up, sample by sample (the policy above). Allocates
/// nothing; the batch path, the streaming compensator and the C header run the same recursion.
class GuardFilter {
 public:
  /// The weight at a sample at `time_s` with target weight `v`.
  double update(double time_s, double v, double recover_s) noexcept;
  /// As at power-on: w = 1, no previous sample.
  void reset() noexcept { weight_ = 1.0, started_ = false; }

 private:
  double weight_ = 1.0, last_time_s_ = 0.0;
  bool started_ = false;
};

/// What the guard saw over a run of samples, for a summary line.
struct NoveltySummary {
  std::size_t samples = 0;
  std::size_t outside = 0;  ///< samples with ν > 1, outside the training region
  std::size_t reduced = 0;  ///< samples whose correction was reduced (w < 1)
  double max_novelty = 0;   ///< NaN when the model has no guard
  /// "novelty: 12.0 % of 1800 samples outside the training region (max 3.21), correction
  /// reduced on 4.0 %" or "novelty: the model has no guard (format version 1)".
  std::string line() const;
};

/// Counts over per-sample novelties and weights (RecordingPrediction's).
NoveltySummary summarize_novelty(std::span<const double> novelty, std::span<const double> weight);

}  // namespace fogdrift
