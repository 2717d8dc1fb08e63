// fogdrift campaign: write a campaign folder (recordings and campaign.json) from recordings or
// from one long log cut into recordings, validated as inspect validates (docs/logs.md).
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/version.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/campaign_option_table.hpp"
#include "fogdrift/io/cut.hpp"
#include "fogdrift/io/recording.hpp"
#include "option_flags.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct CampaignArgs {
  std::string out;
  std::vector<std::string> inputs;
  std::shared_ptr<OptionFlags> flags;  // campaign's options (campaign_option_table.hpp)
  bool force = false;
  bool quiet = false;
};

/// The 1-based positions named by --test: "last", "none", or a list such as 3 or 2,5.
std::set<std::size_t> test_positions(const std::string& text, std::size_t count) {
  if (text == "none") return {};
  if (text == "last") return {count};
  std::set<std::size_t> out;
  for (double v : parse_number_list(text, "--test")) {
    if (v != std::floor(v) || v < 1 || v > static_cast<double>(count))
      throw OptionError("--test", fmt::format("{} is not a recording number 1..{} (the order in "
                                              "which they are listed, after cutting)",
                                              v, count));
    out.insert(static_cast<std::size_t>(v));
  }
  return out;
}

/// The campaign folder from the recordings `args` names and the options `o` its flags gave.
void make(const CampaignArgs& args, const CampaignOptions& o) {
  if (o.sensed.input_rate_dph && (o.latitude_deg || o.true_azimuth_deg))
    throw OptionError("--input-rate-dph",
                      "give either the input rate or the latitude and the "
                      "true azimuth, not both");
  if (!o.sensed.input_rate_dph && !(o.latitude_deg && o.true_azimuth_deg))
    throw OptionError("--input-rate-dph",
                      "say what rate the gyro sensed, so that train models drift and not the "
                      "input: --input-rate-dph R (0 for an axis that sees no rotation, e.g. "
                      "horizontal and pointing east or west, or a MEMS gyro whose noise hides the "
                      "Earth rate), or --latitude-deg L --true-azimuth-deg A (the Earth rate's "
                      "projection on a horizontal axis)");

  const std::map<std::string, double>& references = o.sensed.references;
  const CutOptions& cut_options = o.cut;
  std::vector<Recording> pieces;
  std::size_t plateau_cuts = 0;
  for (const auto& input : args.inputs) {
    const Recording rec = read_recording(input);
    try {
      CutSummary summary;
      for (auto& p : cut(rec, cut_options, &summary)) pieces.push_back(std::move(p));
      plateau_cuts += summary.plateaus;
      // Samples the cut left out are said, on standard error, whatever --quiet says.
      for (const auto& [from, to] : summary.dropped_spans_s)
        std::cerr << fmt::format(
            "fogdrift campaign: note: {}: dropped the samples from {:.6g} to {:.6g} s, a piece "
            "too short to keep (a last window under half of --cut-window-s, or under the "
            "fewest samples a recording needs)\n",
            input, from, to);
    } catch (const OptionError& e) {
      throw args.flags->named(e);
    }
  }
  const std::set<std::size_t> tests = test_positions(o.test, pieces.size());
  // Plateaus asked for and none found: the cut, not --test, is what left too few recordings.
  const bool no_plateau = cut_options.plateaus && plateau_cuts == 0;
  const std::string plateau_note = fmt::format(
      "no plateau ended in {} (a plateau: at least {} s with |rate| below {} °C/min, then a "
      "change); loosen --plateau-rate-degc-per-min or --plateau-min-s, or cut with --cut-gap-s "
      "or --cut-window-s",
      args.inputs.size() == 1 ? args.inputs.front()
                              : fmt::format("any of the {} logs", args.inputs.size()),
      cut_options.plateau_min_s, cut_options.plateau_rate_degc_per_min);
  if (tests.size() == pieces.size()) {
    if (no_plateau)
      throw OptionError("--cut-plateaus",
                        fmt::format("{}: {} recording(s), and --test {} leaves none to train on",
                                    plateau_note, pieces.size(), o.test));
    throw OptionError("--test", "leaves no recording to train on");
  }
  const std::vector<double>& reps = o.repetitions;
  if (!reps.empty()) {
    if (reps.size() != pieces.size())
      throw OptionError("--repetitions", fmt::format("lists {} numbers for {} recordings",
                                                     reps.size(), pieces.size()));
  }

  Campaign c;
  c.latitude_deg = o.latitude_deg;
  c.generator_json = fmt::format(R"({{"tool": "fogdrift campaign", "version": "{}"}})", kVersion);
  std::set<std::string> names;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    CampaignEntry e;
    std::string stem = fs::path(pieces[k].source).stem().string();
    e.file = fmt::format("{}_{:02}.csv", stem, k + 1);
    if (!names.insert(e.file).second) e.file = fmt::format("rec_{:02}.csv", k + 1);
    e.scenario = Scenario::calibration;
    e.role = tests.count(k + 1) ? Role::test : Role::train;
    e.repetition = reps.empty() ? 1 : static_cast<int>(reps[k]);
    if (!reps.empty() && (reps[k] != std::floor(reps[k]) || reps[k] < 1))
      throw OptionError("--repetitions", fmt::format("{} is not an integer >= 1", reps[k]));
    // The start-up condition: the FOG thermometer's first reading, to 0.1 °C.
    e.initial_temp_degc = std::round(pieces[k].temp_fog_degc.front() * 10.0) / 10.0;
    if (e.initial_temp_degc < -70 || e.initial_temp_degc > 100)
      throw InputError(pieces[k].source, 2, 0,
                       fmt::format("temp_fog_degc starts at {} °C, outside [-70, 100]: check "
                                   "its unit (--unit at import)",
                                   e.initial_temp_degc));
    e.input_rate_dph = o.sensed.input_rate_dph;
    for (const auto& [column, value] : references)
      if (!pieces[k].has_column(column))
        throw OptionError("--reference", fmt::format("{} has no column '{}' to give a reference "
                                                     "for (its columns are as fogdrift import "
                                                     "wrote them)",
                                                     pieces[k].source, column));
    e.references = references;
    e.true_azimuth_deg = o.true_azimuth_deg;
    c.recordings.push_back(std::move(e));
  }

  check_output_not_input(args.out, "DIR");
  fill_directory_atomically(args.out, args.force, [&](const fs::path& dir) {
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      Recording r = pieces[k];
      r.source = c.recordings[k].file;
      write_recording(dir / c.recordings[k].file, r);
    }
    write_manifest(dir, c);
    // Validate as inspect does, before the folder appears under its name.
    const Campaign back = read_campaign(dir);
    for (const auto& e : back.recordings) read_recording(back.path_of(e));
  });

  if (args.quiet) return;
  if (no_plateau) std::cout << "note: --cut-plateaus: " << plateau_note << "\n";
  std::cout << fmt::format("{}: campaign of {} recordings ({} train, {} test)\n", args.out,
                           pieces.size(), pieces.size() - tests.size(), tests.size());
  std::cout << fmt::format("  {:<28}  {:<5}  {:>3}  {:>8}  {:>8}  {:>9}\n", "file", "role", "rep",
                           "T0 °C", "samples", "minutes");
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const auto& e = c.recordings[k];
    const auto& t = pieces[k].time_s;
    std::cout << fmt::format("  {:<28}  {:<5}  {:>3}  {:>8.1f}  {:>8}  {:>9.1f}\n", e.file,
                             to_string(e.role), e.repetition, e.initial_temp_degc, t.size(),
                             (t.back() - t.front()) / 60.0);
  }
  std::cout << fmt::format("  next: fogdrift inspect {0}; fogdrift train {0} -o model.json\n",
                           args.out);
}

