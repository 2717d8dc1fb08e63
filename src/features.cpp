#include "fogdrift/features.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <cmath>

#include "fogdrift/enum_names.hpp"
#include "fogdrift/error.hpp"

namespace fogdrift {
namespace {

constexpr std::array kThermometers = {Thermometer::fog, Thermometer::acc1, Thermometer::acc2};
constexpr std::array<EnumName<Thermometer>, 3> kThermometerNames = {
    {{Thermometer::fog, "fog"}, {Thermometer::acc1, "acc1"}, {Thermometer::acc2, "acc2"}}};
constexpr std::array<EnumName<FeatureTerm>, 6> kTermNames = {
    {{FeatureTerm::temp, "T"},
     {FeatureTerm::rate, "dT"},
     {FeatureTerm::gradient, "grad"},
     {FeatureTerm::gradient_rate, "dgrad"},
     {FeatureTerm::time, "t"},
     {FeatureTerm::temp_rate_product, "TdT"}}};
constexpr std::array kTerms = {FeatureTerm::temp,     FeatureTerm::rate,
                               FeatureTerm::gradient, FeatureTerm::gradient_rate,
                               FeatureTerm::time,     FeatureTerm::temp_rate_product};

bool is_gradient(FeatureTerm term) {
  return term == FeatureTerm::gradient || term == FeatureTerm::gradient_rate;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// Splits at commas that are not inside parentheses.
std::vector<std::string_view> split_terms(std::string_view text) {
  std::vector<std::string_view> out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i == text.size() || (text[i] == ',' && depth == 0)) {
      out.push_back(trim(text.substr(start, i - start)));
      start = i + 1;
    } else if (text[i] == '(') {
      ++depth;
    } else if (text[i] == ')') {
      --depth;
    }
  }
  return out;
}

}  // namespace

std::string_view to_string(Thermometer thermometer) {
  return name_in(kThermometerNames, thermometer);
}

std::string_view to_string(FeatureTerm term) {
  return name_in(kTermNames, term);
}

std::string_view column_name(Thermometer thermometer) {
  switch (thermometer) {
    case Thermometer::fog:
      return "temp_fog_degc";
    case Thermometer::acc1:
      return "temp_acc1_degc";
    case Thermometer::acc2:
      return "temp_acc2_degc";
  }
  return "?";
}

FeatureSpec FeatureSpec::parse(std::string_view text) {
  const auto fail = [&](const std::string& why) {
    throw OptionError("features", fmt::format("'{}': {}; write terms such as T,dT,grad or "
                                              "T(fog,acc1) from T, dT, grad, dgrad, t, TdT",
                                              text, why));
  };
  FeatureSpec spec;
  if (trim(text).empty()) fail("the spec is empty");
  for (std::string_view item : split_terms(text)) {
    if (item.empty()) fail("an empty term");
    std::string_view name = item;
    std::string_view list;
    bool has_list = false;
    if (const auto open = item.find('('); open != std::string_view::npos) {
      if (item.back() != ')') fail(fmt::format("'{}' has no closing parenthesis", item));
      name = trim(item.substr(0, open));
      list = item.substr(open + 1, item.size() - open - 2);
      has_list = true;
    }
    const auto term_it = std::find_if(kTerms.begin(), kTerms.end(), [&](FeatureTerm t) {
      return fogdrift::to_string(t) == name;
    });
    if (term_it == kTerms.end()) fail(fmt::format("'{}' is not a term", name));
    FeatureTermSpec term{*term_it, {}};
    for (const auto& existing : spec.terms) {
      if (existing.term == term.term) fail(fmt::format("'{}' appears twice", name));
    }
    if (term.term == FeatureTerm::time) {
      if (has_list) fail("'t' takes no thermometers");
    } else if (!has_list) {
      term.thermometers.assign(kThermometers.begin(), kThermometers.end());
    } else {
      std::array<bool, 3> chosen{};
      for (std::string_view s : split_terms(list)) {
        const auto th = std::find_if(kThermometers.begin(), kThermometers.end(),
                                     [&](Thermometer k) { return fogdrift::to_string(k) == s; });
        if (th == kThermometers.end()) {
          fail(fmt::format("'{}' is not a thermometer (fog, acc1, acc2)", s));
        }
        const auto index = static_cast<std::size_t>(th - kThermometers.begin());
        if (chosen[index]) fail(fmt::format("thermometer '{}' appears twice in {}", s, name));
        chosen[index] = true;
      }
      for (std::size_t k = 0; k < 3; ++k) {
        if (chosen[k]) term.thermometers.push_back(kThermometers[k]);
      }
    }
    if (is_gradient(term.term) && term.thermometers.size() < 2) {
      fail(fmt::format("'{}' needs at least two thermometers", name));
    }
    spec.terms.push_back(std::move(term));
  }
  return spec;
}

