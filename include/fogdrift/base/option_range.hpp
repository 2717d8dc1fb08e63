// The values an option allows (option_table.hpp): bounds on a number, which the option's parser
// checks in every front end, and a note for what bounds cannot say. The docs' "allowed" column,
// --help and Python's docstrings show text(), so what is documented is what is checked.
//
//   at_least(0)                        "≥ 0"
//   above(0).at_most(100)              "> 0, ≤ 100"
//   between(1, 1000)                   "1 … 1000"
//   at_least(2).with("ssa-svr ≥ 5")    "≥ 2; ssa-svr ≥ 5"
//   "> {c_min}"                        a note alone: a rule between options, which the library's
//                                      validate() checks
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace fogdrift {

struct OptionRange {
  std::optional<double> min, max;
  bool min_open = false;  ///< min itself excluded: "> min"
  bool max_open = false;  ///< max itself excluded: "< max"
  /// What the bounds cannot say: a choice's names, a rule between options ("> {c_min}"), a remark
  /// ("0 runs every iteration").
  std::string note;

  OptionRange() = default;
  /// A note alone, without bounds.
  OptionRange(const char* text) : note(text) {}             // NOLINT(google-explicit-constructor)
  OptionRange(std::string text) : note(std::move(text)) {}  // NOLINT(google-explicit-constructor)

  /// The same range with an upper bound: ≤ max, or < max.
  OptionRange at_most(double max) const;
  OptionRange below(double max) const;
  /// The same range with a note after its bounds.
  OptionRange with(std::string text) const;

  bool has_bounds() const { return min || max; }
  /// Whether `value` lies within the bounds (any value without bounds; never a NaN with them).
  bool contains(double value) const;
  /// The bounds as a user reads them: "≥ 0", "> 0, ≤ 100", "1 … 1000"; "" without bounds.
  std::string bounds_text() const;
  /// The bounds as a message says them: "between 1 and 1000" where bounds_text() is "1 … 1000",
  /// else bounds_text().
  std::string bounds_phrase() const;
  /// The bounds, then the note after "; ", or either alone.
  std::string text() const;
};

/// ≥ min, > min, and min … max (both included).
OptionRange at_least(double min);
OptionRange above(double min);
OptionRange between(double min, double max);

}  // namespace fogdrift
