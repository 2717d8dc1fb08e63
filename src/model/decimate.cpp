#include "fogdrift/model/decimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {

std::size_t decimation_factor(double model_dt_s, double data_dt_s, const std::string& option) {
  if (model_dt_s == 0) return 1;
  if (!(data_dt_s > 0) || !std::isfinite(data_dt_s))
    throw OptionError(option, "the data's sample interval must be positive and finite");
  const double ratio = model_dt_s / data_dt_s;
  if (ratio < 0.99)
    throw OptionError(
        option, fmt::format("the data come every {:.6g} s ({:.6g} Hz), slower than the model's "
                            "{:.6g} s ({:.6g} Hz): train a model on data at this rate, or log at "
                            "{:.6g} Hz or a whole multiple of it",
                            data_dt_s, 1 / data_dt_s, model_dt_s, 1 / model_dt_s, 1 / model_dt_s));
  const double k = std::round(ratio);
  if (std::fabs(ratio - k) > 0.01 * k)
    throw OptionError(
        option, fmt::format("the data's interval {:.6g} s ({:.6g} Hz) is not a whole fraction of "
                            "the model's {:.6g} s ({:.6g} Hz): put the data on the model's grid "
                            "(fogdrift import ... --step-s {:.6g}), or train at the data's rate",
                            data_dt_s, 1 / data_dt_s, model_dt_s, 1 / model_dt_s, model_dt_s));
  return static_cast<std::size_t>(k);
}

std::size_t decimation_factor(const FeatureOptions& model, double data_dt_s,
                              const std::string& option) {
  const std::size_t k = decimation_factor(model.sample_interval_s, data_dt_s, option);
  constexpr std::size_t kLongestUnrecordedWindow = 1001;
  if (model.sample_interval_s == 0 && std::isfinite(data_dt_s) && data_dt_s > 0) {
    const std::size_t w = signal::window_samples(model.rates, data_dt_s);
    if (w > kLongestUnrecordedWindow)
      throw OptionError(
          option,
          fmt::format("the model file does not record the interval it was trained at (written "
                      "before models did), so its {:.6g} s rate window would run at the data's "
                      "{:.6g} Hz: {} samples, too many to set up; train the model again (the "
                      "model then runs on blocks at its own rate), or resample the data to the "
                      "training rate (fogdrift import ... --step-s)",
                      model.rates.window_s, 1 / data_dt_s, w));
  }
  return k;
}

double streaming_interval_s(const FeatureOptions& model, double data_dt_s, std::size_t k) {
  return model.sample_interval_s > 0 ? model.sample_interval_s / static_cast<double>(k) : data_dt_s;
}

Recording decimate(const Recording& recording, std::size_t k) {
  if (k <= 1) return recording;
  Recording out;
  out.source = recording.source;
  const std::size_t n = recording.size();
  // Every thermometer, further ones from their columns; an absent one sums zeros, never kept.
  const std::vector<double> zeros(n, 0.0);
  const std::vector<std::string> further = further_thermometers_of(recording);
  std::vector<std::vector<double>> further_degc;
  for (const std::string& name : further)
    further_degc.push_back(recording.numeric_column(thermometer_column(name)));
  std::vector<const std::vector<double>*> temps;
  for (const auto* v :
       {&recording.temp_fog_degc, &recording.temp_acc1_degc, &recording.temp_acc2_degc})
    temps.push_back(v->empty() ? &zeros : v);
  for (const auto& v : further_degc) temps.push_back(&v);
  std::vector<std::vector<double>> means(temps.size());
  std::vector<double> sample(temps.size());
  BlockSum sum(temps.size());
  for (std::size_t first = 0, last = 0; first < n; first = last + 1) {
    last = first == 0 ? 0 : std::min(n - 1, first + k - 1);
    if (first != 0 && last - first + 1 < k) break;  // a trailing partial block is not yet done
    sum.clear();
    for (std::size_t i = first; i <= last; ++i) {
      for (std::size_t j = 0; j < temps.size(); ++j) sample[j] = (*temps[j])[i];
      sum.add(sample, recording.gyro_dph[i]);
    }
    const auto c = static_cast<double>(sum.count);
    out.time_s.push_back(recording.time_s[last]);
    out.gyro_dph.push_back(sum.gyro / c);
    for (std::size_t j = 0; j < temps.size(); ++j) means[j].push_back(sum.temp[j] / c);
  }
  out.temp_fog_degc = std::move(means[0]);
  if (!recording.temp_acc1_degc.empty()) out.temp_acc1_degc = std::move(means[1]);
  if (!recording.temp_acc2_degc.empty()) out.temp_acc2_degc = std::move(means[2]);
  for (std::size_t f = 0; f < further.size(); ++f) {
    const std::vector<double>& m = means[3 + f];
    ExtraColumn column{thermometer_column(further[f]), {}};
    for (double v : m) column.cells.push_back(csv::format_number(v));
    out.extra.push_back(std::move(column));
  }
  return out;
}

std::vector<double> decimate(std::span<const double> values, std::size_t k) {
  if (k <= 1) return {values.begin(), values.end()};
  std::vector<double> out;
  const std::size_t n = values.size();
  for (std::size_t first = 0, last = 0; first < n; first = last + 1) {
    last = first == 0 ? 0 : std::min(n - 1, first + k - 1);
    if (first != 0 && last - first + 1 < k) break;
    double sum = 0;
    for (std::size_t i = first; i <= last; ++i) sum += values[i];
    out.push_back(sum / static_cast<double>(last - first + 1));
  }
  return out;
}

}  // namespace fogdrift
