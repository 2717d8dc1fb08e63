// A protocol's chamber schedule and hours (chamber.hpp; docs/field.md, "Chamber hours").
#include "fogdrift/sim/chamber.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/sim/thermal_network.hpp"

namespace fogdrift::sim {
namespace {

constexpr double kWarmFirstRunS = 1800.0;  // the run before a warm restart (scenarios.cpp)
constexpr double kLongestSettleS = 7 * 86400.0;

// The instrument's thermal state through the chamber's steps, and the steps taken.
class Chamber {
 public:
  Chamber(const Instrument& instrument, const ChamberOptions& options)
      : network_(instrument.thermal), options_(options) {
    temps_.fill(options.start_degc);
    air_ = options.start_degc;
    // RK4 is stable well below 2.8 time constants; half the shortest keeps it accurate too.
    dt_s_ = std::min(10.0, 0.5 * network_.shortest_time_constant_s());
  }

  // Holds or ramps the air linearly from air_ to `to_degc` over `seconds`, powered or not.
  void run(double seconds, double to_degc, bool powered) {
    const double from = air_;
    const auto n = static_cast<long>(std::ceil(seconds / dt_s_));
    for (long k = 0; k < n; ++k) {
      const double a = from + (to_degc - from) * static_cast<double>(k) / static_cast<double>(n);
      const double b =
          from + (to_degc - from) * static_cast<double>(k + 1) / static_cast<double>(n);
      network_.step(temps_, seconds / static_cast<double>(n), a, b, powered);
    }
    air_ = to_degc;
  }

  // Unpowered at the air held, until every node is within the options' margin; seconds taken.
  double settle() {
    double t = 0;
    while (!settled()) {
      if (t >= kLongestSettleS)
        throw OptionError("settled_within_degc",
                          fmt::format("the instrument comes no closer than {:.3g} °C to the "
                                      "air in 7 days, longer than any chamber waits: check "
                                      "its thermal capacities and conductances, or give a "
                                      "larger margin",
                                      distance()));
      network_.step(temps_, dt_s_, air_, air_, false);
      t += dt_s_;
    }
    return t;
  }

  void add(int repetition, Approach approach, double set_point, const std::string& action,
           double from, double seconds) {
    if (seconds <= 0) return;
    schedule.steps.push_back({repetition, approach, set_point, action, from, air_, seconds});
  }

  double air() const { return air_; }

  ChamberSchedule schedule;

 private:
  double distance() const {
    double d = 0;
    for (double t : temps_) d = std::max(d, std::fabs(t - air_));
    return d;
  }
  bool settled() const { return distance() <= options_.settled_within_degc; }

