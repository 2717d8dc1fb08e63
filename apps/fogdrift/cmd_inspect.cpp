// fogdrift inspect: validate a recording or a campaign and summarise it (like svm-checkdata).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/inspect.hpp"
#include "fogdrift/io/inspect_option_table.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/io/target.hpp"
#include "option_flags.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

nlohmann::ordered_json summary_json(const RecordingSummary& s) {
  nlohmann::ordered_json j;
  j["samples"] = s.samples;
  j["start_s"] = s.start_s;
  j["end_s"] = s.end_s;
  j["duration_s"] = s.duration_s;
  j["sample_rate_hz"] = s.sample_rate_hz;
  j["gaps"] = s.gaps;
  j["longest_step_s"] = s.longest_gap_s;
  j["bursts"] = s.bursts;
  j["burst_period_s"] = s.burst_period_s;
  for (const auto& c : s.columns) {
    j["columns"][c.name] = {{"min", c.min}, {"max", c.max}, {"mean", c.mean}, {"std", c.std}};
  }
  j["extra_columns"] = s.extra_columns;
  j["uniformly_sampled"] = s.uniformly_sampled;
  j["log_to_join"] = s.partial;
  if (s.partial) j["missing"] = s.missing;
  return j;
}

void print_recording(const std::string& path, const RecordingSummary& s) {
  std::cout << (s.partial ? fmt::format("{}: valid log to join ({}; fogdrift join brings its "
                                        "columns into a recording by time)\n",
                                        path,
                                        s.missing.empty()
                                            ? std::string("it starts before power-on, t < 0")
                                            : fmt::format("no {}", fmt::join(s.missing, ", ")))
                          : fmt::format("{}: valid fogdrift recording\n", path));
  std::cout << fmt::format("  samples     {}\n  time        {} .. {} s ({:.1f} min)\n", s.samples,
                           s.start_s, s.end_s, s.duration_s / 60.0);
  if (s.bursts > 0)
    std::cout << fmt::format(
        "  sampling    bursts: {} of them, one every {:.6g} s (median); {:.6g} Hz within a burst "
        "(median step {:.6g} s), longest step {:.6g} s\n",
        s.bursts, s.burst_period_s, s.sample_rate_hz, s.sample_interval_s, s.longest_gap_s);
  else
    std::cout << fmt::format(
        "  sampling    {:.6g} Hz (median step {:.6g} s), {} gaps > 1.5 steps, "
        "longest step {:.6g} s\n",
        s.sample_rate_hz, s.sample_interval_s, s.gaps, s.longest_gap_s);
  std::cout << fmt::format("  {:<16}{:>14}{:>14}{:>14}{:>14}\n", "column", "min", "max", "mean",
                           "std");
  for (const auto& c : s.columns) {
    std::cout << fmt::format("  {:<16}{:>14.6g}{:>14.6g}{:>14.6g}{:>14.6g}\n", c.name, c.min, c.max,
                             c.mean, c.std);
  }
  if (s.partial)
    std::cout << "  training    not a recording: 'fogdrift join RECORDING LOG -o OUT' brings its "
                 "columns into one (docs/logs.md, \"Temperatures from another file\")\n";
  else if (s.uniformly_sampled)
    std::cout << "  training    usable as it stands (uniform time steps)\n";
  else if (s.bursts > 0)
    std::cout << fmt::format(
        "  training    not usable as it stands: a burst every {0:.6g} s; make one sample of each "
        "burst, its mean, with 'fogdrift import FILE --step-s {0:.6g}' (docs/logs.md)\n",
        s.burst_period_s);
  else
    std::cout << fmt::format(
        "  training    not usable as it stands: time steps vary by more than 1 % (median {1:.6g} "
        "s, longest {0:.6g} s); put the logger's file on a uniform grid with 'fogdrift import "
        "FILE --rate-hz R' (docs/logs.md)\n",
        s.longest_gap_s, s.sample_interval_s);
  // Further channels a model can compensate (train --targets) are named as such; the rest are
  // kept as they are and read by nothing.
  std::string targets, thermometers, others;
  for (const auto& e : s.extra_columns) {
    std::string& list = is_target_column(e)                       ? targets
                        : further_thermometer_name(e).has_value() ? thermometers
                                                                  : others;
    list += (list.empty() ? "" : ", ") + e;
  }
  if (!targets.empty())
    std::cout << "  targets     " << targets
              << " (further channels a model can compensate: train --targets)\n";
  if (!thermometers.empty())
    std::cout << "  thermometer " << thermometers
              << " (further thermometers: train --thermometers)\n";
  if (!others.empty()) std::cout << "  extra       " << others << " (kept, read by no command)\n";
}