void run(const CampaignArgs& args) {
  CampaignOptions o;
  args.flags->apply(campaign_option_table(), o);
  make(args, o);
}

}  // namespace

void add_campaign(CLI::App& app) {
  auto a = std::make_shared<CampaignArgs>();
  auto* cmd = app.add_subcommand(
      "campaign",
      "Make a campaign folder (recordings and campaign.json) from fogdrift recordings, or from\n"
      "one long log cut into recordings at gaps (--cut-gap-s), at the ends of temperature\n"
      "plateaus (--cut-plateaus: each piece a chamber step and the plateau it settles to), or\n"
      "into fixed windows (--cut-window-s). Power cycles in a raw log are split by\n"
      "'import --split-at-reset'.\n"
      "Every recording is a calibration start-up; its initial temperature is the FOG\n"
      "thermometer's first reading. The folder is validated as inspect validates and appears\n"
      "only when complete. Examples:\n"
      "  fogdrift campaign cal run_1.csv run_2.csv run_3.csv --input-rate-dph 0\n"
      "  fogdrift campaign cal long.csv --cut-gap-s 600 --test 2,5 --latitude-deg 47.4 \\\n"
      "    --true-azimuth-deg 90\n"
      "See docs/logs.md.");
  cmd->add_option("OUT", a->out, "Campaign folder to create (must not exist or be empty)")
      ->required();
  cmd->add_option("RECORDING", a->inputs, "fogdrift recordings (CSV), in start-up order")
      ->required()
      ->check(CLI::ExistingFile);
  const auto& table = campaign_option_table();
  a->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->add_flag("--force", a->force, "Replace OUT if it exists (only after success)");
  cmd->add_flag("-q,--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] { run(*a); });
}

}  // namespace fogdrift::app
