#include "fogdrift/train/held_out.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

/// A line must beat the mean by this share of its RMSE to count as a temperature signal: noise
/// alone lets a fitted slope beat a constant by a little on held-out rows.
constexpr double kSignalShare = 0.05;
/// A model expected to remove less than this share of the held-out drift is not worth shipping.
constexpr double kUsefulShare = 0.10;
/// Below this share of the variation within a start-up, compensation may not help the
/// north-finder (docs/tuning.md, "How sure train is"). On the denoised target: on a population of
/// 20 instruments the two whose start-ups like the calibration ended worse than raw had 58-62 %,
/// every other 66 % or more. On the block means as logged, whose noise no model predicts, the
/// same two had 23-24 %, every other 41 % or more (docs/field.md, "The target without
/// denoising", also gives a second population).
constexpr double kStartupShareDenoised = 0.65;
constexpr double kStartupShareAsLogged = 0.30;

double centred_sum_of_squares(const std::vector<double>& v) {
  double mean = 0;
  for (double x : v) mean += x;
  mean /= static_cast<double>(v.size());
  double s = 0;
  for (double x : v) s += (x - mean) * (x - mean);
  return s;
}

/// "fog" of "T_fog_degc".
std::string thermometer_of(const std::string& temperature_input) {
  return temperature_input.substr(2, temperature_input.size() - 7);
}

}  // namespace

double startup_warning_share(bool denoised_target) {
  return denoised_target ? kStartupShareDenoised : kStartupShareAsLogged;
}

std::vector<std::size_t> temperature_inputs(std::span<const std::string> feature_names) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < feature_names.size(); ++k) {
    const std::string& n = feature_names[k];
    if (n.starts_with("T_") && n.ends_with("_degc")) out.push_back(k);
  }
  return out;
}

namespace {

// The baselines over folds already split and standardised.
std::vector<Baseline> baselines_of(const Dataset& data, std::span<const tune::ScaledSplit> splits) {
  if (splits.empty()) throw OptionError("folds", "there are no folds to score the baselines on");
  const std::vector<std::size_t> temps = temperature_inputs(data.feature_names);
  std::vector<double> sse(1 + temps.size(), 0.0);
  std::size_t count = 0;
  const std::size_t d = data.cols();
  for (const tune::ScaledSplit& s : splits) {
    // Standardised training columns have mean 0, so the least-squares line through them has
    // intercept 0 and slope Σxy / Σx².
    for (std::size_t r = 0; r < s.test.rows; ++r) sse[0] += s.test.y[r] * s.test.y[r];
    for (std::size_t j = 0; j < temps.size(); ++j) {
      const std::size_t k = temps[j];
      double sxy = 0, sxx = 0;
      for (std::size_t r = 0; r < s.train.rows; ++r) {
        const double x = s.train.x[r * d + k];
        sxy += x * s.train.y[r];
        sxx += x * x;
      }
      const double slope = sxx > 0 ? sxy / sxx : 0.0;
      for (std::size_t r = 0; r < s.test.rows; ++r) {
        const double e = slope * s.test.x[r * d + k] - s.test.y[r];
        sse[1 + j] += e * e;
      }
    }
    count += s.test.rows;
  }
  if (count == 0) throw OptionError("folds", "the folds hold out no rows");
  std::vector<Baseline> out;
  out.push_back({"mean", "", std::sqrt(sse[0] / static_cast<double>(count))});
  for (std::size_t j = 0; j < temps.size(); ++j) {
    const std::string& input = data.feature_names[temps[j]];
    out.push_back({"line in " + input, input, std::sqrt(sse[1 + j] / static_cast<double>(count))});
  }
  return out;
}

}  // namespace

std::vector<Baseline> baseline_scores(const Dataset& data, std::span<const tune::Fold> folds) {
  return baselines_of(data, tune::scale_splits(data, folds));
}

