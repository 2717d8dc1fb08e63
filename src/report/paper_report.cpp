#include "fogdrift/report/paper_report.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fogdrift/base/version.hpp"
#include "fogdrift/eval/field.hpp"
#include "report/seed_stats.hpp"

namespace fogdrift::report {

MeanSd mean_sd(const std::vector<double>& values) {
  MeanSd r;
  if (values.empty()) return r;
  double s = 0;
  for (double v : values) s += v;
  r.mean = s / static_cast<double>(values.size());
  if (values.size() < 2) return r;
  double ss = 0;
  for (double v : values) ss += (v - r.mean) * (v - r.mean);
  r.sd = std::sqrt(ss / static_cast<double>(values.size() - 1));
  return r;
}

// Whether every seed has Table 3 with the true drift subtracted.
bool has_oracle(const PaperResult& r) {
  for (const SeedRun& s : r.seeds)
    if (s.oracle_rmse_deg.empty()) return false;
  return !r.seeds.empty();
}

PaperVerdict verdict(const PaperResult& r) {
  PaperVerdict v;
  const double ssa_std = over_seeds(r, [](const SeedRun& s) {
                           return s.method(Method::ssa_svr).table2.std_after_dph;
                         }).mean;
  const double denoised = over_seeds(r, [](const SeedRun& s) { return s.denoised_std_dph; }).mean;
  const double bp_std = over_seeds(r, [](const SeedRun& s) {
                          return s.method(Method::bp).table2.std_after_dph;
                        }).mean;
  v.std_ratio = ssa_std / denoised;
  for (const Method method : r.options.methods) {
    // The tuned SVRs run (a --methods list may leave PSO- and GWO-SVR out).
    if (method != Method::pso_svr && method != Method::gwo_svr && method != Method::ssa_svr)
      continue;
    const double std = over_seeds(r, [method](const SeedRun& s) {
                         return s.method(method).table2.std_after_dph;
                       }).mean;
    if (std > bp_std) v.tuned_worse_than_bp.emplace_back(to_string(method));
  }
  const double ssa_nf =
      over_seeds(r, [](const SeedRun& s) { return s.method(Method::ssa_svr).mean_rmse_deg; }).mean;
  const double raw_nf = over_seeds(r, [](const SeedRun& s) { return s.raw_mean_rmse_deg; }).mean;
  v.northfind_ratio = ssa_nf / raw_nf;
  v.stable_ratio = ssa_nf / over_seeds(r, [](const SeedRun& s) { return s.stable_rmse_deg; }).mean;
  const double floor_nf =
      has_oracle(r) ? over_seeds(r, [](const SeedRun& s) { return s.oracle_mean_rmse_deg; }).mean
                    : std::nan("");
  v.oracle_ratio = floor_nf / raw_nf;
  v.floor_ratio = ssa_nf / floor_nf;
  const std::vector<sim::Approach>& ups = r.options.start_ups;
  for (std::size_t a = 0; a < ups.size(); ++a) {
    const double raw =
        over_seeds(r, [a](const SeedRun& s) { return s.start_up_raw_rmse_deg[a]; }).mean;
    const double floor =
        over_seeds(r, [a](const SeedRun& s) { return s.start_up_floor_rmse_deg[a]; }).mean;
    for (const Method method : r.options.methods) {
      const std::string m = to_string(method);
      const double comp = over_seeds(r, [&](const SeedRun& s) {
                            return s.method(method).start_up_rmse_deg[a];
                          }).mean;
      if (comp > raw)
        v.worse_than_raw.push_back(fmt::format("{} under {}", m, sim::to_string(ups[a])));
      if (method == Method::ssa_svr) v.ssa_removed.push_back(eval::share_removed(raw, comp, floor));
    }
  }
  return v;
}

bool PaperVerdict::start_ups_removed_enough() const {
  return std::all_of(ssa_removed.begin(), ssa_removed.end(), [](double x) { return x >= 0.6; });
}

bool PaperVerdict::holds() const {
  return std_ratio <= 0.25 && tuned_worse_than_bp.empty() && stable_ratio <= 1.2 &&
         floor_ratio <= 1.15 && start_ups_removed_enough() && worse_than_raw.empty();
}

std::string paper_json(const PaperResult& r) {
  using json = nlohmann::ordered_json;
  json j;
  const MeanSd c =
      over_seeds(r, [](const SeedRun& s) { return s.method(Method::ssa_svr).hyperparameter("C"); });
  const MeanSd sg = over_seeds(
      r, [](const SeedRun& s) { return s.method(Method::ssa_svr).hyperparameter("sigma"); });
  j["table1"] = {{"C", c.mean}, {"C_sd", c.sd}, {"sigma", sg.mean}, {"sigma_sd", sg.sd}};

  json t2;
  const MeanSd den = over_seeds(r, [](const SeedRun& s) { return s.denoised_std_dph; });
  t2["denoised"] = {{"std_dph", den.mean}, {"std_dph_sd", den.sd}};
  for (const Method method : r.options.methods) {
    const std::string m = to_string(method);
    const MeanSd mae =
        over_seeds(r, [&](const SeedRun& s) { return s.method(method).table2.mae_dph; });
    const MeanSd sd =
        over_seeds(r, [&](const SeedRun& s) { return s.method(method).table2.std_after_dph; });
    t2[m] = {
        {"mae_dph", mae.mean}, {"mae_dph_sd", mae.sd}, {"std_dph", sd.mean}, {"std_dph_sd", sd.sd}};
  }
  j["table2"] = t2;

  json t3;
  t3["temps_degc"] = r.northfind_temps_degc;
  auto row = [&](auto per, auto mean) {
    json x;
    std::vector<double> m, sd;
    for (std::size_t k = 0; k < r.northfind_temps_degc.size(); ++k) {
      const MeanSd v = over_seeds(r, [&](const SeedRun& s) { return per(s)[k]; });
      m.push_back(v.mean);
      sd.push_back(v.sd);
    }
    const MeanSd mm = over_seeds(r, mean);
    x["rmse_deg"] = m;
    x["rmse_deg_sd"] = sd;
    x["mean_deg"] = mm.mean;
    x["mean_deg_sd"] = mm.sd;
    return x;
  };
  t3["raw"] = row([](const SeedRun& s) -> const std::vector<double>& { return s.raw_rmse_deg; },
                  [](const SeedRun& s) { return s.raw_mean_rmse_deg; });
  for (const Method method : r.options.methods) {
    const std::string m = to_string(method);
    t3[m] = row(
        [&](const SeedRun& s) -> const std::vector<double>& { return s.method(method).rmse_deg; },
        [&](const SeedRun& s) { return s.method(method).mean_rmse_deg; });
  }
  if (has_oracle(r))
    t3["oracle"] =
        row([](const SeedRun& s) -> const std::vector<double>& { return s.oracle_rmse_deg; },
            [](const SeedRun& s) { return s.oracle_mean_rmse_deg; });
  j["table3"] = t3;
  const MeanSd st = over_seeds(r, [](const SeedRun& s) { return s.stable_rmse_deg; });
  j["stable_rmse_deg"] = st.mean;
  j["stable_rmse_deg_sd"] = st.sd;
  j["seeds"] = r.seeds.size();
  j["elapsed_s"] = r.seconds;
  std::vector<std::uint64_t> seeds;
  for (const SeedRun& s : r.seeds) seeds.push_back(s.seed);
  j["seed_values"] = seeds;

  const PaperVerdict v = verdict(r);
  auto number = [](double x) { return std::isnan(x) ? json(nullptr) : json(x); };
  j["goals"] = {{"ssa_std_over_denoised", v.std_ratio},
                {"ssa_std_at_most_quarter", v.std_ratio <= 0.25},
                {"tuned_svr_no_worse_than_bp", v.tuned_worse_than_bp.empty()},
                {"tuned_svr_worse_than_bp", v.tuned_worse_than_bp},
                {"ssa_northfind_over_stable", v.stable_ratio},
                {"ssa_northfind_within_20pct_of_stable", v.stable_ratio <= 1.2},
                {"ssa_northfind_over_floor", number(v.floor_ratio)},
                {"ssa_northfind_within_15pct_of_floor", v.floor_ratio <= 1.15},
                {"ssa_northfind_over_raw", v.northfind_ratio},
                {"true_drift_subtracted_over_raw", number(v.oracle_ratio)},
                {"ssa_removed_by_start_up", json::object()},
                {"start_ups_removed_at_least_60pct", v.start_ups_removed_enough()},
                {"worse_than_raw", v.worse_than_raw},
                {"none_worse_than_raw", v.worse_than_raw.empty()},
                {"all_hold", v.holds()}};
  for (std::size_t a = 0; a < v.ssa_removed.size(); ++a)
    j["goals"]["ssa_removed_by_start_up"][std::string(sim::to_string(r.options.start_ups[a]))] =
        number(v.ssa_removed[a]);
  // The start-up conditions table: every method under every approach, mean over seeds.
  json su = json::object();
  for (std::size_t a = 0; a < r.options.start_ups.size(); ++a) {
    json x;
    x["raw_mean_deg"] =
        over_seeds(r, [a](const SeedRun& s) { return s.start_up_raw_rmse_deg[a]; }).mean;
    x["floor_mean_deg"] =
        number(over_seeds(r, [a](const SeedRun& s) { return s.start_up_floor_rmse_deg[a]; }).mean);
    for (const Method method : r.options.methods) {
      const std::string m = to_string(method);
      x[m] = {
          {"mean_deg",
           over_seeds(r, [&](const SeedRun& s) { return s.method(method).start_up_rmse_deg[a]; })
               .mean},
          {"unguarded_mean_deg",
           over_seeds(
               r, [&](const SeedRun& s) { return s.method(method).start_up_unguarded_rmse_deg[a]; })
               .mean},
          {"drift_error_removed", number(over_seeds(r, [&](const SeedRun& s) {
                                           return s.method(method).start_up_drift_error_removed[a];
                                         }).mean)}};
    }
    if (!r.seeds.front().causal_start_up_rmse_deg.empty())
      x["ssa-svr-causal"] = {
          {"mean_deg",
           over_seeds(r, [a](const SeedRun& s) { return s.causal_start_up_rmse_deg[a]; }).mean},
          {"unguarded_mean_deg",
           over_seeds(r, [a](const SeedRun& s) { return s.causal_start_up_unguarded_rmse_deg[a]; })
               .mean},
          {"drift_error_removed", number(over_seeds(r, [a](const SeedRun& s) {
                                           return s.causal_start_up_drift_error_removed[a];
                                         }).mean)}};
    su[std::string(sim::to_string(r.options.start_ups[a]))] = x;
  }
  j["start_ups"] = su;

  json studies;
  studies["loto"] = json::array();
  for (const LotoRow& l : r.loto) {
    studies["loto"].push_back({{"temp_degc", l.temp_degc},
                               {"method", to_string(l.method)},
                               {"denoised_std_dph", l.denoised_std_dph},
                               {"std_all_dph", l.std_all_dph},
                               {"std_left_out_dph", l.std_loto_dph},
                               {"mae_all_dph", l.mae_all_dph},
                               {"mae_left_out_dph", l.mae_loto_dph}});
  }
  studies["fitness"] = json::array();
  for (const FitnessRow& f : r.fitness) {
    studies["fitness"].push_back({{"fitness", tune::to_string(f.fitness)},
                                  {"C", f.c},
                                  {"sigma", f.sigma},
                                  {"fitness_value", f.fitness_value},
                                  {"std_dph", f.std_dph},
                                  {"mae_dph", f.mae_dph},
                                  {"northfind_mean_deg", f.mean_rmse_deg}});
  }
  j["studies"] = studies;

  const PaperOptions& o = r.options;
  j["settings"] = {{"first_seed", o.first_seed},
                   {"population", o.population},
                   {"iterations", o.iterations},
                   {"fitness", std::string(tune::to_string(o.fitness))},
                   {"cv", std::string(tune::to_string(o.cv.scheme))},
                   {"folds", o.cv.folds},
                   {"epsilon", o.search_epsilon ? nlohmann::ordered_json(nullptr)
                                                : nlohmann::ordered_json(o.epsilon)},
                   {"search_epsilon", o.search_epsilon},
                   {"northfind_approach", std::string(sim::to_string(o.northfind.approach))},
                   {"studies", o.studies},
                   {"fogdrift_version", kVersion}};
  json per = json::array();
  for (const SeedRun& s : r.seeds) {
    json x;
    x["seed"] = s.seed;
    x["denoised_std_dph"] = s.denoised_std_dph;
    x["raw_mean_rmse_deg"] = s.raw_mean_rmse_deg;
    if (!s.oracle_rmse_deg.empty()) x["oracle_mean_rmse_deg"] = s.oracle_mean_rmse_deg;
    x["stable_rmse_deg"] = s.stable_rmse_deg;
    for (const MethodRun& m : s.methods) {
      json h;
      for (const auto& [n, val] : m.hyperparameters) h[n] = val;
      x["methods"][to_string(m.method)] = {{"std_dph", m.table2.std_after_dph},
                                           {"mae_dph", m.table2.mae_dph},
                                           {"mean_rmse_deg", m.mean_rmse_deg},
                                           {"fitness_value", m.fitness_value},
                                           {"hyperparameters", h},
                                           {"train_s", m.train_seconds}};
    }
    x["elapsed_s"] = s.seconds;
    per.push_back(x);
  }
  j["per_seed"] = per;
  return j.dump(2) + "\n";
}

}  // namespace fogdrift::report
