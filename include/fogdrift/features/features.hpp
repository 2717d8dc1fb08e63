// The model input x built from the instrument's thermometers (docs/method.md §2 step 2, the
// paper's eq. 3: temperature, temperature rate and gradient terms), and the preprocessing that
// turns a 1 Hz recording into modelling rows.
//
// A FeatureSpec is written as a short text, stored in every model:
//   "T,dT,grad"                  the paper's 9 inputs: T_k, dT_k/dt and T_i - T_j of all three
//   "T(fog),dT(fog,acc1),grad"   a term may name its thermometers: fog, acc1, acc2
//   "T(fog,acc1,acc2,case),dT,grad"  or a further one, NAME of a column temp_NAME_degc
// Terms: T (temperature, °C), dT (rate, °C/s), grad (T_i - T_j for every pair i < j of the
// term's thermometers, °C), dgrad (rate of that gradient, °C/s; the eq. 3 term d(grad T)/dt),
// t (time since power-on, s), TdT (T_k times dT_k/dt, °C²/s), dT@τ (the rate through a
// first-order lag of τ seconds, °C/s: LaggedRate; "dT@600(fog)"; several τ may be named). A term
// without a list reads the three (fog, acc1, acc2), or the list parse() is given (train
// --thermometers).
//
// Thermometers are numbered: fog, acc1, acc2 are 0, 1, 2, and further ones 3, 4, … in the
// order the spec first names them (FeatureSpec::further); a term's list is kept in that order.
//
// Preprocessing of one recording (compute_features):
//   1. rates dT_k/dt at the recording's rate with the differentiator (signal/differentiate.hpp);
//   2. every feature column at the recording's rate;
//   3. block means over block_s (signal/resample.hpp); the trailing partial block is dropped.
// The recording must be uniformly sampled (every interval within 1 % of the median interval).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/io/recording.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/signal/resample.hpp"

namespace fogdrift {

/// A thermometer by number: the three every model knows by name, and further ones, Thermometer(3
/// + i) for FeatureSpec::further[i] (docs/logs.md, "More thermometers").
enum class Thermometer : std::uint8_t { fog, acc1, acc2 };
enum class FeatureTerm {
  temp,
  rate,
  gradient,
  gradient_rate,
  time,
  temp_rate_product,
  lagged_rate
};

/// "T", "dT", "grad", "dgrad", "t", "TdT", "dT@" (written with its time constant: dT@600).
std::string_view to_string(FeatureTerm term);

/// The recording column thermometer NAME is read from: temp_NAME_degc ("temp_fog_degc", ...).
std::string thermometer_column(std::string_view name);

/// Whether `name` may name a thermometer: fog, acc1, acc2, or a further one, the NAME of a
/// channel temp_NAME_degc (recording.hpp is_channel_column: lower-case letters, digits and '_')
/// that starts with a letter.
bool is_thermometer_name(std::string_view name);

struct FeatureTermSpec {
  FeatureTerm term = FeatureTerm::temp;
  std::vector<Thermometer> thermometers;  ///< in number order; unused for t
  double tau_s = 0;                       ///< the lag's time constant of dT@τ, s; else 0
};

/// The rate of a temperature seen through a first-order lag of time constant tau_s (the term
/// dT@τ, docs/field.md, "A rate through a lag"): the lag's state s follows the temperature,
/// s += (1 − e^(−dt/τ))·(T − s), and the term is ds/dt = (T − s)/τ, °C/s: the temperature's
/// rate low-passed at τ. The state starts at the first reading (the unit at rest at power-on),
/// so the term starts at 0. The batch features, the streaming compensator and the C header
/// run this one recursion.
class LaggedRate {
 public:
  LaggedRate(double tau_s, double dt_s);
  /// Pushes one reading, °C; returns the term, °C/s.
  double push(double temp_degc) noexcept {
    if (!started_) {
      state_degc_ = temp_degc;
      started_ = true;
    }
    state_degc_ += gain_ * (temp_degc - state_degc_);
    return (temp_degc - state_degc_) / tau_s_;
  }
  void reset() noexcept { started_ = false; }
  double gain() const noexcept { return gain_; }

 private:
  double tau_s_, gain_, state_degc_ = 0;
  bool started_ = false;
};

/// One model input as an operation on a sample's temperatures, their rates and its time: the
/// term and the thermometer it reads (`b` too for the two gradient terms, a − b).
struct FeatureColumn {
  FeatureTerm term = FeatureTerm::temp;
  Thermometer a = Thermometer::fog, b = Thermometer::fog;
  double tau_s = 0;  ///< dT@τ's time constant, s