  ThermalNetwork network_;
  ChamberOptions options_;
  NodeTemps temps_{};
  double air_ = 0;
  double dt_s_ = 10;
};

// The chamber to `to_degc` at its own ramp rate, unpowered.
void move(Chamber& c, int repetition, Approach approach, double set_point, double to_degc,
          const ChamberOptions& o) {
  const double from = c.air();
  const double seconds = std::fabs(to_degc - from) / o.chamber_ramp_degc_per_min * 60.0;
  c.run(seconds, to_degc, false);
  c.add(repetition, approach, set_point, "ramp", from, seconds);
}

void settle(Chamber& c, int repetition, Approach approach, double set_point) {
  const double at = c.air();
  c.add(repetition, approach, set_point, "settle", at, c.settle());
}

void hold(Chamber& c, int repetition, Approach approach, double set_point,
          const std::string& action, double seconds, bool powered) {
  const double at = c.air();
  c.run(seconds, at, powered);
  c.add(repetition, approach, set_point, action, at, seconds);
}

// A pass: one repetition's start-ups, and the warm repetition chained to a soaked one (0: none).
struct Pass {
  int repetition;
  Approach approach;
  int chained_warm;
};

}  // namespace

void validate(const ChamberOptions& o) {
  if (!(o.start_degc >= -70 && o.start_degc <= 100))
    throw OptionError("start_degc", fmt::format("{} °C is outside [-70, 100]", o.start_degc));
  if (!(o.chamber_ramp_degc_per_min > 0 && o.chamber_ramp_degc_per_min <= 100))
    throw OptionError("chamber_ramp_degc_per_min",
                      fmt::format("{} °C/min is outside (0, 100]", o.chamber_ramp_degc_per_min));
  if (!(o.settled_within_degc >= 0.001 && o.settled_within_degc <= 10))
    throw OptionError("settled_within_degc",
                      fmt::format("{} °C is outside [0.001, 10]", o.settled_within_degc));
}

double settle_seconds(const Instrument& instrument, double from_degc, double to_degc,
                      double within_degc) {
  ChamberOptions o;
  o.start_degc = from_degc;
  o.settled_within_degc = within_degc;
  validate(o);
  Chamber c(instrument, o);
  c.run(0, to_degc, false);  // the air jumps
  return c.settle();
}

ChamberSchedule chamber_schedule(const Instrument& instrument, const CalibrationOptions& p,
                                 const ChamberOptions& o) {
  validate(instrument);
  validate(p);
  validate(o);
  // A warm repetition rides on a soaked one when the soaked start-up's powered time is the warm
  // history's first run: each soaked repetition takes the first warm one not yet taken.
  std::vector<Pass> passes;
  std::vector<char> taken(static_cast<std::size_t>(p.repetitions) + 1, 0);
  const bool chain = o.chain_warm && p.powered_s == kWarmFirstRunS;
  for (int r = 1; r <= p.repetitions; ++r) {
    if (taken[static_cast<std::size_t>(r)]) continue;
    Pass pass{r, approach_of(p, r), 0};
    if (chain && pass.approach == Approach::soaked)
      for (int w = 1; w <= p.repetitions; ++w)
        if (approach_of(p, w) == Approach::warm && !taken[static_cast<std::size_t>(w)]) {
          pass.chained_warm = w;
          taken[static_cast<std::size_t>(w)] = 1;
          break;
        }
    passes.push_back(pass);
  }

  Chamber c(instrument, o);
  for (const Pass& pass : passes) {
    const int r = pass.repetition;
    const Approach a = pass.approach;
    std::vector<double> temps = temps_of(p, r);
    // Soaked and warm start-ups begin at equilibrium: either way round gives them their
    // history, so the pass starts at the end nearer the chamber.
    if ((a == Approach::soaked || a == Approach::warm) &&
        std::fabs(temps.back() - c.air()) < std::fabs(temps.front() - c.air()))
      std::reverse(temps.begin(), temps.end());
    switch (a) {
      case Approach::calibration:
      case Approach::sweep:
        move(c, 0, a, temps.front(), temps.front(), o);
        settle(c, r, a, temps.front());
        for (std::size_t i = 0; i < temps.size(); ++i) {
          hold(c, r, a, temps[i], "soak", p.soak_s, false);
          hold(c, r, a, temps[i], "powered (recorded)", p.powered_s, true);
          if (i + 1 < temps.size()) {
            const double from = c.air();
            c.run(p.ramp_s, temps[i + 1], false);
            c.add(r, a, temps[i], "ramp", from, p.ramp_s);
          }
        }
        break;
      case Approach::soaked:
      case Approach::warm:
        for (double t : temps) {
          move(c, t == temps.front() ? 0 : r, a, t, t, o);
          settle(c, r, a, t);
          if (a == Approach::warm) {
            hold(c, r, a, t, "powered", kWarmFirstRunS, true);
            hold(c, r, a, t, "off", p.warm_off_s, false);
          }
          hold(c, r, a, t, "powered (recorded)", p.powered_s, true);
          if (pass.chained_warm != 0) {
            hold(c, pass.chained_warm, Approach::warm, t, "off", p.warm_off_s, false);
            hold(c, pass.chained_warm, Approach::warm, t, "powered (recorded)", p.powered_s, true);
            ++c.schedule.chained_warm_start_ups;
          }
        }
        break;
      case Approach::ramping:
        for (double t : temps) {
          move(c, t == temps.front() ? 0 : r, a, t, t - kStepDegc, o);
          settle(c, r, a, t);
          // Powered while the air ramps up at the start-up's rate, then holds.
          const double ramp_s = kStepDegc / p.ramp_degc_per_min * 60.0;
          const double from = c.air();
          c.run(std::min(ramp_s, p.powered_s),
                from + kStepDegc * std::min(1.0, p.powered_s / ramp_s), true);
          if (p.powered_s > ramp_s) c.run(p.powered_s - ramp_s, c.air(), true);
          c.add(r, a, t, "powered (recorded)", from, p.powered_s);
        }
        break;
    }
  }

  ChamberSchedule& s = c.schedule;
  s.repetition_hours.assign(static_cast<std::size_t>(p.repetitions), 0.0);
  for (const ChamberStep& step : s.steps) {
    const double h = step.seconds / 3600.0;
    s.hours += h;
    if (step.repetition == 0) {
      s.move_hours += h;
      continue;
    }
    s.repetition_hours[static_cast<std::size_t>(step.repetition - 1)] += h;
    if (role_of(p, step.repetition) == Role::test) s.test_hours += h;
  }
  s.settle_10degc_s = settle_seconds(instrument, 0.0, kStepDegc, o.settled_within_degc);
  return s;
}

}  // namespace fogdrift::sim
