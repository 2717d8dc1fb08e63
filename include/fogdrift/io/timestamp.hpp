// Time stamps as loggers and chamber sheets write them: a date and time (ISO 8601 or a
// spreadsheet's) and a time of day, read into seconds (docs/logs.md; `import --unit
// time_s=datetime|clock`).
#pragma once

#include <optional>
#include <string_view>

namespace fogdrift {

/// Seconds since 1970-01-01 00:00:00 UTC of "YYYY-MM-DD[T| ]HH:MM[:SS[.fraction]][Z|±HH:MM]"
/// (no zone: read as UTC); nothing for any other text.
std::optional<double> parse_datetime(std::string_view text);

/// Seconds since midnight of a time of day "H:MM", "HH:MM", "HH:MM:SS" or "HH:MM:SS.fraction"
/// (hours 0-23); nothing for any other text.
std::optional<double> parse_clock(std::string_view text);

}  // namespace fogdrift
