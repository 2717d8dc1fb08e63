// `export-c`'s options (export_option_table.hpp). Defaults are ExportOptions'; to_c_header
// checks the prefix and the rate against the model (decimation_factor), naming "prefix" and
// "rate".
#include "fogdrift/firmware/export_option_table.hpp"

#include <fmt/format.h>

#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/stream/fault_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<ExportOptions> make_export_table() {
  using O = ExportOptions;
  OptionTable<O> t;
  const OptionSpec prefix{"prefix",
                          "--prefix",
                          OptionType::text,
                          "",
                          {"a C identifier, not starting with '_'"},
                          "C name prefix of every symbol",
                          {}};
  t.push_back({prefix, [](const O& o) { return o.prefix; },
               [](O& o, const std::string& text) { o.prefix = text; }});
  t.push_back(number_option<O>(
      {"stream_rate_hz",
       "--stream-rate-hz",
       {},
       "Hz",
       between(0, kMaxStreamRateHz).with("0: no streaming part"),
       "Also write PREFIX_update() for samples at this fixed rate: the model's rate or a whole "
       "multiple of it",
       {"rate"}},
      [](auto& o) -> auto& { return o.stream_rate_hz; }));
  t.push_back(choice_option<O>(
      {"precision",
       "--precision",
       {},
       "",
       {"double, float"},
       "Arithmetic of the header: double (the model's numbers, what fogdrift computes) or float "
       "(for a 32-bit FPU such as a Cortex-M4F's; docs/firmware.md gives its error and cost); "
       "times stay double",
       {}},
      [](auto& o) -> auto& { return o.precision; },
      [](CPrecision p) { return p == CPrecision::single ? "float" : "double"; },
      [](const std::string& text, const std::string& keyword) {
        if (text == "double") return CPrecision::double_;
        if (text == "float") return CPrecision::single;
        throw OptionError(keyword, fmt::format("'{}' is not double or float", text));
      }));
  t.push_back(on_off_option<O>(
      {"force_float",
       "--force-float",
       {},
       "",
       "",
       "With {precision} float: write the header even where float departs from the model by "
       "more than 1e-3 of the drift's STD on its training inputs (warned)",
       {}},
      [](auto& o) -> auto& { return o.force_float; }));
  for (Option<O>& o : lifted<O>(
           fault_option_table(), [](auto& e) -> auto& { return e.faults; }))
    t.push_back(std::move(o));
  return t;
}

}  // namespace

const OptionTable<ExportOptions>& export_option_table() {
  static const OptionTable<ExportOptions> table = make_export_table();
  return table;
}

}  // namespace fogdrift
