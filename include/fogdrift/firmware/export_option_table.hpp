// `export-c`'s options, described once (option_table.hpp, docs/options.md): `fogdrift export-c`'s
// flags and the keywords of Octave's Model.export_c. The C names' prefix, the streaming part's
// rate, the arithmetic, and the fault policy the streaming part runs (fault_option_table.hpp,
// its timings fitted to the model by each front end before these options apply). The model, the
// file and the axis each front end names itself.
#pragma once

#include <string>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift {

/// What to_c_header is asked besides the model.
struct ExportOptions {
  std::string prefix = "fogdrift_model";  ///< of every C name (checked by to_c_header)
  double stream_rate_hz = 0;              ///< PREFIX_update() for samples at this rate; 0: none
  CPrecision precision = CPrecision::double_;
  /// With float: write the header even where float departs from the model by more than
  /// kFloatShareLimit of the drift's STD (the front end warns).
  bool force_float = false;
  FaultPolicy faults;
};

const OptionTable<ExportOptions>& export_option_table();

}  // namespace fogdrift
