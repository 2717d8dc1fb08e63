// A model beside what needs no model (baseline_comparison.hpp).
#include "fogdrift/eval/baseline_comparison.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <tuple>

namespace fogdrift::eval {
namespace {

/// Of e = y − p (p empty: 0): √mean e², and the sample STD of e, as Table 2's STDs (metrics.hpp).
std::pair<double, double> rmse_and_std(std::span<const double> y, std::span<const double> p) {
  double mean = 0;
  for (std::size_t i = 0; i < y.size(); ++i) mean += y[i] - (p.empty() ? 0.0 : p[i]);
  const double n = static_cast<double>(y.size());
  mean /= n;
  double sum2 = 0, centred = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double e = y[i] - (p.empty() ? 0.0 : p[i]);
    sum2 += e * e;
    centred += (e - mean) * (e - mean);
  }
  return {std::sqrt(sum2 / n), y.size() > 1 ? std::sqrt(centred / (n - 1)) : 0.0};
}

/// Two figures of a rule broken, with 4 significant digits or as many more (up to 12) as it
/// takes to print them apart: a harm of a millionth must not read "0.04947 against 0.04947".
std::pair<std::string, std::string> apart(double worse, double better) {
  int digits = 4;
  while (digits < 12 &&
         fmt::format("{:.{}g}", worse, digits) == fmt::format("{:.{}g}", better, digits))
    ++digits;
  return {fmt::format("{:.{}g}", worse, digits), fmt::format("{:.{}g}", better, digits)};
}

/// The rules of the file comment, on figures already computed.
void judge(BaselineComparison& c, const std::string& line_input) {
  c.harms.clear();
  c.no_better_than.clear();
  if (c.model_rmse > c.raw_rmse) {
    const auto [model, raw] = apart(c.model_rmse, c.raw_rmse);
    c.harms.push_back(fmt::format("worse than raw: RMSE {} {{unit}} against {}", model, raw));
  }
  if (c.model_std > c.raw_std) {
    const auto [after, before] = apart(c.model_std, c.raw_std);
    c.harms.push_back(
        fmt::format("adds variation: STD {} {{unit}} after against {} before, "
                    "worse than the recording mean",
                    after, before));
  }
  if (std::isfinite(c.line_rmse) && c.model_rmse > c.line_rmse) {
    const auto [model, line] = apart(c.model_rmse, c.line_rmse);
    c.harms.push_back(fmt::format("worse than the line in {}: RMSE {} {{unit}} against {}",
                                  line_input, model, line));
  }
  if (!c.harms.empty()) return;
  if (c.model_std > (1.0 - kNoBetterShare) * c.raw_std)
    c.no_better_than.push_back("the recording mean");
  if (std::isfinite(c.line_rmse) && c.model_rmse > (1.0 - kNoBetterShare) * c.line_rmse)
    c.no_better_than.push_back("the line in " + line_input);
}

}  // namespace

BaselineComparison compare_with_baselines(std::span<const double> y, std::span<const double> model,
                                          std::span<const double> line,
                                          const std::string& line_input) {
  if (model.size() != y.size() || (!line.empty() && line.size() != y.size()))
    throw std::invalid_argument("compare_with_baselines: sizes differ");
  BaselineComparison c;
  c.rows = y.size();
  if (y.empty()) return c;
  std::tie(c.raw_rmse, c.raw_std) = rmse_and_std(y, {});
  // The recording mean's error is y − ȳ: its RMSE is the population STD of y.
  const double n = static_cast<double>(y.size());
  c.mean_rmse = c.raw_std * std::sqrt((n - 1) / n);
  std::tie(c.model_rmse, c.model_std) = rmse_and_std(y, model);
  if (!line.empty()) std::tie(c.line_rmse, c.line_std) = rmse_and_std(y, line);
  judge(c, line_input);
  return c;
}

BaselineComparison pool(std::span<const BaselineComparison> recordings,
                        const std::string& line_input) {
  BaselineComparison p;
  double raw = 0, mean = 0, line = 0, model = 0, raw_s = 0, line_s = 0, model_s = 0;
  std::size_t counted = 0;
  bool has_line = true;
  for (const BaselineComparison& r : recordings) {
    if (r.rows == 0) continue;
    const double n = static_cast<double>(r.rows);
    raw += n * r.raw_rmse * r.raw_rmse;
    mean += n * r.mean_rmse * r.mean_rmse;
    model += n * r.model_rmse * r.model_rmse;
    raw_s += r.raw_std * r.raw_std;
    model_s += r.model_std * r.model_std;
    has_line = has_line && std::isfinite(r.line_rmse);
    if (has_line) {
      line += n * r.line_rmse * r.line_rmse;
      line_s += r.line_std * r.line_std;
    }
    p.rows += r.rows;
    ++counted;
  }
  if (counted == 0) return p;
  const double n = static_cast<double>(p.rows), k = static_cast<double>(counted);
  p.raw_rmse = std::sqrt(raw / n);
  p.mean_rmse = std::sqrt(mean / n);
  p.model_rmse = std::sqrt(model / n);
  p.raw_std = std::sqrt(raw_s / k);
  p.model_std = std::sqrt(model_s / k);
  if (has_line) {
    p.line_rmse = std::sqrt(line / n);
    p.line_std = std::sqrt(line_s / k);
  }
  judge(p, line_input);
  return p;
}

}  // namespace fogdrift::eval
