#include "fogdrift/train/folds.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift::tune {
namespace {

constexpr std::array<EnumName<CvScheme>, 4> kCvSchemeNames = {
    {{CvScheme::automatic, "auto"},
     {CvScheme::repetition, "repetition"},
     {CvScheme::recording, "recording"},
     {CvScheme::temperature, "temperature"}}};

}  // namespace

std::string to_string(CvScheme scheme) {
  return std::string(name_in(kCvSchemeNames, scheme));
}

CvScheme parse_cv_scheme(const std::string& text, const std::string& option) {
  return parse_in(kCvSchemeNames, text, option, "a cross-validation scheme");
}

std::string cv_scheme_names() {
  return names_in(kCvSchemeNames);
}

namespace {

// k folds of `available` whole units (recordings, temperatures) need 2 ≤ k ≤ available.
std::size_t checked_folds(std::size_t k, std::size_t available, const char* units,
                          const char* counted) {
  if (available < 2)
    throw OptionError("folds",
                      fmt::format("folds of whole {} need at least 2 {}, and there {} {}", units,
                                  counted, available == 1 ? "is" : "are", available));
  if (k < 2) throw OptionError("folds", fmt::format("{} is not a number of folds: 2 or more", k));
  if (k > available)
    throw OptionError("folds",
                      fmt::format("{} folds of whole {} need {} {}, and there are {}; ask "
                                  "for {}",
                                  k, units, k, counted, available,
                                  available == 2 ? std::string("2 folds")
                                                 : fmt::format("2 to {} folds", available)));
  return k;
}

}  // namespace

std::vector<Fold> grouped_folds(const Dataset& data, const CvOptions& options) {
  // Only groups that have rows take part.
  std::vector<std::size_t> rows_of(data.groups.size(), 0);
  for (std::size_t g : data.group) ++rows_of[g];
  std::vector<std::size_t> groups;
  for (std::size_t g = 0; g < data.groups.size(); ++g)
    if (rows_of[g] > 0) groups.push_back(g);
  std::set<int> repetitions;
  for (std::size_t g : groups) repetitions.insert(data.groups[g].repetition);

  std::set<double> temperatures;
  for (std::size_t g : groups) temperatures.insert(data.groups[g].initial_temp_degc);

  CvScheme scheme = options.scheme;
  if (scheme == CvScheme::automatic)
    scheme = temperatures.size() >= std::max<std::size_t>(3, options.folds) ? CvScheme::temperature
             : repetitions.size() >= 2                                      ? CvScheme::repetition
                                                                            : CvScheme::recording;

  std::vector<std::size_t> fold_of_group(data.groups.size(), 0);
  std::vector<std::string> names;
  if (scheme == CvScheme::repetition) {
    if (repetitions.size() < 2)
      throw OptionError("cv", fmt::format("leave-one-repetition-out needs recordings of two or "
                                          "more repetitions; the training data has {}",
                                          repetitions.size()));
    const std::vector<int> reps(repetitions.begin(), repetitions.end());
    for (std::size_t g : groups)
      fold_of_group[g] = static_cast<std::size_t>(
          std::find(reps.begin(), reps.end(), data.groups[g].repetition) - reps.begin());
    for (int r : reps) names.push_back(fmt::format("repetition {}", r));
  } else if (scheme == CvScheme::temperature) {
    std::set<double> temperatures;
    for (std::size_t g : groups) temperatures.insert(data.groups[g].initial_temp_degc);
    const std::size_t k = checked_folds(options.folds, temperatures.size(), "initial temperatures",
                                        "training temperatures");
    const std::vector<double> temps(temperatures.begin(), temperatures.end());
    for (std::size_t g : groups) {
      const auto t = static_cast<std::size_t>(
          std::find(temps.begin(), temps.end(), data.groups[g].initial_temp_degc) - temps.begin());
      fold_of_group[g] = t % k;
    }
    for (std::size_t f = 0; f < k; ++f) {
      std::string held;
      for (std::size_t t = f; t < temps.size(); t += k)
        held += fmt::format("{}{:g}", held.empty() ? "" : ",", temps[t]);
      names.push_back(fmt::format("temperatures {} °C", held));
    }
  } else {
    const std::size_t k =
        checked_folds(options.folds, groups.size(), "recordings", "training recordings");
    std::vector<std::size_t> sorted = groups;
    std::stable_sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) {
      const GroupInfo &ga = data.groups[a], &gb = data.groups[b];
      if (ga.initial_temp_degc != gb.initial_temp_degc)
        return ga.initial_temp_degc < gb.initial_temp_degc;
      if (ga.repetition != gb.repetition) return ga.repetition < gb.repetition;
      return ga.file < gb.file;
    });
    for (std::size_t i = 0; i < sorted.size(); ++i) fold_of_group[sorted[i]] = i % k;
    for (std::size_t f = 0; f < k; ++f) names.push_back(fmt::format("recordings {}/{}", f + 1, k));
  }

  std::vector<Fold> folds(names.size());
  for (std::size_t f = 0; f < folds.size(); ++f) folds[f].name = names[f];
  for (std::size_t i = 0; i < data.rows; ++i) {
    const std::size_t f = fold_of_group[data.group[i]];
    for (std::size_t m = 0; m < folds.size(); ++m)
      (m == f ? folds[m].test_rows : folds[m].train_rows).push_back(i);
  }
  return folds;
}

ScaledSplit scale_split(const Dataset& data, std::span<const std::size_t> train_rows,
                        std::span<const std::size_t> test_rows) {
  const std::size_t d = data.cols();
  auto gather = [&](std::span<const std::size_t> rows) {
    Data out;
    out.rows = rows.size();
    out.cols = d;
    out.x.reserve(rows.size() * d);
    out.y.reserve(rows.size());
    for (std::size_t i : rows) {
      const auto r = data.row(i);
      out.x.insert(out.x.end(), r.begin(), r.end());
      out.y.push_back(data.y[i]);
    }
    return out;
  };
  ScaledSplit s;
  s.train = gather(train_rows);
  s.test = gather(test_rows);
  s.x_scaler = Standardizer::fit(s.train.x, d, data.feature_names);
  s.y_scaler = Standardizer::fit(s.train.y, 1, {"drift_dph"});
  s.x_scaler.apply(s.train.x);
  s.x_scaler.apply(s.test.x);
  s.y_scaler.apply(s.train.y);
  s.y_scaler.apply(s.test.y);
  return s;
}

std::vector<ScaledSplit> scale_splits(const Dataset& data, std::span<const Fold> folds) {
  std::vector<ScaledSplit> splits;
  splits.reserve(folds.size());
  for (const Fold& f : folds) splits.push_back(scale_split(data, f.train_rows, f.test_rows));
  return splits;
}

double pooled_rmse(std::span<const ScaledSplit> splits, const FoldPredictions& predicted) {
  double sse = 0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < splits.size(); ++k) {
    const Data& test = splits[k].test;
    for (std::size_t r = 0; r < test.rows; ++r) {
      const double e = predicted[k][r] - test.y[r];
      sse += e * e;
    }
    n += test.rows;
  }
  return std::sqrt(sse / static_cast<double>(n));
}

}  // namespace fogdrift::tune
