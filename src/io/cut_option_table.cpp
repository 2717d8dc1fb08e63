// The cutting options of `fogdrift campaign` (cut_option_table.hpp). Defaults are CutOptions';
// cut() checks them again for the library's own callers, naming its fields, which these options
// answer.
#include "fogdrift/io/cut_option_table.hpp"

namespace fogdrift {
namespace {

OptionTable<CutOptions> make_cut_table() {
  using O = CutOptions;
  OptionTable<O> t;
  t.push_back(number_option<O>(
      {"cut_gap_s",
       "--cut-gap-s",
       {},
       "s",
       at_least(0).with("0: no cut at gaps"),
       "Cut at time steps longer than this",
       {"gap_s"}},
      [](auto& o) -> auto& { return o.gap_s; }));
  t.push_back(number_option<O>(
      {"cut_window_s",
       "--cut-window-s",
       {},
       "s",
       at_least(0).with("0: no windows"),
       "Cut into windows of this length; a last window under half of it "
       "is dropped",
       {"window_s"}},
      [](auto& o) -> auto& { return o.window_s; }));
  t.push_back(on_off_option<O>(
      {"cut_plateaus",
       "--cut-plateaus",
       {},
       "",
       "",
       "Cut where each temperature plateau ends (chamber_degc, else "
       "temp_fog_degc): each piece a chamber step and the plateau it "
       "settles to",
       {"plateaus"}},
      [](auto& o) -> auto& { return o.plateaus; }));
  t.push_back(number_option<O>(
      {"plateau_rate_degc_per_min",
       "--plateau-rate-degc-per-min",
       {},
       "°C/min",
       above(0),
       "A plateau's |rate| stays below this (slope over ±60 s)",
       {}},
      [](auto& o) -> auto& { return o.plateau_rate_degc_per_min; }));
  t.push_back(number_option<O>(
      {"plateau_min_s", "--plateau-min-s", {}, "s", above(0), "Shortest plateau", {}},
      [](auto& o) -> auto& { return o.plateau_min_s; }));
  return t;
}

}  // namespace

const OptionTable<CutOptions>& cut_option_table() {
  static const OptionTable<CutOptions> table = make_cut_table();
  return table;
}

}  // namespace fogdrift