HeldOutReport held_out_report(const Dataset& data, std::span<const tune::Fold> folds,
                              const FoldPredictor& predict, std::string folds_description,
                              double startup_warning_below, bool model_is_a_line) {
  HeldOutReport r;
  r.folds = std::move(folds_description);
  // Pooled over the held-out rows: the squared error, and within each recording the squared
  // deviation of the error and of the target from their means over that recording's rows.
  double sse = 0, within_error = 0, within_target = 0;
  std::size_t count = 0;
  // Each fold split and standardised once, for the model and the baselines alike.
  const std::vector<tune::ScaledSplit> splits = tune::scale_splits(data, folds);
  for (std::size_t k = 0; k < folds.size(); ++k) {
    const tune::ScaledSplit& split = splits[k];
    const std::vector<double> p = predict(split, k);
    if (p.size() != split.test.rows)
      throw OptionError("held_out", "the model predicted another number of rows than held out");
    std::map<std::size_t, std::pair<std::vector<double>, std::vector<double>>> by_group;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double e = p[i] - split.test.y[i];
      sse += e * e;
      auto& [errors, targets] = by_group[data.group[folds[k].test_rows[i]]];
      errors.push_back(e);
      targets.push_back(split.test.y[i]);
    }
    for (const auto& [group, g] : by_group) {
      within_error += centred_sum_of_squares(g.first);
      within_target += centred_sum_of_squares(g.second);
    }
    count += p.size();
  }
  if (count == 0) throw OptionError("folds", "the folds hold out no rows");
  const double model_rmse = std::sqrt(sse / static_cast<double>(count));
  r.model_rmse = model_rmse;
  r.expected_startup_share =
      within_target > 0 ? 1.0 - std::sqrt(within_error / within_target) : 0.0;
  r.baselines = baselines_of(data, splits);
  const Baseline& mean = r.baselines.front();
  r.expected_share = mean.rmse > 0 ? 1.0 - model_rmse / mean.rmse : 0.0;
  const Baseline* best_line = nullptr;
  for (std::size_t i = 1; i < r.baselines.size(); ++i)
    if (best_line == nullptr || r.baselines[i].rmse < best_line->rmse) best_line = &r.baselines[i];
  const bool no_signal =
      best_line != nullptr && best_line->rmse >= (1.0 - kSignalShare) * mean.rmse;
  if (r.expected_share < kUsefulShare) {
    r.warnings.push_back(
        model_rmse >= mean.rmse
            ? fmt::format("the model predicts the held-out drift no better than the training mean "
                          "(RMSE {:.4f} against {:.4f}, standardised, over {}): it would remove "
                          "nothing on this unit",
                          model_rmse, mean.rmse, r.folds)
            : fmt::format("the model removes only {:.0f} % of the held-out drift (RMSE {:.4f} "
                          "against the training mean's {:.4f}, standardised, over {}): it would "
                          "remove little on this unit",
                          100 * r.expected_share, model_rmse, mean.rmse, r.folds));
    if (no_signal)
      r.warnings.push_back(fmt::format(
          "no temperature explains the drift: no straight line in a temperature beats the mean "
          "by {1:.0f} % (best: {0}, RMSE {2:.4f} against {3:.4f}); the data show no temperature "
          "signal. Check that the target column is the channel the thermometers drive and that the "
          "calibration spans a temperature change",
          best_line->input, 100 * kSignalShare, best_line->rmse, mean.rmse));
  } else if (r.expected_startup_share < startup_warning_below) {
    r.warnings.push_back(fmt::format(
        "the model removes {:.0f} % of the held-out drift but only {:.0f} % of its variation "
        "within a start-up, the part a four-position north-finding sees: most of what it learnt "
        "is the static drift between temperatures, and on this unit it may not help the "
        "north-finder",
        100 * r.expected_share, 100 * r.expected_startup_share));
  } else if (!model_is_a_line && best_line != nullptr && best_line->rmse <= model_rmse) {
    r.warnings.push_back(fmt::format(
        "a straight line in {} predicts the held-out drift as well as the model (RMSE {:.4f} "
        "against {:.4f}, standardised, over {}): the drift is mostly a static function of that "
        "temperature, and a straight line in it ({{method}} poly, {{max_degree}} 1, {{features}} "
        "'T({})') is simpler to trust",
        best_line->input, best_line->rmse, model_rmse, r.folds, thermometer_of(best_line->input)));
  }
  return r;
}

}  // namespace fogdrift
