// The causal streaming compensator of the C header (c_parts.hpp, compensator.hpp): the model's
// part written here around the streaming step's C code, src/stream/step_state.h and step.h, the
// code the library runs too.
#include "firmware/c_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/c_text.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift::detail {
namespace {

/// The temperature arguments a model reads, e.g. "temp_fog_degc" (docs/logs.md, "Fewer
/// thermometers").
std::string thermometers_read(const CompensationModel& model) {
  const FeatureSpec& spec = model.dataset.features;
  const std::vector<std::string> columns = spec.thermometer_columns();
  std::vector<std::string> read;
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (spec.reads(static_cast<Thermometer>(k))) read.push_back(columns[k]);
  return read.empty() ? std::string("none") : fmt::format("{}", fmt::join(read, ", "));
}

// kStepStateC and kStepC: src/stream/step_state.h and step.h, embedded at build time.
#include "c_step.inc"
#include "c_step_state.inc"

/// The step's code with its names fds_ and FDS_ given the header's prefix: every identifier that
/// starts with them, in code and comments alike. Its state first, then its functions.
constexpr std::string_view kCodeStarts = "/* fogdrift: the header's code starts here. */\n";
static_assert(kStepStateC.find(kCodeStarts) != std::string_view::npos,
              "src/stream/step_state.h lost the line its embedded code starts after");
static_assert(kStepC.find(kCodeStarts) != std::string_view::npos,
              "src/stream/step.h lost the line its embedded code starts after");

std::string renamed_compensator(const std::string& prefix, const std::string& upper) {
  const auto after_start = [](std::string_view file) {
    return file.substr(file.find(kCodeStarts) + kCodeStarts.size());
  };
  const std::string code =
      std::string(after_start(kStepStateC)) + "\n" + std::string(after_start(kStepC));
  const auto identifier = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  std::string out;
  for (std::size_t i = 0; i < code.size(); ++i) {
    const bool start = i == 0 || !identifier(code[i - 1]);
    if (start && code.substr(i, 4) == "fds_") {
      out += prefix + "_";
      i += 3;
    } else if (start && code.substr(i, 4) == "FDS_") {
      out += upper + "_";
      i += 3;
    } else {
      out += code[i];
    }
  }
  return out;
}

// The header's streaming part, around the compensator's code: the user's guide, the model's
// constants and tables the code reads (src/stream/step.h lists them), the features in
// compute_features()'s order, and the entry points under the names of the model's
// thermometers and target.
constexpr std::string_view kStreamingC =
    R"(/* Streaming: samples every @DATA_DT@ s in, the features computed causally every @DT@ s.
 *   @P@_state s; @P@_reset(&s);   at power-on
 *   drift_@UNIT@ = @P@_update(&s, time_s, @TEMP_ARGS@);
 *   @READING_COMP@ = @P@_compensated_@UNIT@(&s, @READING@);
 *   s.flags: what was wrong with the sample (@U@_FAULT_* bits, 0 for a good sample).
 * Temperature rates: causal Savitzky-Golay derivative over the last @W@ samples (during the
 * first @W@, the samples before power-on taken equal to the first, as if the unit had been at
 * rest); the taps for k + 1 samples start at k(k + 1)/2 in the table.
 * Thermometers this model reads: @READS@; pass anything for the others.@NOTE@
 * Sensor faults (fogdrift docs/compensation.md, "Sensor faults"): a thermometer reading that is
 * not a number, outside [@U@_TEMP_MIN_DEGC, @U@_TEMP_MAX_DEGC], more than @U@_TEMP_JUMP_DEGC
 * from its last good reading continued along its rate, or stuck is continued along its
 * last rate for up to @U@_BRIDGE_S, and so is a time gap; beyond that the drift is held at its
 * last good value until the rate window has refilled, and after @U@_HOLD_S the correction stops
 * (the mean drift). A sample whose time does not advance is skipped; time going back by more
 * than @U@_BRIDGE_S starts again as at power-on. The drift is always a finite number. */
#define @U@_RATE_WINDOW @W@
@GUARD_DEFINE@#ifndef @U@_TEMP_MIN_DEGC
#define @U@_TEMP_MIN_DEGC (@TEMP_MIN@)
#endif
#ifndef @U@_TEMP_MAX_DEGC
#define @U@_TEMP_MAX_DEGC (@TEMP_MAX@)
#endif
#ifndef @U@_@LIMIT@
#define @U@_@LIMIT@ (@GYRO_LIMIT@)
#endif
#define @U@_READING_LIMIT @U@_@LIMIT@
#ifndef @U@_BRIDGE_S
#define @U@_BRIDGE_S (@BRIDGE@)
#endif
#ifndef @U@_HOLD_S
#define @U@_HOLD_S (@HOLD@)
#endif
#ifndef @U@_STUCK_S
#define @U@_STUCK_S (@STUCK@) /* 0: no stuck check */
#endif
#ifndef @U@_STUCK_DELTA_DEGC
#define @U@_STUCK_DELTA_DEGC (@STUCK_DELTA@)
#endif
#ifndef @U@_TEMP_JUMP_DEGC
#define @U@_TEMP_JUMP_DEGC (@TEMP_JUMP@) /* 0: no jump check */
#endif
@FLAGS@
#define @U@_INTERVAL_TOLERANCE (@INTERVAL_TOLERANCE@) /* a step within it of the interval is one */
#define @U@_BLOCK @BLOCK@ /* samples per model sample */
static const double @P@_data_dt_s = @DATA_DT@;
static const double @P@_dt_s = @DT@;
#define @U@_N_THERMOMETERS @NT@ /* @THERMOMETERS@ */
static const int @P@_reads[@U@_N_THERMOMETERS] = {@READ_FLAGS@};
static const @REAL@ @P@_rate_taps[@NTAPS@] = {@TAPS@};
@LAG_TABLES@#define @U@_DRIFT_MEAN @P@_drift_mean_@UNIT@
#define @U@_DRIFT_LIMIT ((@REAL@)@DRIFT_LIMIT@) /* kDriftLimitScales drift scales */
#define @U@_FABS fabs@F@
#define @U@_DIFFERENCE_FROM_NEWEST @FROM_NEWEST@

/* The model's inputs from the thermometers' temperatures and rates at time t. */
static inline void @P@_features_(const @REAL@ temp[@U@_N_THERMOMETERS],
                                 const @REAL@ rate[@U@_N_THERMOMETERS], double t,
                                 const @REAL@* lag_rate, @REAL@ f[@U@_N_FEATURES]) {
  (void)temp;
  (void)rate;
  (void)t;
  (void)lag_rate;
@FEATURES@}

static inline @REAL@ @P@_predict_(const @REAL@ f[@U@_N_FEATURES]) {
  return @P@_predict_@UNIT@(f);
}

@COMPENSATOR@
/* Predicted drift, @UNIT_TEXT@, for the newest sample (every @P@_data_dt_s seconds since power-on):
 * the thermometers averaged over blocks of @U@_BLOCK samples, the first sample a block of its
 * own, and the model run once per block (fogdrift docs/compensation.md, "Any sample rate"). */
static inline @REAL@ @P@_update(@P@_state* s, double time_s, @TEMP_PARAMS@) {
  const @REAL@ raw[@U@_N_THERMOMETERS] = {@TEMP_ARGS@};
  return @P@_update_(s, time_s, raw);
}

/* @READING@ minus the last update's drift; the last good value where the @READING_WORD@ is not a
 * number or beyond @U@_@LIMIT@ (then @U@_FAULT_GYRO_BAD is set in s->flags). */
static inline @REAL@ @P@_compensated_@UNIT@(@P@_state* s, @REAL@ @READING@) {
  return @P@_compensated_(s, @READING@);
}

)";

}  // namespace

