// Joining a second log into a recording by time (docs/logs.md, "Temperatures from another file").
//
// Test houses log the chamber and the instrument on different machines: the gyro and one
// thermometer in the instrument's log, the thermocouples in a sheet kept by hand or by the
// chamber's controller. Both are imported first (the sheet with import --partial), so both have
// time_s in seconds. A row of the recording at time t takes the log's values at t − offset_s:
//
//   t_recording = t_log + offset_s
//
// The offset is given, or estimated from a column both files hold (the same quantity seen by two
// sensors, such as the unit's own thermometer and a thermocouple on its case): the offset that
// minimises the variance of their difference over the overlap. The variance, not the mean square,
// so that a constant difference between the two sensors does not bias the offset; the
// consequence is that a column changing at a constant rate cannot fix an offset (a shift in time
// is then a constant), and the summary says how sharply the minimum is defined.
//
// Values are taken by linear interpolation between the log samples either side (a bracket no
// longer than max_step_s) or from the nearest log sample (no farther than max_age_s). Rows before
// the first joinable one and after the last are dropped; a run of rows inside that cannot be
// joined splits the recording, as a long gap does on import.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/io/recording.hpp"

namespace fogdrift {

enum class JoinMethod { linear, nearest };

std::string_view to_string(JoinMethod method);  ///< "linear", "nearest"
/// Parses "linear" or "nearest"; throws OptionError("method", ...) otherwise.
JoinMethod join_method_from_string(std::string_view text);

/// The offset estimated from a column both files hold.
struct OffsetSearch {
  std::string recording_column;  ///< a numeric column of the recording
  std::string log_column;        ///< the same quantity in the log
  /// Offsets searched: offset_s ± range_s; 0: every offset that leaves an overlap of at least
  /// half the shorter of the two files.
  double range_s = 0;
};

/// The rules an estimated alignment must pass (docs/logs.md, "The evidence").
/// The STD of the difference of the two columns at the estimate, at most this share of the
/// recording column's STD over the rows compared: the two move together.
inline constexpr double kJoinResidualShare = 0.5;
/// The mean difference (the constant gap between the two sensors), at most this multiple of the
/// larger of the two columns' ranges over the rows compared: the same quantity, not two.
inline constexpr double kJoinGapShare = 1.0;
/// The half-width of the minimum, at most this share of the time the two columns were compared
/// over (and the minimum not at an end of the searched range): the column fixes the offset.
inline constexpr double kJoinSharpShare = 0.05;

struct JoinOptions {
  /// The log's columns to bring in; empty: every numeric column but time_s and those the
  /// recording has already. A column named here that the recording has is an error unless
  /// `replace` (which, with no columns named, also takes the log's value of those).
  std::vector<std::string> columns;
  bool replace = false;
  JoinMethod method = JoinMethod::linear;
  /// t_recording = t_log + offset_s, given by the user; the centre of the searches when
  /// `estimates` are set (0 when not given). Neither given nor estimated: an OptionError, since 0
  /// is no default for two clocks nothing ties together.
  std::optional<double> offset_s;
  /// Column pairs to estimate the offset from; with several, each is judged and they must agree,
  /// and the offset applied is their mean weighted by 1 / half-width².
  std::vector<OffsetSearch> estimates;
  /// Write the join even when the evidence fails (JoinEvidence::failures say why).
  bool force = false;
  /// linear: the longest step between two log samples interpolated across, s, > 0; unset
  /// (auto): 1.5 × the log's median step.
  std::optional<double> max_step_s;
  /// nearest: the farthest a log sample may be from the row, s, > 0; unset (auto): the log's
  /// median step.
  std::optional<double> max_age_s;
};

struct OffsetEstimate {
  double offset_s = 0;  ///< the estimate
  double searched_from_s = 0, searched_to_s = 0;
  bool at_edge = false;              ///< the minimum lies at an end of the searched range
  double residual_std = 0;           ///< STD of the difference at the estimate, the column's unit
  double centre_s = 0;               ///< the offset given (JoinOptions::offset_s)
  double residual_std_at_start = 0;  ///< the same at centre_s; NaN where the files do not overlap
  /// Half the width of the offsets whose residual variance is at most twice the minimum, s: how
  /// sharply the column fixes the offset.
  double half_width_s = 0;
  std::size_t rows_compared = 0;
  double compared_from_s = 0, compared_to_s = 0;  ///< the recording's rows compared, first .. last
  /// At the estimate, over the rows compared: the mean of (recording − log), the constant gap
  /// between the two sensors; the recording column's STD; both columns' ranges (max − min).
  double mean_difference = 0;
  double recording_std = 0;
  double recording_range = 0, log_range = 0;
};

/// One column pair's estimate and what it shows.
struct ColumnMatch {
  std::string recording_column, log_column;
  OffsetEstimate estimate;
  /// The rules this pair breaks, each a sentence with the numbers; empty when it passes.
  std::vector<std::string> failures;
};

/// What supports the offset a join applies (see the file comment).
struct JoinEvidence {
  bool given = false;        ///< the user gave the offset and asked for no estimate
  double offset_s = 0;       ///< the offset to apply
  double uncertainty_s = 0;  ///< ± the sharpest estimate's half-width; 0 when given
  std::vector<ColumnMatch> matches;
  /// Every rule broken (the pairs' and their disagreement); empty when the evidence passes.
  std::vector<std::string> failures;
  bool founded() const { return failures.empty(); }
};

struct JoinSummary {
  JoinMethod method = JoinMethod::linear;
  double offset_s = 0;  ///< the offset applied
  JoinEvidence evidence;
  bool forced = false;                  ///< written with JoinOptions::force against failed evidence
  double limit_s = 0;                   ///< max_step_s (linear) or max_age_s (nearest) as applied
  std::vector<std::string> columns;     ///< the columns brought in
  std::vector<std::string> skipped;     ///< the log's text columns, not brought in
  std::vector<std::string> kept;        ///< columns both hold: the recording's kept (no replace)
  double log_from_s = 0, log_to_s = 0;  ///< the log's span on the recording's time axis
  std::size_t rows_in = 0;              ///< the recording's rows
  std::size_t rows_out = 0;             ///< rows written, over all segments
  std::size_t dropped_before = 0;       ///< rows before the first joinable one
  std::size_t dropped_after = 0;        ///< rows after the last joinable one
  std::size_t dropped_inside = 0;       ///< rows inside that could not be joined (splits)
  std::size_t log_rows_used = 0;        ///< log samples within the recording's span
};

struct JoinResult {
  std::vector<Recording> segments;  ///< in time order; one unless the log has long gaps
  JoinSummary summary;
};

/// The offset and its evidence: the given offset, or every estimate judged by the rules above.
/// Throws OptionError naming offset_s when neither is given, estimate for a column either file
/// lacks, and InputError naming the files when an estimate finds no overlap.
JoinEvidence judge_alignment(const Recording& recording, const Recording& log,
                             const JoinOptions& options);

/// The recording with the log's columns joined in (see the file comment), at the offset
/// judge_alignment() gives. Throws OptionError naming columns, method, offset_s, estimate,
/// max_step_s or max_age_s for an impossible option, and InputError naming the files when no row
/// can be joined, an estimate has no overlap, or the evidence fails without options.force.
JoinResult join(const Recording& recording, const Recording& log, const JoinOptions& options);
/// The same with the evidence already judged (what the command line prints before it joins).
JoinResult join(const Recording& recording, const Recording& log, const JoinOptions& options,
                const JoinEvidence& evidence);

/// One column pair's offset alone, searched about centre_s.
OffsetEstimate estimate_offset(const Recording& recording, const Recording& log,
                               const OffsetSearch& search, double centre_s);

}  // namespace fogdrift
