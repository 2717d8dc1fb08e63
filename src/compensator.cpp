#include "fogdrift/compensator.hpp"

namespace fogdrift {

StreamingCompensator::StreamingCompensator(const CompensationModel& model, double dt_s)
    : model_(model),
      rates_{signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s),
             signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s)},
      features_(model.inputs()),
      work_(model.inputs()) {}

void StreamingCompensator::reset() noexcept {
  for (auto& r : rates_) r.reset();
}

double StreamingCompensator::update(const Sample& s) noexcept {
  const std::array<double, 3> temp = {s.temp_fog_degc, s.temp_acc1_degc, s.temp_acc2_degc};
  std::array<double, 3> rate{};
  for (std::size_t k = 0; k < 3; ++k) rate[k] = rates_[k].push(temp[k]);
  // The feature columns in compute_features()'s order (features.cpp).
  std::size_t c = 0;
  for (const auto& term : model_.dataset.features.terms) {
    const auto& th = term.thermometers;
    const auto idx = [](Thermometer k) { return static_cast<std::size_t>(k); };
    switch (term.term) {
      case FeatureTerm::temp:
        for (auto k : th) features_[c++] = temp[idx(k)];
        break;
      case FeatureTerm::rate:
        for (auto k : th) features_[c++] = rate[idx(k)];
        break;
      case FeatureTerm::gradient:
      case FeatureTerm::gradient_rate: {
        const auto& v = term.term == FeatureTerm::gradient_rate ? rate : temp;
        for (std::size_t i = 0; i < th.size(); ++i)
          for (std::size_t j = i + 1; j < th.size(); ++j)
            features_[c++] = v[idx(th[i])] - v[idx(th[j])];
        break;
      }
      case FeatureTerm::time:
        features_[c++] = s.time_s;
        break;
      case FeatureTerm::temp_rate_product:
        for (auto k : th) features_[c++] = temp[idx(k)] * rate[idx(k)];
        break;
    }
  }
  return model_.predict_dph(features_, work_);
}

}  // namespace fogdrift
