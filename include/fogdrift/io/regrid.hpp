// Putting a logger's samples on a uniform time grid, which the features need (docs/logs.md).
//
// Real loggers stamp samples with jitter (a 50 Hz logger with millisecond stamps steps by 19, 20
// and 21 ms), log in bursts (250 samples at 50 Hz every five minutes), and drop samples. The
// grid is t_k = k·h with h = step_s, so every output time is a whole multiple of h.
//
// Two ways of filling it:
//   mean    bin k holds the samples with t in [t_k − h/2, t_k + h/2); its value is their mean, a
//           box filter that also keeps a faster input from aliasing. A bin with no sample is a gap.
//   linear  the value at t_k is interpolated linearly between the samples either side; for an
//           input about as fast as the grid or slower, where a bin may hold no sample by jitter
//           alone. Input steps longer than 1.5 × the median step are gaps.
//   automatic (the default) takes mean when the input's median step is at most h/2, else linear.
// A gap no longer than max_gap_s is bridged by linear interpolation between the samples (or bins)
// either side, and reported; a longer one splits the recording into segments, since a bridge
// would invent minutes of drift the instrument never logged. Times keep their origin (seconds
// since power-on), so a later segment starts where it was logged.
//
// gyro_dph, the thermometers, accel_*_g, chamber_degc and every extra column that holds numbers
// only (another gyro axis, an accelerometer, a thermometer of the unit's own) are averaged or
// interpolated; table_deg, a position rather than a signal, takes the value of the sample nearest
// t_k. Extra columns with text are not carried over (the summary lists them).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift {

enum class RegridMethod { automatic, mean, linear };

std::string_view to_string(RegridMethod method);  ///< "auto", "mean", "linear"
/// Parses "auto", "mean" or "linear"; throws OptionError("method", ...) otherwise.
RegridMethod regrid_method_from_string(std::string_view text);

struct RegridOptions {
  /// Grid step h, s, in [0.001, 1e6] (1 / the output rate).
  double step_s = 1.0;
  RegridMethod method = RegridMethod::automatic;
  /// Longest gap bridged by interpolation, s, >= 0; a longer gap splits the recording.
  /// Negative means the default: 10 grid steps.
  double max_gap_s = -1.0;
  /// Segments with fewer grid samples than this are dropped (and counted), >= 2.
  std::size_t min_segment_samples = 2;
};

/// One stretch of time with no sample (linear) or no sample in whole bins (mean).
struct RegridGap {
  double start_s = 0;      ///< time of the last sample before the gap, s
  double end_s = 0;        ///< time of the first sample after it, s
  bool bridged = false;    ///< interpolated across (true) or split at (false)
  std::size_t filled = 0;  ///< grid samples interpolated inside it (0 when split)
  double length_s() const { return end_s - start_s; }
};

struct RegridSummary {
  RegridMethod method = RegridMethod::mean;  ///< the method used (never automatic)
  double step_s = 0;
  double max_gap_s = 0;  ///< the limit applied, s
  std::size_t input_samples = 0;
  double input_median_step_s = 0;  ///< s
  double input_max_jitter = 0;     ///< largest |step / median − 1| over non-gap steps
  std::size_t output_samples = 0;  ///< over all kept segments
  std::vector<RegridGap> gaps;
  std::size_t dropped_segments = 0;          ///< shorter than min_segment_samples
  std::vector<std::string> dropped_columns;  ///< extra columns with text, not carried over
};

struct RegridResult {
  std::vector<Recording> segments;  ///< in time order; one when nothing was split
  RegridSummary summary;
};

/// The recording on the grid (see the file comment). Throws OptionError naming step_s, max_gap_s
/// or min_segment_samples for an impossible option, and InputError naming the recording when no
/// segment of at least min_segment_samples remains.
RegridResult regrid(const Recording& recording, const RegridOptions& options);

/// Whether `recording` is uniformly sampled as the features need it: every step within 1 % of
/// the median step. (features.hpp's sample_interval_s() enforces the same rule.)
bool is_uniformly_sampled(const Recording& recording);

}  // namespace fogdrift
