// The compensation model as C99 source for an instrument's processor (docs/compensation.md):
// `fogdrift export-c` writes what to_c_header() returns.
#pragma once

#include <string>

#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift {

/// A self-contained C99 header for an instrument's processor: the scalers and regressor as
/// `static const` tables (numbers printed to 17 significant digits, so the doubles are the
/// model's) and
///   static inline PREFIX_real PREFIX_predict_dph(const PREFIX_real features[PREFIX_N_FEATURES]);
/// which needs only <math.h> (exp or tanh), no heap and no other state. The features are those of
/// the model's spec, in the order listed in the header's comment and PREFIX_feature_names.
/// `prefix` must be a C identifier (OptionError("prefix", …) otherwise).
///
/// With `stream_dt_s` > 0 the header also computes the features itself, causally, one sample
/// at a time at that fixed sample interval — what StreamingCompensator does:
///   PREFIX_state s; PREFIX_reset(&s);   at power-on
///   drift_dph = PREFIX_update(&s, time_s, temp_fog_degc, temp_acc1_degc, temp_acc2_degc);
///   gyro_compensated_dph = PREFIX_compensated_dph(&s, gyro_dph);
/// with the causal differentiator's taps as a table and a fixed buffer in the state (no heap),
/// and the fault policy `faults` (stream_faults.hpp) with its settings as macros the firmware may
/// override; s.flags holds each sample's fault flags as PREFIX_FAULT_* bits.
/// A model of another target (target.hpp) names its functions and drift in its unit:
/// PREFIX_predict_g, PREFIX_compensated_g(&s, accel_x_g), whose range check
/// PREFIX_READING_LIMIT_G is off (HUGE_VAL) unless the firmware defines it.
/// It is meant for a model trained with causal rates; the header says so when the model's were
/// centred. OptionError("stream_dt_s", …) when the differentiator window does not fit the
/// interval, and the FaultPolicy's own for invalid settings.
/// The arithmetic of the header (`export-c --precision`); times stay double either way.
enum class CPrecision {
  double_,  ///< the model's numbers as they are: the header computes what fogdrift computes
  single,   ///< float tables and arithmetic, for a 32-bit FPU (Cortex-M4F): docs/firmware.md
};

/// With CPrecision::single every table and all arithmetic but time are float (PREFIX_real), and
/// <math.h>'s float functions are called.
std::string to_c_header(const CompensationModel& model,
                        const std::string& prefix = "fogdrift_model", double stream_dt_s = 0,
                        const FaultPolicy& faults = {}, CPrecision precision = CPrecision::double_);

/// Every axis of a model set in one header (c_header_set.cpp): each axis's model as above under
/// the prefix PREFIX_AXIS (AXIS = axis_name(), gyro for gyro_dph, NAME for gyro_NAME_dph,
/// accel_x for accel_x_g; each axis's functions named in its unit, PREFIX_AXIS_predict_g),
/// PREFIX_N_AXES and PREFIX_axis_names, and with `stream_dt_s` > 0 one update for all of them:
///   PREFIX_state s; PREFIX_reset(&s);   at power-on
///   PREFIX_update(&s, time_s, temp_fog_degc, temp_acc1_degc, temp_acc2_degc, drift_dph);
///   PREFIX_compensated_dph(&s, gyro_dph, gyro_compensated_dph);
/// with arrays of PREFIX_N_AXES values in PREFIX_axis_names order; axes of several kinds
/// (target.hpp) share arrays named for no unit (drift, reading, compensated: PREFIX_compensated),
/// each value in its axis's unit, PREFIX_axis_units. A set of one model gives
/// to_c_header(model, ...) itself.
std::string to_c_header(const ModelSet& set, const std::string& prefix = "fogdrift_model",
                        double stream_dt_s = 0, const FaultPolicy& faults = {},
                        CPrecision precision = CPrecision::double_);

/// How far a float header's drift departs from the model's own (export-c --precision float):
/// the features rounded to float, standardised and the drift de-standardised in float as the
/// header does (the steps where float loses most: a thermometer that varies by micro-degrees
/// about 25 °C keeps no digits after `features - mean`), the regressor itself run in double on
/// those float inputs. Evaluated on the model's own training inputs as its file keeps them (the
/// guard's prototypes; without a guard, the feature means and one scale either side of each).
struct FloatPrecisionCheck {
  double max_error = 0;    ///< largest |float drift − double drift|, in the target's unit
  double drift_std = 0;    ///< the training drift's standard deviation (its scaler's scale)
  std::size_t inputs = 0;  ///< rows compared
  /// The largest error as a share of the drift's STD; export-c refuses above kFloatShareLimit.
  double share() const { return drift_std > 0 ? max_error / drift_std : 0.0; }
};
inline constexpr double kFloatShareLimit = 1e-3;
FloatPrecisionCheck check_float_precision(const CompensationModel& model);

/// The upper-case form of `prefix` that the header's macros carry; OptionError("prefix", …) when
/// `prefix` is not a C identifier (letters, digits and '_', not starting with a digit).
std::string c_macro_prefix(const std::string& prefix);

}  // namespace fogdrift
