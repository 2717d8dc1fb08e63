#include "fogdrift/signal/wavelet.hpp"

#include <algorithm>
#include <array>
#include <span>

#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

constexpr std::size_t kMaxFilterLength = 40;  // db20 and sym20

struct FilterEntry {
  const char* name;
  const char* family;
  int order;
  std::size_t length;
  std::array<double, kMaxFilterLength> dec_lo;  // the first `length` taps
};

constexpr FilterEntry kTable[] = {
#include "wavelet_filters.inc"
};

std::span<const FilterEntry> table() {
  return kTable;
}

}  // namespace

const std::vector<std::string>& wavelet_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& entry : table()) out.emplace_back(entry.name);
    return out;
  }();
  return names;
}

Wavelet wavelet(std::string_view name) {
  if (name == "haar") name = "db1";
  const auto& entries = table();
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const FilterEntry& e) { return name == e.name; });
  if (it == entries.end()) {
    throw OptionError("wavelet", "'" + std::string(name) +
                                     "' is not a known wavelet; use haar, db1..db20, sym2..sym20 "
                                     "or coif1..coif5");
  }
  Wavelet w;
  w.name = it->name;
  w.family = it->family;
  w.order = it->order;
  w.dec_lo.assign(it->dec_lo.begin(), it->dec_lo.begin() + static_cast<std::ptrdiff_t>(it->length));
  const std::size_t n = w.dec_lo.size();
  w.rec_lo.assign(w.dec_lo.rbegin(), w.dec_lo.rend());
  w.dec_hi.resize(n);
  for (std::size_t k = 0; k < n; ++k) w.dec_hi[k] = (k % 2 == 0) ? -w.rec_lo[k] : w.rec_lo[k];
  w.rec_hi.assign(w.dec_hi.rbegin(), w.dec_hi.rend());
  return w;
}

}  // namespace fogdrift::signal
