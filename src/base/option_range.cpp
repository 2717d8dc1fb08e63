// Bounds of an option's values and their text (option_range.hpp).
#include "fogdrift/base/option_range.hpp"

#include <fmt/format.h>

#include <cmath>

namespace fogdrift {
namespace {

/// A bound as it is written: the shortest text that reads back to it, a power of ten from a
/// million up as 1e6.
std::string bound_text(double v) {
  std::string s = fmt::format("{}", v);
  const std::size_t zeros = s.size() - s.find_last_not_of('0') - 1;
  if (s.find_first_of(".e") == std::string::npos && zeros >= 6)
    s = s.substr(0, s.size() - zeros) + "e" + std::to_string(zeros);
  return s;
}

}  // namespace

OptionRange OptionRange::at_most(double bound) const {
  OptionRange r = *this;
  r.max = bound;
  r.max_open = false;
  return r;
}

OptionRange OptionRange::below(double bound) const {
  OptionRange r = *this;
  r.max = bound;
  r.max_open = true;
  return r;
}

OptionRange OptionRange::with(std::string text) const {
  OptionRange r = *this;
  r.note = std::move(text);
  return r;
}

bool OptionRange::contains(double value) const {
  if (!has_bounds()) return true;
  if (std::isnan(value)) return false;
  if (min && (min_open ? !(value > *min) : !(value >= *min))) return false;
  if (max && (max_open ? !(value < *max) : !(value <= *max))) return false;
  return true;
}

std::string OptionRange::bounds_text() const {
  if (min && max && !min_open && !max_open)
    return fmt::format("{} … {}", bound_text(*min), bound_text(*max));
  std::string out;
  if (min) out = fmt::format("{} {}", min_open ? ">" : "≥", bound_text(*min));
  if (max)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", max_open ? "<" : "≤", bound_text(*max));
  return out;
}

std::string OptionRange::bounds_phrase() const {
  if (min && max && !min_open && !max_open)
    return fmt::format("between {} and {}", bound_text(*min), bound_text(*max));
  return bounds_text();
}

std::string OptionRange::text() const {
  const std::string bounds = bounds_text();
  if (bounds.empty()) return note;
  return note.empty() ? bounds : bounds + "; " + note;
}

OptionRange at_least(double min) {
  OptionRange r;
  r.min = min;
  return r;
}

OptionRange above(double min) {
  OptionRange r;
  r.min = min;
  r.min_open = true;
  return r;
}

OptionRange between(double min, double max) {
  return at_least(min).at_most(max);
}

}  // namespace fogdrift
