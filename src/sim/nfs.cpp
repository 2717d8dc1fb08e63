#include "fogdrift/sim/nfs.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/sim/accelerometer.hpp"
#include "fogdrift/sim/fog_error_model.hpp"

namespace fogdrift::sim {
namespace {

constexpr std::array<Node, 3> kThermometerNode = {Node::coil_outer, Node::acc1, Node::acc2};
using ThermometerOf = const ThermometerParams* (*)(const Instrument&);
constexpr std::array<ThermometerOf, 3> kThermometers = {
    [](const Instrument& in) { return &in.thermometer_fog; },
    [](const Instrument& in) { return &in.thermometer_acc1; },
    [](const Instrument& in) { return &in.thermometer_acc2; }};

double coil_mean_degc(const NodeTemps& t) {
  return 0.5 * (t[node_index(Node::coil_inner)] + t[node_index(Node::coil_outer)]);
}

// `value` rounded to a multiple of `step`, computed so that 0.01-type steps print exactly
// ("-39.73", not "-39.730000000000004"): divide by 1/step when that is a whole number.
double round_to(double value, double step) {
  if (step <= 0.0) return value;
  const double k = std::round(value / step);
  const double inverse = std::round(1.0 / step);
  if (inverse >= 1.0 && std::abs(inverse * step - 1.0) < 1e-12) return k / inverse;
  return k * step;
}

double read_thermometer(const ThermometerParams& p, double lagged_degc, Rng& rng) {
  return round_to(lagged_degc + p.offset_degc + p.noise_degc * rng.normal(), p.resolution_degc);
}

// Logger resolutions of the channels the instrument file does not quantise.
constexpr double kAccelResolutionG = 1e-8;
constexpr double kChamberResolutionDegc = 1e-3;
constexpr double kTableResolutionDeg = 1e-6;

// Number of fine steps in one output interval; the interval must be a whole number of steps.
// An interval shorter than the fine step (a kilohertz logger over the default 0.1 s step) is one
// step: the integration is then finer than asked, never coarser.
int substeps(double interval_s, double fine_step_s) {
  const double ratio = interval_s / fine_step_s;
  if (ratio <= 1.0) return 1;
  const double whole = std::round(ratio);
  if (std::abs(ratio - whole) > 1e-6 * ratio) {
    throw OptionError("output_rate_hz",
                      fmt::format("the output interval {} s is not a whole number of fine steps "
                                  "of {} s (instrument.fog.fine_step_s)",
                                  interval_s, fine_step_s));
  }
  return static_cast<int>(whole);
}

}  // namespace

NfsSimulator::NfsSimulator(const Instrument& instrument, const NodeTemps& initial, double time_s)
    : instrument_(instrument), network_(instrument.thermal), temps_(initial), time_s_(time_s) {
  validate(instrument_);
  for (int i = 0; i < 3; ++i) thermometer_state_degc_[i] = read_node(i);
  filtered_coil_degc_ = coil_mean_degc(temps_);
}

double NfsSimulator::read_node(int thermometer) const {
  const ThermometerParams& p = *kThermometers[thermometer](instrument_);
  const double node = temps_[node_index(kThermometerNode[thermometer])];
  if (p.housing_share == 0.0) return node;
  return (1.0 - p.housing_share) * node + p.housing_share * temps_[node_index(Node::housing)];
}

void NfsSimulator::step(double dt, const AirProfile& air, bool powered, const NodeTemps* rate) {
  if (rate) {
    network_.step(temps_, dt, air(time_s_), air(time_s_ + dt), powered, *rate);
  } else {
    network_.step(temps_, dt, air(time_s_), air(time_s_ + dt), powered);
  }
  // The lags' step responses for this dt, computed once per dt (every step of a run shares it).
  if (dt != lag_dt_s_) {
    for (int i = 0; i < 3; ++i) {
      const double lag = kThermometers[i](instrument_)->lag_s;
      lag_gain_[i] = lag > 0.0 ? 1.0 - std::exp(-dt / lag) : 1.0;
    }
    lag_gain_[3] = 1.0 - std::exp(-dt / instrument_.fog.filtered_rate_tau_s);
    lag_dt_s_ = dt;
  }
  for (int i = 0; i < 3; ++i)
    thermometer_state_degc_[i] += lag_gain_[i] * (read_node(i) - thermometer_state_degc_[i]);
  filtered_coil_degc_ += lag_gain_[3] * (coil_mean_degc(temps_) - filtered_coil_degc_);
  time_s_ += dt;
}

void NfsSimulator::advance(double duration_s, const AirProfile& air, bool powered) {
  if (duration_s <= 0.0) return;
  const double fine = instrument_.fog.fine_step_s;
  const long steps = std::max(1L, static_cast<long>(std::ceil(duration_s / fine - 1e-9)));
  const double dt = duration_s / static_cast<double>(steps);
  for (long s = 0; s < steps; ++s) step(dt, air, powered);
}

Recording NfsSimulator::record(const RecordSetup& setup, const AirProfile& air,
                               double power_on_time_s) {
  if (!(setup.output_rate_hz > 0.0) || !std::isfinite(setup.output_rate_hz)) {
    throw OptionError("output_rate_hz",
                      fmt::format("{} must be a positive rate", setup.output_rate_hz));
  }
  const double interval = 1.0 / setup.output_rate_hz;
  const int n_sub = substeps(interval, instrument_.fog.fine_step_s);
  const double dt = interval / n_sub;
  const long n_out = std::lround(setup.duration_s * setup.output_rate_hz);
  if (n_out < 2) throw OptionError("duration", "a recording needs at least 2 samples");

  const FogParams& fog = instrument_.fog;
  Rng bias_rng(derive_seed(setup.seed, 1));
  const double turn_on_bias_dph = fog.bias_dph + fog.bias_run_to_run_dph * bias_rng.normal();
  FogNoise noise(fog, derive_seed(setup.seed, 2));
  Rng sensor_rng(derive_seed(setup.seed, 3));
  const Vec3 earth = earth_rate_enu_dph(setup.latitude_deg);

  Recording rec;
  for (auto* col :
       {&rec.time_s, &rec.gyro_dph, &rec.temp_fog_degc, &rec.temp_acc1_degc, &rec.temp_acc2_degc}) {
    col->reserve(n_out);
  }
  rec.accel_x_g.emplace();
  rec.accel_y_g.emplace();
  rec.table_deg.emplace();
  rec.chamber_degc.emplace();
  ExtraColumn truth{"drift_true_dph", {}};

  const double start = time_s_;
  for (long k = 0; k < n_out; ++k) {
    double angle_arcsec = 0.0;
    double drift_integral = 0.0;
    for (int j = 0; j < n_sub; ++j) {
      const double t_rel = (time_s_ - start) + 0.5 * dt;  // mid-step, relative to the recording
      const NodeTemps rate = network_.derivative(temps_, air(time_s_), true);
      const double coil_mean = coil_mean_degc(temps_);
      const double coil_rate =
          0.5 * (rate[node_index(Node::coil_inner)] + rate[node_index(Node::coil_outer)]);
      const double gradient_rate =
          rate[node_index(Node::coil_inner)] - rate[node_index(Node::coil_outer)];
      // ds/dt of the low-passed coil mean s: (T̄ − s)/τ_F.
      const HiddenState hidden{(coil_mean - filtered_coil_degc_) / fog.filtered_rate_tau_s,
                               temps_[node_index(Node::electronics)]};
      const double drift =
          thermal_drift(fog, coil_mean, coil_rate, gradient_rate, hidden).total_dph();
      const double input = dot(earth, setup.platform.body_x(setup.table.angle_deg(t_rel)));
      angle_arcsec += (input + turn_on_bias_dph + drift) * dt + noise.angle_increment_arcsec(dt);
      drift_integral += drift * dt;
      step(dt, air, true, &rate);
    }
    const double t_rel = time_s_ - start;
    const double table = setup.table.angle_deg(t_rel);
    // Stamps from the sample count, not the accumulated steps, so they print as 1, 2, 3 ...
    const double stamp = (start - power_on_time_s) + static_cast<double>(k + 1) * interval;
    rec.time_s.push_back(std::round(stamp * 1e9) / 1e9);
    // The output is a whole number of quanta per interval; round away the product's last bits.
    rec.gyro_dph.push_back(round_to(noise.quantize_arcsec(angle_arcsec) / interval, 1e-9));
    rec.temp_fog_degc.push_back(
        read_thermometer(instrument_.thermometer_fog, thermometer_state_degc_[0], sensor_rng));
    rec.temp_acc1_degc.push_back(
        read_thermometer(instrument_.thermometer_acc1, thermometer_state_degc_[1], sensor_rng));
    rec.temp_acc2_degc.push_back(
        read_thermometer(instrument_.thermometer_acc2, thermometer_state_degc_[2], sensor_rng));
    rec.accel_x_g->push_back(
        round_to(accelerometer_output_g(instrument_.accel_x, setup.platform.body_x(table),
                                        temps_[node_index(Node::acc1)], sensor_rng),
                 kAccelResolutionG));
    rec.accel_y_g->push_back(
        round_to(accelerometer_output_g(instrument_.accel_y, setup.platform.body_y(table),
                                        temps_[node_index(Node::acc2)], sensor_rng),
                 kAccelResolutionG));
    double wrapped = std::fmod(table, 360.0);
    if (wrapped < 0.0) wrapped += 360.0;
    rec.table_deg->push_back(round_to(wrapped, kTableResolutionDeg));
    rec.chamber_degc->push_back(round_to(air(time_s_), kChamberResolutionDegc));
    if (setup.write_true_drift)
      truth.cells.push_back(fmt::format("{:.9g}", drift_integral / interval));
  }
  if (setup.write_true_drift) rec.extra.push_back(std::move(truth));
  return rec;
}

}  // namespace fogdrift::sim
