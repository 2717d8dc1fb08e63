#include "fogdrift/compensator.hpp"

namespace fogdrift {

StreamingCompensator::StreamingCompensator(const CompensationModel& model, double dt_s)
    : model_(model),
      rates_{signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s)},
      columns_(model.dataset.features.columns()),
      features_(model.inputs()),
      work_(model.inputs()) {}

void StreamingCompensator::reset() noexcept {
  for (auto& r : rates_) r.reset();
}

double StreamingCompensator::update(const Sample& s) noexcept {
  const std::array<double, 3> temp = {s.temp_fog_degc, s.temp_acc1_degc, s.temp_acc2_degc};
  std::array<double, 3> rate{};
  for (std::size_t k = 0; k < 3; ++k) rate[k] = rates_[k].push(temp[k]);
  for (std::size_t c = 0; c < columns_.size(); ++c)
    features_[c] = columns_[c].value(temp, rate, s.time_s);
  return model_.predict_dph(features_, work_);
}

}  // namespace fogdrift
