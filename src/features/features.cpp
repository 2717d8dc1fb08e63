#include "fogdrift/features/features.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift {
namespace {

constexpr std::array<std::string_view, 3> kThermometerNames = {"fog", "acc1", "acc2"};
constexpr std::array<EnumName<FeatureTerm>, 7> kTermNames = {
    {{FeatureTerm::temp, "T"},
     {FeatureTerm::rate, "dT"},
     {FeatureTerm::gradient, "grad"},
     {FeatureTerm::gradient_rate, "dgrad"},
     {FeatureTerm::time, "t"},
     {FeatureTerm::temp_rate_product, "TdT"},
     {FeatureTerm::lagged_rate, "dT@"}}};
// The longest lag a term may name, s: a day, far beyond any start-up.
constexpr double kMaxLagS = 86400;
constexpr std::array kTerms = {FeatureTerm::temp,       FeatureTerm::rate,
                               FeatureTerm::gradient,   FeatureTerm::gradient_rate,
                               FeatureTerm::time,       FeatureTerm::temp_rate_product,
                               FeatureTerm::lagged_rate};

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

std::string_view to_string(FeatureTerm term) {
  return name_in(kTermNames, term);
}

LaggedRate::LaggedRate(double tau_s, double dt_s)
    : tau_s_(tau_s), gain_(-std::expm1(-dt_s / tau_s)) {
  if (!(tau_s > 0) || !std::isfinite(tau_s))
    throw OptionError("features", fmt::format("dT@{}: the lag must be a time > 0 s", tau_s));
  if (!(dt_s > 0) || !std::isfinite(dt_s))
    throw OptionError("dt_s", "the sample interval must be positive and finite");
}

std::string thermometer_column(std::string_view name) {
  return fmt::format("temp_{}_degc", name);
}

bool is_thermometer_name(std::string_view name) {
  if (std::find(kThermometerNames.begin(), kThermometerNames.end(), name) !=
      kThermometerNames.end())
    return true;
  // A further one: the NAME of a channel temp_NAME_degc (recording.hpp), starting with a letter.
  return !name.empty() && name.front() >= 'a' && name.front() <= 'z' &&
         is_channel_column(thermometer_column(name));
}

std::string_view FeatureSpec::thermometer_name(Thermometer k) const {
  const auto i = static_cast<std::size_t>(k);
  return i < 3 ? kThermometerNames[i] : std::string_view(further.at(i - 3));
}

std::vector<std::string> FeatureSpec::thermometer_columns() const {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < thermometer_count(); ++k)
    out.push_back(thermometer_column(thermometer_name(static_cast<Thermometer>(k))));
  return out;
}

FeatureSpec FeatureSpec::parse(std::string_view text,
                               const std::vector<std::string>& thermometers) {
  const auto fail = [&](const std::string& why) {
    throw OptionError("features",
                      fmt::format("'{}': {}; write terms such as T,dT,grad or T(fog,acc1) from T, "
                                  "dT, grad, dgrad, t, TdT, dT@SECONDS",
                                  text, why));
  };
  FeatureSpec spec;
  // A thermometer's number, a further one numbered as it is first met.
  const auto number = [&](std::string_view name) {
    const auto known = std::find(kThermometerNames.begin(), kThermometerNames.end(), name);
    if (known != kThermometerNames.end())
      return static_cast<Thermometer>(known - kThermometerNames.begin());
    if (!is_thermometer_name(name))
      fail(
          fmt::format("'{}' is not a thermometer (fog, acc1, acc2, or NAME of a further column "
                      "temp_NAME_degc: lower-case letters, digits and '_')",
                      name));
    auto at = std::find(spec.further.begin(), spec.further.end(), name);
    if (at == spec.further.end()) at = spec.further.insert(at, std::string(name));
    return static_cast<Thermometer>(3 + (at - spec.further.begin()));
  };
  std::vector<std::string_view> bare(kThermometerNames.begin(), kThermometerNames.end());
  if (!thermometers.empty()) bare.assign(thermometers.begin(), thermometers.end());
  if (trim(text).empty()) fail("the spec is empty");
  for (std::string_view item : split_terms(text)) {
    if (item.empty()) fail("an empty term");
    std::string_view name = item;
    std::vector<std::string_view> list = bare;
    bool has_list = false;
    if (const auto open = item.find('('); open != std::string_view::npos) {
      if (item.back() != ')') fail(fmt::format("'{}' has no closing parenthesis", item));
      name = trim(item.substr(0, open));
      list = split_terms(item.substr(open + 1, item.size() - open - 2));
      has_list = true;
    }
    FeatureTermSpec term;
    if (name.starts_with("dT@")) {
      term.term = FeatureTerm::lagged_rate;
      const std::string_view tau = name.substr(3);
      double value = 0;
      const auto [end, ec] = std::from_chars(tau.data(), tau.data() + tau.size(), value);
      if (ec != std::errc() || end != tau.data() + tau.size() || !(value > 0) ||
          !(value <= kMaxLagS))
        fail(
            fmt::format("'{}': the lag after '@' must be a number of seconds, > 0 and at most "
                        "{} (a day)",
                        name, kMaxLagS));
      term.tau_s = value;
    } else {
      const auto term_it = std::find_if(kTerms.begin(), kTerms.end(), [&](FeatureTerm t) {
        return t != FeatureTerm::lagged_rate && fogdrift::to_string(t) == name;
      });
      if (term_it == kTerms.end()) fail(fmt::format("'{}' is not a term", name));
      term.term = *term_it;
    }
    for (const auto& existing : spec.terms) {
      if (existing.term == term.term && existing.tau_s == term.tau_s)
        fail(fmt::format("'{}' appears twice", name));
    }
    if (term.term == FeatureTerm::time) {
      if (has_list) fail("'t' takes no thermometers");
    } else {
      for (std::string_view s : list) {
        const Thermometer k = number(s);
        if (std::find(term.thermometers.begin(), term.thermometers.end(), k) !=
            term.thermometers.end())
          fail(fmt::format("thermometer '{}' appears twice in {}", s, name));
        term.thermometers.push_back(k);
      }
      std::sort(term.thermometers.begin(), term.thermometers.end());
    }
    if (is_gradient(term.term) && term.thermometers.size() < 2) {
      fail(fmt::format("'{}' needs at least two thermometers", name));
    }
    spec.terms.push_back(std::move(term));
  }
  return spec;
}