int inspect_campaign(const fs::path& path, bool json) {
  const Campaign c = read_campaign(path);
  int failures = 0, irregular = 0;
  nlohmann::ordered_json out;
  out["campaign"] = c.dir.string();
  if (c.latitude_deg) out["latitude_deg"] = *c.latitude_deg;
  if (!json) {
    std::cout << fmt::format(
        "{}: campaign, {}, {} recordings\n", c.dir.string(),
        c.latitude_deg ? fmt::format("latitude {}°", *c.latitude_deg) : "no latitude",
        c.recordings.size());
    std::cout << fmt::format(
        "  {:<28}  {:<11}  {:<5}  {:>3}  {:>6}  {:>8}  {:>7}  {:>8}  {:>15}  {:>15}  {:>15}  "
        "{:>12}  {:>10}\n",
        "file", "scenario", "role", "rep", "T0 °C", "samples", "min", "Hz", "T_fog °C", "T_acc1 °C",
        "T_acc2 °C", "gyro °/h", "std °/h");
  }
  for (const auto& e : c.recordings) {
    nlohmann::ordered_json r;
    r["file"] = e.file;
    r["scenario"] = to_string(e.scenario);
    r["role"] = to_string(e.role);
    try {
      const Recording rec = read_recording(c.path_of(e));
      const RecordingSummary s = summarize(rec);
      r["summary"] = summary_json(s);
      if (!s.uniformly_sampled) ++irregular;
      if (!json) {
        auto range = [&](const char* name) {
          for (const auto& c : s.columns)
            if (c.name == name) return fmt::format("{:.2f}..{:.2f}", c.min, c.max);
          return std::string("absent");
        };
        // Two spaces between columns, so that a wide value never runs into its neighbour.
        std::cout << fmt::format(
            "  {:<28}  {:<11}  {:<5}  {:>3}  {:>6.1f}  {:>8}  {:>7.1f}  {:>8.3g}  {:>15}  {:>15}  "
            "{:>15}  {:>12.6g}  {:>10.4g}\n",
            e.file, to_string(e.scenario), to_string(e.role), e.repetition, e.initial_temp_degc,
            s.samples, s.duration_s / 60.0, s.sample_rate_hz, range("temp_fog_degc"),
            range("temp_acc1_degc"), range("temp_acc2_degc"), s.columns[0].mean, s.columns[0].std);
      }
    } catch (const InputError& err) {
      ++failures;
      r["error"] = err.what();
      std::cerr << "fogdrift: error: " << err.what() << "\n";
    }
    out["recordings"].push_back(r);
  }
  out["valid"] = failures == 0;
  out["uniformly_sampled"] = irregular == 0;
  if (json)
    std::cout << out.dump(2) << "\n";
  else if (failures == 0) {
    std::cout << "campaign is valid\n";
    if (irregular > 0)
      std::cout << fmt::format(
          "but {} recording(s) are not uniformly sampled, which train needs: "
          "import the logger's files with --rate-hz R (docs/logs.md)\n",
          irregular);
  } else
    std::cout << fmt::format("campaign has {} invalid recording(s)\n", failures);
  return failures == 0 ? 0 : 1;
}

}  // namespace

void add_inspect(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "inspect",
      "Validate a recording (CSV) or a campaign (folder or campaign.json) and summarise it:\n"
      "duration, sample rate, gaps, temperature ranges per thermometer, gyro mean and STD. With\n"
      "--log, a log to join (a chamber sheet imported with --partial) is summarised too: span,\n"
      "step, columns and their ranges.\n"
      "Exit status 0 when everything is valid, 1 with the error (file:line:column: rule) "
      "otherwise.");
  auto path = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("PATH", *path, "Recording CSV, campaign folder or campaign.json")->required();
  cmd->add_flag("--json", *json, "Print the summary as JSON");
  const auto& table = inspect_option_table();
  auto flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->callback([path, json, flags] {
    InspectOptions options;
    flags->apply(inspect_option_table(), options);
    const fs::path p(*path);
    int status = 0;
    if (fs::is_directory(p) || p.extension() == ".json") {
      status = inspect_campaign(p, *json);
    } else {
      // A recording is held to a recording's rules; with --log, a log to join (a chamber sheet
      // imported with --partial) is summarised too.
      Recording rec;
      if (options.log) {
        rec = read_log(p);
        // Every column a recording needs, from time 0 on: a recording, held to its rules.
        if (missing_required(rec).empty() && !rec.time_s.empty() && rec.time_s.front() >= 0) {
          rec.partial = false;
          validate(rec);
        }
      } else {
        try {
          rec = read_recording(p);
        } catch (const InputError& e) {
          // read_log relaxes only a recording's required columns and its start at t ≥ 0: what
          // it accepts is a valid log to join.
          bool is_log = false;
          try {
            read_log(p);
            is_log = true;
          } catch (const InputError&) {
          }
          if (!is_log) throw;
          throw InputError(e.file(), e.line(), e.column(),
                           e.message() + fmt::format("; it is a valid log to join, and "
                                                     "'fogdrift inspect --log {}' summarises it",
                                                     p.string()));
        }
      }
      const RecordingSummary s = summarize(rec);
      if (*json) {
        nlohmann::ordered_json j = summary_json(s);
        j["file"] = p.string();
        j["valid"] = true;
        std::cout << j.dump(2) << "\n";
      } else {
        print_recording(p.string(), s);
      }
    }
    if (status != 0) throw CLI::RuntimeError(status);
  });
}

}  // namespace fogdrift::app
