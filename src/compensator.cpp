#include "fogdrift/compensator.hpp"

namespace fogdrift {

StreamingCompensator::StreamingCompensator(const CompensationModel& model, double dt_s,
                                           bool guarded)
    : model_(model),
      rates_{signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s)},
      columns_(model.dataset.features.columns()),
      features_(model.inputs()),
      work_(model.inputs()),
      guarded_(guarded && !model.guard.empty()) {}

void StreamingCompensator::reset() noexcept {
  for (auto& r : rates_) r.reset();
  filter_.reset();
  weight_ = 1.0;
}

double StreamingCompensator::update(const Sample& s) noexcept {
  const std::array<double, 3> temp = {s.temp_fog_degc, s.temp_acc1_degc, s.temp_acc2_degc};
  std::array<double, 3> rate{};
  for (std::size_t k = 0; k < 3; ++k) rate[k] = rates_[k].push(temp[k]);
  for (std::size_t c = 0; c < columns_.size(); ++c)
    features_[c] = columns_[c].value(temp, rate, s.time_s);
  last_ = model_.predict(features_, work_);
  if (!guarded_) return last_.drift_dph;
  weight_ = filter_.update(s.time_s, last_.target_weight, model_.guard.settings.recover_s);
  return model_.guarded_dph(last_.drift_dph, weight_);
}

}  // namespace fogdrift
