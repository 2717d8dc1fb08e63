// Time stamps as loggers and chamber sheets write them (timestamp.hpp).
#include "fogdrift/io/timestamp.hpp"

namespace fogdrift {
namespace {

// Days since 1970-01-01 of a proleptic Gregorian date (the civil-from-days inverse).
long long days_from_civil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

}  // namespace

std::optional<double> parse_datetime(std::string_view t) {
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  while (!t.empty() && t.back() == ' ') t.remove_suffix(1);
  auto digits = [&](std::size_t at, std::size_t n) -> std::optional<int> {
    if (at + n > t.size()) return std::nullopt;
    int v = 0;
    for (std::size_t k = at; k < at + n; ++k) {
      if (t[k] < '0' || t[k] > '9') return std::nullopt;
      v = v * 10 + (t[k] - '0');
    }
    return v;
  };
  // Seconds may be left out ("2020-03-07 15:45", a spreadsheet's default).
  const bool with_seconds = t.size() > 16 && t[16] == ':';
  const auto y = digits(0, 4), mo = digits(5, 2), d = digits(8, 2), h = digits(11, 2),
             mi = digits(14, 2), se = with_seconds ? digits(17, 2) : std::optional<int>(0);
  if (!y || !mo || !d || !h || !mi || !se || t[4] != '-' || t[7] != '-' ||
      (t[10] != 'T' && t[10] != ' ') || t[13] != ':')
    return std::nullopt;
  if (*mo < 1 || *mo > 12 || *d < 1 || *d > 31 || *h > 23 || *mi > 59 || *se > 60)
    return std::nullopt;
  std::size_t pos = with_seconds ? 19 : 16;
  double fraction = 0;
  if (with_seconds && pos < t.size() && (t[pos] == '.' || t[pos] == ',')) {
    double scale = 0.1;
    ++pos;
    if (pos >= t.size() || t[pos] < '0' || t[pos] > '9') return std::nullopt;
    while (pos < t.size() && t[pos] >= '0' && t[pos] <= '9') {
      fraction += scale * (t[pos] - '0');
      scale /= 10;
      ++pos;
    }
  }
  long long zone_s = 0;
  if (pos < t.size()) {
    if (t[pos] == 'Z' && pos + 1 == t.size()) {
      ++pos;
    } else if ((t[pos] == '+' || t[pos] == '-') && pos + 6 == t.size() && t[pos + 3] == ':') {
      const auto zh = digits(pos + 1, 2), zm = digits(pos + 4, 2);
      if (!zh || !zm) return std::nullopt;
      zone_s = (t[pos] == '+' ? 1 : -1) * (*zh * 3600LL + *zm * 60LL);
      pos += 6;
    } else {
      return std::nullopt;
    }
  }
  const long long days = days_from_civil(*y, static_cast<unsigned>(*mo), static_cast<unsigned>(*d));
  const long long whole = days * 86400LL + *h * 3600LL + *mi * 60LL + *se - zone_s;
  return static_cast<double>(whole) + fraction;
}

std::optional<double> parse_clock(std::string_view t) {
  while (!t.empty() && t.front() == ' ') t.remove_prefix(1);
  while (!t.empty() && t.back() == ' ') t.remove_suffix(1);
  auto number = [&](std::size_t& at, std::size_t min, std::size_t max) -> std::optional<int> {
    std::size_t n = 0;
    int v = 0;
    while (at < t.size() && n < max && t[at] >= '0' && t[at] <= '9') {
      v = v * 10 + (t[at++] - '0');
      ++n;
    }
    if (n < min) return std::nullopt;
    return v;
  };
  std::size_t pos = 0;
  const auto h = number(pos, 1, 2);
  if (!h || pos >= t.size() || t[pos++] != ':') return std::nullopt;
  const auto mi = number(pos, 2, 2);
  std::optional<int> se = 0;
  double fraction = 0;
  if (mi && pos < t.size() && t[pos] == ':') {
    ++pos;
    se = number(pos, 2, 2);
    if (se && pos < t.size() && (t[pos] == '.' || t[pos] == ',')) {
      ++pos;
      double scale = 0.1;
      if (pos >= t.size()) return std::nullopt;
      while (pos < t.size() && t[pos] >= '0' && t[pos] <= '9') {
        fraction += scale * (t[pos++] - '0');
        scale /= 10;
      }
    }
  }
  if (!mi || !se || pos != t.size() || *h > 23 || *mi > 59 || *se > 60) return std::nullopt;
  return *h * 3600.0 + *mi * 60.0 + *se + fraction;
}

}  // namespace fogdrift