std::string c_streaming_part(const CompensationModel& model, const std::string& prefix,
                             const std::string& upper, double data_dt_s, const FaultPolicy& faults,
                             bool single) {
  if (!std::isfinite(data_dt_s)) throw OptionError("stream_dt_s", "must be a finite interval");
  validate(faults);
  const std::size_t block =
      decimation_factor(model.dataset.preprocessing, data_dt_s, "stream_dt_s");
  // The data's interval as the model's interval / block (decimate.hpp), and the model's.
  data_dt_s = streaming_interval_s(model.dataset.preprocessing, data_dt_s, block);
  const double dt_s = static_cast<double>(block) * data_dt_s;
  signal::CausalDifferentiator diff(model.dataset.preprocessing.rates, dt_s);
  const std::size_t w = diff.window();
  std::vector<double> taps;
  for (std::size_t k = 1; k <= w; ++k) {
    const auto& t = diff.taps(k);
    taps.insert(taps.end(), t.begin(), t.end());
  }
  std::string flags;
  for (std::size_t k = 0; k < fault::count; ++k) {
    std::string name(fault::names()[k]);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    flags += fmt::format("#define {}_FAULT_{} {}u\n", upper, name, 1u << k);
  }
  // Feature assignments: FeatureColumn::value() written out in C, a lagged rate (dT@τ) from its
  // lag's state (features.hpp, LaggedRate).
  std::string features;
  const std::vector<FeatureColumn> columns = model.dataset.features.columns();
  std::vector<double> lag_gain, lag_tau_s;
  std::vector<int> lag_thermometer;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].lagged()) {
      features += fmt::format("  f[{}] = lag_rate[{}];\n", c, lag_gain.size());
      lag_gain.push_back(LaggedRate(columns[c].tau_s, dt_s).gain());
      lag_tau_s.push_back(columns[c].tau_s);
      lag_thermometer.push_back(static_cast<int>(columns[c].a));
      continue;
    }
    const auto a = static_cast<std::size_t>(columns[c].a);
    const auto b = static_cast<std::size_t>(columns[c].b);
    std::string value;
    switch (columns[c].term) {
      case FeatureTerm::temp:
        value = fmt::format("temp[{}]", a);
        break;
      case FeatureTerm::rate:
        value = fmt::format("rate[{}]", a);
        break;
      case FeatureTerm::gradient:
        value = fmt::format("temp[{}] - temp[{}]", a, b);
        break;
      case FeatureTerm::gradient_rate:
        value = fmt::format("rate[{}] - rate[{}]", a, b);
        break;
      case FeatureTerm::time:
        value = "t";
        break;
      case FeatureTerm::temp_rate_product:
        value = fmt::format("temp[{}] * rate[{}]", a, a);
        break;
      case FeatureTerm::lagged_rate:
        break;  // above
    }
    features += fmt::format("  f[{}] = {};\n", c, value);
  }
  // One argument per thermometer of the spec, the further ones after fog, acc1, acc2.
  const FeatureSpec& spec = model.dataset.features;
  const std::vector<std::string> temp_columns = spec.thermometer_columns();
  std::string read_flags, params, names;
  for (std::size_t k = 0; k < temp_columns.size(); ++k) {
    const auto th = static_cast<Thermometer>(k);
    const char* sep = k ? ", " : "";
    read_flags += fmt::format("{}{}", sep, spec.reads(th) ? 1 : 0);
    params += fmt::format("{}@REAL@ {}", sep, temp_columns[k]);
    names += fmt::format("{}{}", sep, spec.thermometer_name(th));
  }
  const std::string args = fmt::format("{}", fmt::join(temp_columns, ", "));
  const bool guarded = !model.guard.empty();
  const bool gyro = target_of(model.dataset.target_column).kind == TargetKind::gyro;
  return fill_template(
      std::string(kStreamingC),
      {{"@COMPENSATOR@", renamed_compensator(prefix, upper)},
       {"@GUARD_DEFINE@", guarded ? fmt::format("#ifndef {0}_GUARD\n#define {0}_GUARD 1 /* 0: full "
                                                "correction always */\n#endif\n",
                                                upper)
                                  : std::string()},
       {"@NOTE@",
        model.dataset.preprocessing.rates.causality == signal::Causality::causal
            ? ""
            : "\n * NOTE: this model was trained with centred rates; streaming applies causal "
              "ones, which\n * lag. Train with --differentiator causal for firmware."},
       {"@FEATURES@", features},
       {"@LAG_TABLES@",
        lag_gain.empty()
            ? std::string("#define @U@_N_LAGS 0\n")
            : fmt::format("#define @U@_N_LAGS {} /* inputs dT@tau: rates through a lag */\n"
                          "static const int @P@_lag_thermometer[@U@_N_LAGS] = {{{}}};\n"
                          "static const @REAL@ @P@_lag_gain[@U@_N_LAGS] = {{{}}};\n"
                          "static const @REAL@ @P@_lag_tau_s[@U@_N_LAGS] = {{{}}};\n",
                          lag_gain.size(), fmt::join(lag_thermometer, ", "), c_array(lag_gain),
                          c_array(lag_tau_s))},
       {"@FLAGS@", flags},
       {"@READS@", thermometers_read(model)},
       {"@READ_FLAGS@", read_flags},
       {"@NT@", std::to_string(spec.thermometer_count())},
       {"@THERMOMETERS@", names},
       {"@TEMP_PARAMS@", params},
       {"@TEMP_ARGS@", args},
       {"@TAPS@", c_array(taps)},
       {"@NTAPS@", std::to_string(taps.size())},
       {"@TEMP_MIN@", c_number(faults.temp_min_degc)},
       {"@TEMP_MAX@", c_number(faults.temp_max_degc)},
       // A gyro's readings beyond the limit are faults; another target's only when not a number
       // (stream_faults.hpp), unless the firmware defines a limit of its own.
       {"@GYRO_LIMIT@", gyro ? c_number(faults.gyro_limit_dph) : std::string("HUGE_VAL")},
       {"@BRIDGE@", c_number(faults.bridge_s)},
       {"@HOLD@", c_number(faults.hold_s)},
       {"@STUCK@", c_number(faults.stuck_s)},
       {"@STUCK_DELTA@", c_number(faults.stuck_delta_degc)},
       {"@TEMP_JUMP@", c_number(faults.temp_jump_degc)},
       {"@INTERVAL_TOLERANCE@", c_number(kIntervalTolerance)},
       {"@DRIFT_LIMIT@", c_number(kDriftLimitScales * model.y_scaler.scale[0])},
       // In float, differences from the newest sample keep the rate's rounding that of the change
       // in temperature over the window, not of the temperature itself.
       {"@FROM_NEWEST@", single ? "1" : "0"},
       {"@DATA_DT@", c_number(data_dt_s)},
       {"@BLOCK@", std::to_string(block)},
       {"@DT@", c_number(dt_s)},
       {"@W@", std::to_string(w)},
       // Last: the values above may contain the prefix's own placeholders.
       {"@P@", prefix},
       {"@U@", upper}});
}

}  // namespace fogdrift::detail
