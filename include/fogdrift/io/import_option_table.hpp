// `fogdrift import`'s options, described once (option_table.hpp, docs/options.md): the column
// map and units (--map, --unit: NAME=VALUE assignments, one a flag, so that a foreign name may
// hold any character, commas too), how a foreign file is read (its separator, preamble and
// time), which samples are mended (empty cells, spikes), and the uniform grid a recording may be
// put on. The files and the output the command declares itself.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/import.hpp"
#include "fogdrift/io/regrid.hpp"
#include "fogdrift/signal/hampel.hpp"

namespace fogdrift {

/// What the table sets: the reading's options, the units as written, the spike filter asked
/// for, and the grid.
struct ImportRunOptions {
  ImportOptions read;  ///< its conversions are import_plan's, from `units`
  /// fogdrift column -> its unit as the user wrote it (parse_unit).
  std::map<std::string, std::string> units;
  bool hampel = false;
  signal::HampelOptions hampel_options;
  /// The grid: a rate or a step (0: neither, the logger's own time stamps), its filling, and the
  /// longest gap bridged (unset: 10 grid steps).
  double rate_hz = 0;
  double step_s = 0;
  RegridMethod method = RegridMethod::automatic;
  std::optional<double> max_gap_s;
};

const OptionTable<ImportRunOptions>& import_option_table();

/// What to read with (the units' conversions made, parse_unit) and the grid asked for. Throws
/// OptionError naming the option (its keyword) for options that contradict or have no effect: a
/// rate and a step both, a grid's method or gap without a grid, a spike setting without the
/// filter; parse_unit's OptionError (naming --unit COLUMN=UNIT) for a unit it does not know.
struct ImportPlan {
  ImportOptions read;
  std::optional<RegridOptions> grid;
};
ImportPlan import_plan(const ImportRunOptions& options);

}  // namespace fogdrift
