// `fogdrift campaign`'s options (campaign_option_table.hpp). Defaults are the structs'. cut()
// checks the cutting again for the library's own callers, naming its fields, which these options
// answer; the references are checked as they are read (check_reference).
#include "fogdrift/io/campaign_option_table.hpp"

#include <fmt/format.h>

#include "fogdrift/io/target.hpp"

namespace fogdrift {
namespace {

OptionTable<SensedOptions> make_sensed_table() {
  using O = SensedOptions;
  OptionTable<O> t;
  t.push_back(number_or_none_option<O>(
      {"input_rate_dph",
       "--input-rate-dph",
       {},
       "°/h",
       between(-kReferenceLimit, kReferenceLimit),
       "The rate the gyro sensed, the same in every recording (0 for an axis that sees no "
       "rotation); none: a campaign's latitude and true azimuth give it, and for recording files "
       "the target subtracts each recording's mean, losing the turn-on bias",
       {}},
      [](auto& o) -> auto& { return o.input_rate_dph; }));
  OptionSpec references{
      "references",
      "--reference",
      OptionType::assignments,
      "",
      {},
      "COLUMN=VALUE: what a target channel sensed, in its unit, the same in "
      "every recording: an accelerometer's share of gravity (accel_x_g=0 for a "
      "level axis, accel_z_g=1 pointing up), a scale-factor channel's nominal "
      "(sf_fog_ppm=0), a gyro axis's own input rate (docs/logs.md, \"Other "
      "targets\"); without one, train subtracts each recording's mean and says so",
      {}};
  t.push_back(
      {references,
       [](const O& o) {
         std::vector<std::pair<std::string, std::string>> items;
         for (const auto& [column, value] : o.references)
           items.emplace_back(column, option_number_text(value));
         return option_assignments_text(items);
       },
       [references](O& o, const std::string& text) {
         std::map<std::string, double> out;
         for (const auto& [column, value] : parse_assignments_option(references, text)) {
           double v = 0;
           try {
             v = parse_number_option(references, value);
           } catch (const OptionError& e) {  // which of the items
             throw OptionError(references.keyword, fmt::format("{}: {}", column, e.message()));
           }
           check_reference(column, v, references.keyword);  // a target column, a sane value
           if (!out.emplace(column, v).second)
             throw OptionError(references.keyword, fmt::format("{} is given twice", column));
         }
         o.references = std::move(out);
       }});
  return t;
}

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

OptionTable<CampaignOptions> make_campaign_table() {
  using O = CampaignOptions;
  OptionTable<O> t;
  OptionSpec test{
      "test",
      "--test",
      OptionType::text,
      "",
      {"last, none, or numbers such as 2,5"},
      "The recordings held out for evaluate: the last, none, or their numbers (1-based, "
      "in the order listed, after cutting)",
      {}};
  t.push_back({test, [](const O& o) { return o.test; },
               [](O& o, const std::string& text) { o.test = text; }});
  t.push_back(numbers_option<O>(
      {"repetitions",
       "--repetitions",
       {},
       "",
       at_least(1).with("whole numbers, one per recording"),
       "The repetition of the temperature cycle each recording belongs "
       "to, e.g. 1,1,1,2,2,2 (default: all 1)",
       {}},
      [](auto& o) -> auto& { return o.repetitions; }));
  for (Option<O>& o : lifted<O>(
           sensed_option_table(), [](auto& c) -> auto& { return c.sensed; }))
    t.push_back(std::move(o));
  t.push_back(number_or_none_option<O>(
      {"latitude_deg",
       "--latitude-deg",
       {},
       "°",
       between(-90, 90),
       "The site's latitude, with {true_azimuth_deg} instead of {input_rate_dph}: the gyro "
       "sensed the Earth rate's projection on its horizontal axis",
       {}},
      [](auto& o) -> auto& { return o.latitude_deg; }));
  t.push_back(number_or_none_option<O>(
      {"true_azimuth_deg",
       "--true-azimuth-deg",
       {},
       "°",
       between(0, 360),
       "The azimuth of the horizontal sensitive axis, degrees from true north (with "
       "{latitude_deg})",
       {}},
      [](auto& o) -> auto& { return o.true_azimuth_deg; }));
  for (Option<O>& o : lifted<O>(
           cut_option_table(), [](auto& c) -> auto& { return c.cut; }))
    t.push_back(std::move(o));
  return t;
}

}  // namespace

const OptionTable<SensedOptions>& sensed_option_table() {
  static const OptionTable<SensedOptions> table = make_sensed_table();
  return table;
}

const OptionTable<CutOptions>& cut_option_table() {
  static const OptionTable<CutOptions> table = make_cut_table();
  return table;
}

const OptionTable<CampaignOptions>& campaign_option_table() {
  static const OptionTable<CampaignOptions> table = make_campaign_table();
  return table;
}

}  // namespace fogdrift