  /// Whether its value is a state carried from sample to sample (dT@τ, LaggedRate), which
  /// value() cannot give: the caller runs a LaggedRate on thermometer a per such column.
  bool lagged() const noexcept { return term == FeatureTerm::lagged_rate; }

  /// Its value for one sample; temperatures and rates are indexed by Thermometer, one per
  /// thermometer of the spec (FeatureSpec::thermometer_count).
  double value(std::span<const double> temp_degc, std::span<const double> rate_degc_per_s,
               double time_s) const noexcept {
    const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
    switch (term) {
      case FeatureTerm::temp:
        return temp_degc[i];
      case FeatureTerm::rate:
        return rate_degc_per_s[i];
      case FeatureTerm::gradient:
        return temp_degc[i] - temp_degc[j];
      case FeatureTerm::gradient_rate:
        return rate_degc_per_s[i] - rate_degc_per_s[j];
      case FeatureTerm::time:
        return time_s;
      case FeatureTerm::temp_rate_product:
        return temp_degc[i] * rate_degc_per_s[i];
      case FeatureTerm::lagged_rate:
        break;  // a state: see lagged()
    }
    return 0.0;
  }
  /// Whether it reads thermometer `k` at all (its temperature or its rate).
  bool reads(Thermometer k) const noexcept {
    if (term == FeatureTerm::time) return false;
    const bool two = term == FeatureTerm::gradient || term == FeatureTerm::gradient_rate;
    return a == k || (two && b == k);
  }
  /// Whether it reads the rate of any thermometer: an input the differentiator's warm-up
  /// disturbs (docs/field.md, "The guard at power-on").
  bool reads_rate() const noexcept {
    return term == FeatureTerm::rate || term == FeatureTerm::gradient_rate ||
           term == FeatureTerm::temp_rate_product;
  }
  /// Whether it reads the rate of thermometer `k`.
  bool reads_rate(Thermometer k) const noexcept {
    return (term == FeatureTerm::rate || term == FeatureTerm::temp_rate_product) ? a == k
           : term == FeatureTerm::gradient_rate ? (a == k || b == k)
                                                : false;
  }
};

struct FeatureSpec {
  std::vector<FeatureTermSpec> terms;
  /// Names of the further thermometers, Thermometer(3), Thermometer(4), …: each read from its
  /// column temp_NAME_degc.
  std::vector<std::string> further;

