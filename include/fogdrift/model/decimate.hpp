// A model at any sample rate (docs/compensation.md, "Any sample rate"). A model's features are
// formed at the interval of the recordings it was trained on, dt_m (FeatureOptions::
// sample_interval_s). Data logged faster, every dt_d = dt_m / k with k a whole number, is brought
// to the model's interval before its features are formed: the thermometers are averaged over
// blocks of k samples, and the model runs once per block, so its cost per data sample falls as
// the rate rises instead of growing with the rate (a 121 s rate window is 121 taps at any rate,
// not 12,101 at 100 Hz).
//
// Blocks. After power-on the first sample is a block of its own; then every k samples make one:
//     block 0 = sample 0,   block j ≥ 1 = samples (j − 1)k + 1 … jk,
// each at the time of its last sample, so block j is complete at sample jk and the blocks are
// dt_m apart from the first sample on. Data sample i is compensated with the drift of the last
// block complete at it, block ⌊i / k⌋: causal, and at most dt_m old. The batch path
// (CompensationModel::predict), the StreamingCompensator and the C header form the same blocks
// with the same arithmetic (the sum of k values in order, then one division).
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "fogdrift/features/features.hpp"
#include "fogdrift/io/recording.hpp"

namespace fogdrift {

/// k, the data samples per model sample, for a model trained at `model_dt_s` on data sampled
/// every `data_dt_s`: 1 when model_dt_s is 0 (a model file that does not record it runs at the
/// data's own rate). Throws OptionError naming `option` when the data are slower than the model
/// or dt_m / dt_d is more than 1 % from a whole number, with the fix.
std::size_t decimation_factor(double model_dt_s, double data_dt_s, const std::string& option);

/// The same for a model's preprocessing, with one more refusal: a model file that does not record
/// its interval runs its rate filter at the data's own rate, whose set-up grows with the square
/// of the window in samples; beyond 1001 samples (a 121 s window above about 8 Hz) it is refused,
/// naming the fix (retrain, which records the interval, or resample the data).
std::size_t decimation_factor(const FeatureOptions& model, double data_dt_s,
                              const std::string& option);

/// The data interval the streaming paths run on for a model and a given `data_dt_s` that
/// decimation_factor() accepted as k samples per model interval: the model's own interval / k,
/// so a rate typed with four digits (0.0033 Hz for a 305 s interval) runs exactly as the model
/// was trained; `data_dt_s` itself for a model file that does not record its interval.
double streaming_interval_s(const FeatureOptions& model, double data_dt_s, std::size_t k);

/// The recording in blocks of `k` samples (see the file comment): time of each block's last
/// sample, thermometers (further temp_NAME_degc columns too) and gyro averaged; other columns are
/// not kept. k = 1 returns a copy.
Recording decimate(const Recording& recording, std::size_t k);

/// One column in the same blocks: the mean of each (a target at the data's rate brought to the
/// model's rows, build_dataset).
std::vector<double> decimate(std::span<const double> values, std::size_t k);

/// Sums of the thermometers (in Thermometer order) and the gyro over a block as it fills, shared
/// by the streaming paths; sized once, so adding and clearing allocate nothing.
struct BlockSum {
  std::vector<double> temp;
  double gyro = 0;
  std::size_t count = 0;
  explicit BlockSum(std::size_t thermometers = 3) : temp(thermometers, 0.0) {}
  void add(std::span<const double> temp_degc, double gyro_dph) noexcept {
    for (std::size_t k = 0; k < temp.size(); ++k) temp[k] += temp_degc[k];
    gyro += gyro_dph, ++count;
  }
  void clear() noexcept {
    std::fill(temp.begin(), temp.end(), 0.0);
    gyro = 0, count = 0;
  }
};

}  // namespace fogdrift