std::string FeatureSpec::to_string() const {
  std::string out;
  for (const auto& term : terms) {
    if (!out.empty()) out += ',';
    out += fogdrift::to_string(term.term);
    if (term.term != FeatureTerm::time && term.thermometers.size() != 3) {
      out += '(';
      for (std::size_t k = 0; k < term.thermometers.size(); ++k) {
        if (k > 0) out += ',';
        out += fogdrift::to_string(term.thermometers[k]);
      }
      out += ')';
    }
  }
  return out;
}

std::vector<FeatureColumn> FeatureSpec::columns() const {
  std::vector<FeatureColumn> out;
  for (const auto& term : terms) {
    const auto& th = term.thermometers;
    if (term.term == FeatureTerm::time) {
      out.push_back({FeatureTerm::time});
    } else if (term.term == FeatureTerm::gradient || term.term == FeatureTerm::gradient_rate) {
      for (std::size_t i = 0; i < th.size(); ++i)
        for (std::size_t j = i + 1; j < th.size(); ++j) out.push_back({term.term, th[i], th[j]});
    } else {
      for (auto k : th) out.push_back({term.term, k});
    }
  }
  return out;
}

std::string FeatureColumn::name() const {
  const auto ta = fogdrift::to_string(a), tb = fogdrift::to_string(b);
  switch (term) {
    case FeatureTerm::temp:
      return fmt::format("T_{}_degc", ta);
    case FeatureTerm::rate:
      return fmt::format("dT_{}_degc_per_s", ta);
    case FeatureTerm::gradient:
      return fmt::format("grad_{}_{}_degc", ta, tb);
    case FeatureTerm::gradient_rate:
      return fmt::format("dgrad_{}_{}_degc_per_s", ta, tb);
    case FeatureTerm::time:
      return "t_s";
    case FeatureTerm::temp_rate_product:
      return fmt::format("TdT_{}_degc2_per_s", ta);
  }
  return "?";
}

std::vector<std::string> FeatureSpec::names() const {
  std::vector<std::string> out;
  for (const FeatureColumn& c : columns()) out.push_back(c.name());
  return out;
}

FeatureSpec default_feature_spec() {
  return FeatureSpec::parse("T,dT,grad");
}

std::vector<bool> FeatureSpec::rate_inputs() const {
  std::vector<bool> out;
  for (const FeatureColumn& c : columns()) out.push_back(c.reads_rate());
  return out;
}

bool FeatureSpec::reads(Thermometer k) const {
  const std::vector<FeatureColumn> plan = columns();
  return std::any_of(plan.begin(), plan.end(), [k](const FeatureColumn& c) { return c.reads(k); });
}

FeatureSpec default_feature_spec(const std::vector<Thermometer>& present) {
  if (present.empty()) throw OptionError("features", "no thermometer to build features from");
  if (present.size() == 3) return default_feature_spec();
  std::vector<std::string_view> names;
  for (Thermometer k : present) names.push_back(to_string(k));
  const std::string list = fmt::format("{}", fmt::join(names, ","));
  return FeatureSpec::parse(present.size() == 1 ? fmt::format("T({0}),dT({0})", list)
                                                : fmt::format("T({0}),dT({0}),grad({0})", list));
}

std::vector<Thermometer> thermometers_of(const Recording& recording) {
  std::vector<Thermometer> out = {Thermometer::fog};
  if (!recording.temp_acc1_degc.empty()) out.push_back(Thermometer::acc1);
  if (!recording.temp_acc2_degc.empty()) out.push_back(Thermometer::acc2);
  return out;
}

double sample_interval_s(const Recording& recording) {
  const auto& t = recording.time_s;
  if (t.size() < 2) {
    throw InputError(recording.source, 0, 0, "a recording needs at least 2 samples");
  }
  const double median = median_time_step_s(t);
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double step = t[i + 1] - t[i];
    if (std::fabs(step - median) > 0.01 * median) {
      // Line numbers count the header as line 1; sample i + 1 is on line i + 3.
      throw InputError(recording.source, i + 3, 0,
                       fmt::format("time_s steps by {:.6g} s here but by {:.6g} s elsewhere; "
                                   "features need uniform sampling (within 1 %): put the log on a "
                                   "uniform grid first with 'fogdrift import --rate-hz' "
                                   "(docs/logs.md)",
                                   step, median));
    }
  }
  return median;
}