std::string FeatureSpec::to_string() const {
  const std::vector<Thermometer> three = {Thermometer::fog, Thermometer::acc1, Thermometer::acc2};
  std::string out;
  for (const auto& term : terms) {
    if (!out.empty()) out += ',';
    out += fogdrift::to_string(term.term);
    if (term.term == FeatureTerm::lagged_rate) out += fmt::format("{}", term.tau_s);
    if (term.term != FeatureTerm::time && term.thermometers != three) {
      out += '(';
      for (std::size_t k = 0; k < term.thermometers.size(); ++k) {
        if (k > 0) out += ',';
        out += thermometer_name(term.thermometers[k]);
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
      for (auto k : th) out.push_back({term.term, k, k, term.tau_s});
    }
  }
  return out;
}

std::vector<std::string> FeatureSpec::names() const {
  std::vector<std::string> out;
  for (const FeatureColumn& c : columns()) {
    const auto ta = thermometer_name(c.a), tb = thermometer_name(c.b);
    switch (c.term) {
      case FeatureTerm::temp:
        out.push_back(fmt::format("T_{}_degc", ta));
        break;
      case FeatureTerm::rate:
        out.push_back(fmt::format("dT_{}_degc_per_s", ta));
        break;
      case FeatureTerm::gradient:
        out.push_back(fmt::format("grad_{}_{}_degc", ta, tb));
        break;
      case FeatureTerm::gradient_rate:
        out.push_back(fmt::format("dgrad_{}_{}_degc_per_s", ta, tb));
        break;
      case FeatureTerm::time:
        out.push_back("t_s");
        break;
      case FeatureTerm::temp_rate_product:
        out.push_back(fmt::format("TdT_{}_degc2_per_s", ta));
        break;
      case FeatureTerm::lagged_rate:
        out.push_back(fmt::format("dT{}s_{}_degc_per_s", c.tau_s, ta));
        break;
    }
  }
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

std::vector<std::string> parse_thermometers(std::string_view text) {
  std::vector<std::string> out;
  for (std::string_view name : split_terms(text)) {
    if (name.empty()) throw OptionError("thermometers", fmt::format("'{}': an empty name", text));
    if (!is_thermometer_name(name))
      throw OptionError("thermometers",
                        fmt::format("'{}' is not a thermometer: fog, acc1, acc2, or NAME of a "
                                    "further column temp_NAME_degc (lower-case letters, digits "
                                    "and '_')",
                                    name));
    if (std::find(out.begin(), out.end(), name) != out.end())
      throw OptionError("thermometers", fmt::format("'{}' appears twice", name));
    out.emplace_back(name);
  }
  return out;
}

FeatureSpec default_feature_spec(const std::vector<std::string>& thermometers) {
  if (thermometers.empty()) throw OptionError("features", "no thermometer to build features from");
  const std::string list = fmt::format("{}", fmt::join(thermometers, ","));
  return FeatureSpec::parse(thermometers.size() == 1
                                ? fmt::format("T({0}),dT({0})", list)
                                : fmt::format("T({0}),dT({0}),grad({0})", list));
}

FeatureSpec recommended_feature_spec(const std::vector<std::string>& thermometers) {
  // The lag's list written out; to_string() drops it where it is fog, acc1, acc2.
  return FeatureSpec::parse(
      fmt::format("{},dT@{}({})", default_feature_spec(thermometers).to_string(), kRecommendedLagS,
                  fmt::join(thermometers, ",")),
      thermometers);
}

std::vector<std::string> thermometers_of(const Recording& recording) {
  std::vector<std::string> out = {"fog"};
  if (!recording.temp_acc1_degc.empty()) out.emplace_back("acc1");
  if (!recording.temp_acc2_degc.empty()) out.emplace_back("acc2");
  return out;
}

std::optional<std::string> further_thermometer_name(std::string_view column) {
  if (!column.starts_with("temp_") || !column.ends_with("_degc") || column.size() <= 10)
    return std::nullopt;
  const std::string_view name = column.substr(5, column.size() - 10);
  if (!is_thermometer_name(name) || std::find(kThermometerNames.begin(), kThermometerNames.end(),
                                              name) != kThermometerNames.end())
    return std::nullopt;
  return std::string(name);
}

std::vector<std::string> further_thermometers_of(const Recording& recording) {
  std::vector<std::string> out;
  for (const ExtraColumn& c : recording.extra)
    if (auto name = further_thermometer_name(c.name)) out.push_back(std::move(*name));
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

  // Each thermometer's column: the three by name, a further one from its extra column.
  const std::size_t nt = spec.thermometer_count();
  std::vector<const std::vector<double>*> temps = {
      &recording.temp_fog_degc, &recording.temp_acc1_degc, &recording.temp_acc2_degc};
  std::vector<std::vector<double>> further(spec.further.size());
  const std::vector<FeatureColumn> plan = spec.columns();
  for (std::size_t i = 0; i < nt; ++i) {
    const auto k = static_cast<Thermometer>(i);
    const std::string column = thermometer_column(spec.thermometer_name(k));
    if (i >= 3) {
      if (recording.has_column(column)) further[i - 3] = recording.numeric_column(column);
      temps.push_back(&further[i - 3]);
    }
    if (!temps[i]->empty() || k == Thermometer::fog) continue;
    for (const FeatureColumn& c : plan) {
      if (!c.reads(k)) continue;
      throw InputError(
          recording.source, 1, 0,
          fmt::format("has no {} column, which the feature {} reads (spec '{}'); a unit with "
                      "fewer thermometers trains on those it has, e.g. --features \"{}\" "
                      "(docs/logs.md)",
                      column, spec.names()[static_cast<std::size_t>(&c - plan.data())],
                      spec.to_string(),
                      default_feature_spec(thermometers_of(recording)).to_string()));
    }
  }
  // Rates only of the thermometers some input reads.
  std::vector<std::vector<double>> rates(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const auto k = static_cast<Thermometer>(i);
    if (std::any_of(plan.begin(), plan.end(),
                    [k](const FeatureColumn& c) { return c.reads_rate(k); }))
      rates[i] = signal::differentiate(*temps[i], dt, options.rates);
  }
  std::vector<std::vector<double>> columns(plan.size(), std::vector<double>(n));  // sample rate
  std::vector<double> temp(nt), rate(nt);
  for (std::size_t s = 0; s < n; ++s) {
    for (std::size_t i = 0; i < nt; ++i) {
      temp[i] = temps[i]->empty() ? 0.0 : (*temps[i])[s];  // an absent one is never read
      rate[i] = rates[i].empty() ? 0.0 : rates[i][s];
    }
    for (std::size_t c = 0; c < plan.size(); ++c)
      columns[c][s] = plan[c].value(temp, rate, recording.time_s[s]);
  }
  for (std::size_t c = 0; c < plan.size(); ++c) {
    if (!plan[c].lagged()) continue;
    LaggedRate lag(plan[c].tau_s, dt);
    const std::vector<double>& temp_c = *temps[static_cast<std::size_t>(plan[c].a)];
    for (std::size_t s = 0; s < n; ++s) columns[c][s] = lag.push(temp_c[s]);
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
