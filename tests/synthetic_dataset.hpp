// A small grouped dataset for the training tests: 3 repetitions × 4 initial temperatures,
// 40 rows each, 3 features; y smooth in x plus noise.
#pragma once

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/random.hpp"
#include "fogdrift/model/dataset.hpp"

namespace fogdrift::test {

/// The dataset options synthetic() stands for, named once: a `{}` temporary at each train() call
/// made GCC 12 warn falsely (-Wmaybe-uninitialized) inside its strings. Its spec is the one
/// whose three features synthetic() holds, so that a model trained on it loads (a model's
/// feature names must be its spec's).
inline const DatasetOptions kDefaultDataset = [] {
  DatasetOptions o;
  o.features = FeatureSpec::parse("T");
  return o;
}();

inline Dataset synthetic(std::uint64_t seed = 1) {
  Dataset d;
  d.feature_names = {"T_fog_degc", "T_acc1_degc", "T_acc2_degc"};
  d.feature_spec = "T";
  Rng rng(seed);
  for (int rep = 1; rep <= 3; ++rep) {
    for (double temp : {-20.0, 0.0, 20.0, 40.0}) {
      GroupInfo g;
      g.file = fmt::format("rep{}_{}.csv", rep, temp);
      g.repetition = rep;
      g.initial_temp_degc = temp;
      const std::size_t gi = d.groups.size();
      d.groups.push_back(g);
      for (int k = 0; k < 40; ++k) {
        const double a = temp / 20 + rng.normal(0, 0.3), b = rng.uniform(-2, 2),
                     c = rng.normal(0, 1);
        d.x.insert(d.x.end(), {a, b, c});
        d.y.push_back(0.02 * std::sin(a) + 0.01 * b * b - 0.005 * c + rng.normal(0, 0.002));
        d.time_s.push_back(k * 10.0);
        d.group.push_back(gi);
        ++d.rows;
      }
    }
  }
  return d;
}

}  // namespace fogdrift::test