  /// Parses the text form; a term without a list reads `thermometers` (empty: fog, acc1,
  /// acc2). Throws OptionError("features", ...) naming the bad term or thermometer, a repeated
  /// term, a gradient term with fewer than two thermometers, or an empty spec.
  static FeatureSpec parse(std::string_view text,
                           const std::vector<std::string>& thermometers = {});
  /// The canonical text form: parse(to_string()) gives the same spec; thermometer lists are
  /// written only when they are not fog, acc1, acc2.
  std::string to_string() const;
  /// One name per model input, with its unit: T_fog_degc, dT_acc1_degc_per_s,
  /// grad_fog_acc1_degc, dgrad_fog_acc2_degc_per_s, t_s, TdT_fog_degc2_per_s,
  /// dT600s_fog_degc_per_s (dT@600).
  std::vector<std::string> names() const;
  std::size_t size() const { return columns().size(); }
  /// The model inputs in order, as operations on one sample: the one description of what each
  /// input is, shared by compute_features(), the streaming compensator and the C header.
  std::vector<FeatureColumn> columns() const;
  /// Thermometers numbered in this spec: 3 + further.size() (some of the three may be unread).
  std::size_t thermometer_count() const { return 3 + further.size(); }
  /// The name of thermometer `k`: fog, acc1, acc2 or further[k − 3].
  std::string_view thermometer_name(Thermometer k) const;
  /// The recording column of each thermometer, in number order: temp_fog_degc,
  /// temp_acc1_degc, temp_acc2_degc, then temp_NAME_degc of each further one.
  std::vector<std::string> thermometer_columns() const;
  /// Whether some input reads thermometer `k` (a unit without it cannot use the spec).
  bool reads(Thermometer k) const;
  /// Per input, whether it reads a temperature rate (FeatureColumn::reads_rate).
  std::vector<bool> rate_inputs() const;
};

/// A comma-separated list of thermometer names (train --thermometers), each fog, acc1, acc2 or
/// a further NAME, none twice. Throws OptionError("thermometers", ...) naming the bad one.
std::vector<std::string> parse_thermometers(std::string_view text);

/// The paper's inputs, "T,dT,grad" (9 features).
FeatureSpec default_feature_spec();

/// The paper's inputs over the thermometers named (docs/logs.md, "Fewer thermometers", "More
/// thermometers"): fog, acc1, acc2: "T,dT,grad"; any other list of two or more:
/// "T(list),dT(list),grad(list)"; one: "T(a),dT(a)". Throws OptionError("features", ...) for an
/// empty list or a name that cannot name a thermometer.
FeatureSpec default_feature_spec(const std::vector<std::string>& thermometers);

/// The lag of train's recommended features, s (docs/field.md, "A rate through a lag").
inline constexpr double kRecommendedLagS = 300;

/// train's features when none are given: the paper's inputs over the thermometers named
/// (default_feature_spec) and their rates through a lag of kRecommendedLagS: "T,dT,grad,dT@300"
/// over fog, acc1, acc2; "T(a),dT(a),dT@300(a)" over one. Chosen on a population of instruments
/// (docs/field.md, "A rate through a lag"); `fogdrift paper` keeps the paper's own inputs.
FeatureSpec recommended_feature_spec(const std::vector<std::string>& thermometers);

/// Those of fog, acc1, acc2 `recording` has, in that order (fog always).
std::vector<std::string> thermometers_of(const Recording& recording);

/// NAME when `column` is temp_NAME_degc of a further thermometer (not fog, acc1 or acc2).
std::optional<std::string> further_thermometer_name(std::string_view column);

/// The further thermometers `recording` has: NAME of each column temp_NAME_degc, in the file's
/// order (docs/logs.md, "More thermometers").
std::vector<std::string> further_thermometers_of(const Recording& recording);

/// How a recording becomes modelling rows.
struct FeatureOptions {
  signal::DifferentiatorOptions rates;  ///< temperature differentiator (default centred, 121 s)
  signal::BlockAverageOptions block;    ///< block averaging (default 10 s)
  /// The interval of the recordings the features were formed at, s (set by preprocessing_for);
  /// faster data are brought to it before compensation (decimate.hpp). 0: not recorded, and a
  /// model runs at the data's own interval, as model files before it did.
  double sample_interval_s = 0;
};

/// The default preprocessing fitted to recordings sampled every dt_s seconds, the shortest of
/// which has shortest_samples samples (docs/logs.md, "Slow or short logs"):
///   block_s   10 s when that is a whole number of samples; else the whole number of samples
///             nearest 10 s, at least one (a log slower than 0.1 Hz is not averaged further);
///   window_s  the recommended window for the base's causality (signal::recommended_rates:
///             121 s centred, 61 s causal) when that spans at least 5 samples, else 5 samples;
///             for the centred differentiator no longer than the shortest recording (its
///             largest odd number of samples, at least 5: a shorter recording still fails,
///             naming window_s);
///   poly_order  the recommended degree for that causality (2 centred, 1 causal);
///   sample_interval_s  dt_s.
/// The differentiator's causality is kept from `base`, and everything else.
FeatureOptions preprocessing_for(double dt_s, std::size_t shortest_samples,
                                 const FeatureOptions& base = {});

/// Feature rows of one recording, at the block rate.
struct FeatureTable {
  std::vector<std::string> names;
  std::size_t rows = 0;
  std::vector<double> x;       ///< rows x names.size(), row-major
  std::vector<double> time_s;  ///< block-centre time since power-on, s
  std::size_t block = 1;       ///< samples per block
  /// Leading rows holding a sample whose rates the causal differentiator took from fewer than
  /// W samples (signal::warmup_samples); 0 with the centred differentiator.
  std::size_t warm_rows = 0;
};

/// The median sample interval of `recording`, after checking that every interval is within 1 %
/// of it; throws InputError naming the recording and the line of the first irregular sample.
double sample_interval_s(const Recording& recording);

/// Features of `recording` (see the file comment). Throws InputError naming the recording when it
/// is too short for the differentiator window or for one block, or not uniformly sampled.
FeatureTable compute_features(const Recording& recording, const FeatureSpec& spec,
                              const FeatureOptions& options = {});

}  // namespace fogdrift