FeatureOptions preprocessing_for(double dt_s, std::size_t shortest_samples,
                                 const FeatureOptions& base) {
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw OptionError("dt_s", "the sample interval must be positive and finite");
  FeatureOptions o = base;
  const FeatureOptions defaults;
  const double per_block = std::max(1.0, std::round(defaults.block.block_s / dt_s));
  o.block.block_s = per_block * dt_s;
  if (std::fabs(defaults.block.block_s / dt_s - per_block) <= 1e-6 * per_block)
    o.block.block_s = defaults.block.block_s;  // exactly 10 s, not 10 s up to rounding
  const signal::DifferentiatorOptions recommended = signal::recommended_rates(o.rates.causality);
  o.rates.poly_order = recommended.poly_order;
  constexpr double kMinWindow = 5;
  double window = std::max(recommended.window_s / dt_s, kMinWindow);
  if (o.rates.causality == signal::Causality::centred && shortest_samples > 0) {
    const double longest_odd =
        static_cast<double>(shortest_samples % 2 == 1 ? shortest_samples : shortest_samples - 1);
    window = std::max(kMinWindow, std::min(window, longest_odd));
  }
  o.rates.window_s = window * dt_s;
  if (window == recommended.window_s / dt_s) o.rates.window_s = recommended.window_s;
  o.sample_interval_s = dt_s;
  return o;
}

FeatureTable compute_features(const Recording& recording, const FeatureSpec& spec,
                              const FeatureOptions& options) {
  const double dt = sample_interval_s(recording);
  const std::size_t n = recording.size();
  std::size_t block = 0;
  try {
    block = signal::block_samples(options.block, dt);
    signal::validate(options.rates, dt, n);
  } catch (const OptionError& e) {
    // The setting, named as the library names it, and the recording that cannot meet it.
    throw OptionError(e.option(), fmt::format("{} (in {}, sampled every {:.6g} s)", e.message(),
                                              recording.source, dt));
  }
  if (n < block) {
    throw InputError(
        recording.source, 0, 0,
        fmt::format("{} samples are fewer than one averaging block of {} s ({} samples)", n,
                    options.block.block_s, block));
  }

  const std::array<const std::vector<double>*, 3> temps = {
      &recording.temp_fog_degc, &recording.temp_acc1_degc, &recording.temp_acc2_degc};
  const std::vector<FeatureColumn> plan = spec.columns();
  for (Thermometer k : {Thermometer::acc1, Thermometer::acc2}) {
    if (!temps[static_cast<std::size_t>(k)]->empty()) continue;
    for (const FeatureColumn& c : plan) {
      if (!c.reads(k)) continue;
      throw InputError(
          recording.source, 1, 0,
          fmt::format("has no {} column, which the feature {} reads (spec '{}'); a unit with "
                      "fewer thermometers trains on those it has, e.g. --features \"{}\" "
                      "(docs/logs.md)",
                      column_name(k), c.name(), spec.to_string(),
                      default_feature_spec(thermometers_of(recording)).to_string()));
    }
  }
  // Rates only of the thermometers some input reads.
  std::array<std::vector<double>, 3> rates;
  for (Thermometer k : {Thermometer::fog, Thermometer::acc1, Thermometer::acc2}) {
    const auto i = static_cast<std::size_t>(k);
    if (std::any_of(plan.begin(), plan.end(),
                    [k](const FeatureColumn& c) { return c.reads_rate(k); }))
      rates[i] = signal::differentiate(*temps[i], dt, options.rates);
  }
  std::vector<std::vector<double>> columns(plan.size(), std::vector<double>(n));  // sample rate
  for (std::size_t s = 0; s < n; ++s) {
    std::array<double, 3> temp{}, rate{};
    for (std::size_t i = 0; i < 3; ++i) {
      temp[i] = temps[i]->empty() ? 0.0 : (*temps[i])[s];  // an absent one is never read
      rate[i] = rates[i].empty() ? 0.0 : rates[i][s];
    }
    for (std::size_t c = 0; c < plan.size(); ++c)
      columns[c][s] = plan[c].value(temp, rate, recording.time_s[s]);
  }

  FeatureTable table;
  table.names = spec.names();
  table.block = block;
  table.time_s = signal::block_average(recording.time_s, block);
  table.rows = table.time_s.size();
  const std::size_t warm = signal::warmup_samples(options.rates, dt);  // samples
  table.warm_rows = std::min(table.rows, (warm + block - 1) / block);
  const std::size_t cols = columns.size();
  table.x.resize(table.rows * cols);
  for (std::size_t c = 0; c < cols; ++c) {
    const auto means = signal::block_average(columns[c], block);
    for (std::size_t r = 0; r < table.rows; ++r) table.x[r * cols + c] = means[r];
  }
  return table;
}

}  // namespace fogdrift
