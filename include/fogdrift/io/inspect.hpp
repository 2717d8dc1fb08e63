// What `fogdrift inspect` reports about a recording: duration, sampling, gaps and ranges.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift {

struct ColumnRange {
  std::string name;
  double min = 0, max = 0, mean = 0, std = 0;  ///< in the column's unit; std is the sample STD
};

struct RecordingSummary {
  std::size_t samples = 0;
  double start_s = 0, end_s = 0, duration_s = 0;
  double sample_interval_s = 0;  ///< median time step, s
  double sample_rate_hz = 0;     ///< 1 / median step
  std::size_t gaps = 0;          ///< steps longer than 1.5 × the median
  double longest_gap_s = 0;      ///< longest step, s
  /// A bursty log: at least two gaps, and the bursts they separate start at regular times (every
  /// start-to-start period within 10 % of a whole number of their median: a lost burst is still a
  /// burst log). Then the number of bursts and that median period, s; else 0 and 0.
  std::size_t bursts = 0;
  double burst_period_s = 0;
  bool uniformly_sampled = false;  ///< every step within 1 % of the median (train needs it)
  /// Every numeric column but time_s with values: the known ones, then the numeric further
  /// columns.
  std::vector<ColumnRange> columns;
  std::vector<std::string> extra_columns;  ///< the further columns, numeric or not
  bool partial = false;                    ///< a log to join (Recording::partial)
  std::vector<std::string> missing;        ///< what a log to join lacks of a recording
};

/// What `fogdrift inspect` is asked (inspect_option_table.hpp).
struct InspectOptions {
  /// The file may be a log to join (a chamber sheet imported with --partial): read it as one
  /// (read_log), without the gyro or the FOG thermometer and with times before power-on.
  bool log = false;
};

/// A recording, or a log to join (a chamber sheet: span, step, columns and ranges).
RecordingSummary summarize(const Recording& recording);

/// Mean and sample standard deviation (n − 1) of `values`; 0 for the STD of fewer than 2 values.
ColumnRange column_range(const std::string& name, const std::vector<double>& values);

}  // namespace fogdrift
