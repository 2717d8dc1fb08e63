// fogdrift stream: the causal streaming compensator on samples as they arrive
// (StreamingCompensator, compensator.hpp), one CSV line in, one line out, flushed, as firmware
// would run it.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fault_options.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/model/compensate_file.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/stream/stream_command_option_table.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift::app {
namespace {

struct StreamArgs {
  ModelLoadOptions load;
  std::string model;
  std::optional<std::string> target;  ///< the axis of a model set
  std::string input = "-";
  /// The rate's, --strict's, the guard's and the fault policy's (fault_options.hpp).
  std::shared_ptr<OptionFlags> flags;
  StreamCommandOptions options;  ///< as run: faults fitted to the model, then the flags
};

// A header's fields as compensate and inspect read them (csv::read): quoted, trimmed.
std::vector<std::string> header_fields(const std::string& line, const std::string& name) {
  std::vector<std::string> fields = csv::split_line(line, ',', name, 1);
  for (std::string& f : fields) {
    const auto first = f.find_first_not_of(" \t");
    const auto last = f.find_last_not_of(" \t");
    f = first == std::string::npos ? std::string() : f.substr(first, last - first + 1);
  }
  return fields;
}

// With --strict, the first faulty sample stops the stream with its file, line and column, as a
// file for training would. Values that are not numbers and steps off the interval are caught
// before the compensator sees them; this names the rule of the fault policy the sample broke.
void stop_at_fault(const std::string& name, std::size_t line_no, std::uint32_t flags,
                   const std::vector<std::string>& names, const std::vector<std::size_t>& column,
                   const std::vector<double>& v, const FaultPolicy& policy) {
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  if (flags & fault::gyro_bad)
    throw InputError(name, line_no, column[1] + 1,
                     fmt::format("{} {} is beyond ±{} °/h (--gyro-limit-dph)", names[1],
                                 csv::format_number(v[1]), policy.gyro_limit_dph));
  for (std::size_t k = 2; k < v.size() && (flags & fault::temp_bad); ++k)
    if (column[k] != kAbsent && (v[k] < policy.temp_min_degc || v[k] > policy.temp_max_degc))
      throw InputError(name, line_no, column[k] + 1,
                       fmt::format("{} {} is outside [{}, {}] °C (--temp-min-degc, "
                                   "--temp-max-degc)",
                                   names[k], csv::format_number(v[k]), policy.temp_min_degc,
                                   policy.temp_max_degc));
  throw InputError(
      name, line_no, 0,
      fmt::format("is a faulty sample ({}); --strict stops at the first", fault::describe(flags)));
}

void run(const StreamArgs& given) {
  StreamArgs a = given;
  // Every axis of the model (model_set.hpp), or the one --target names.
  const ModelSet set = axes_to_run(load_model_set(a.model, a.load), a.target);
  const CompensationModel& first = set.models.front();
  a.options = stream_options(*a.flags, first);
  // Without --rate-hz, the model's own rate; a model file too old to record it needs the flag.
  const double model_dt_s = first.dataset.preprocessing.sample_interval_s;
  if (!a.options.rate_hz && !(model_dt_s > 0))
    throw OptionError("--rate-hz", fmt::format("is needed: {} does not record the rate it was "
                                               "trained at (written before models did)",
                                               a.model));
  const double rate_hz = a.options.rate_hz.value_or(1.0 / model_dt_s);
  if (!a.options.rate_hz && !(rate_hz <= kMaxStreamRateHz))
    throw OptionError("--rate-hz", fmt::format("is needed: {} was trained at {:.6g} Hz, above the "
                                               "{} Hz a stream runs at",
                                               a.model, rate_hz, kMaxStreamRateHz));
  // Streamed, a model trained on centred rates sees causal ones, noisier than those it learned:
  // a tuned SVR's drift then departs from its batch drift by about the drift's own STD
  // (docs/compensation.md). The stream still runs; the user is told, as export-c tells.
  if (first.dataset.preprocessing.rates.causality != signal::Causality::causal)
    std::cerr << fmt::format(
        "fogdrift stream: warning: {} was trained with centred temperature rates; streamed, it "
        "sees causal ones and its drift differs from compensate's (train with --differentiator "
        "causal for the instrument)\n",
        a.model);
  // The interval the compensators run on: the model's own over the samples per model sample,
  // so a rate rounded to four digits runs as the model was trained (decimate.hpp).
  const double dt_s = streaming_interval_s(
      first.dataset.preprocessing, 1.0 / rate_hz,
      decimation_factor(first.dataset.preprocessing, 1.0 / rate_hz, "--rate-hz"));
  // One compensator per axis; a rate a model cannot run at names --rate-hz.
  std::vector<StreamingCompensator> compensators;
  compensators.reserve(set.models.size());
  with_flags({{"rate", "--rate-hz"}}, [&] {
    for (const CompensationModel& model : set.models)
      compensators.emplace_back(model, dt_s, a.options.stream);
  });

  // Standard input through a file buffer of its own: std::cin, kept in step with C's stdio,
  // hands over a character at a time and never says what is ready, which made a log piped in
  // four times slower than the same file named (bench/khz_io.py).
  const std::string name = a.input == "-" ? "<stdin>" : a.input;
  std::ifstream in(a.input == "-" ? std::string("/dev/stdin") : a.input, std::ios::binary);
  if (!in) throw InputError(name, 0, 0, "cannot be opened for reading");

  csv::LineReader lines(in);  // LF, CRLF or CR line ends and a byte-order mark, as compensate
  std::string line;
  if (!lines.next(line)) throw InputError(name, 1, 0, "is empty; a header line is needed");
  const std::vector<std::string> header = header_fields(line, name);
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  auto column_of = [&](const std::string& wanted, bool needed) {
    const auto it = std::find(header.begin(), header.end(), wanted);
    if (it == header.end() && needed)
      throw InputError(name, 1, 0, fmt::format("has no {} column", wanted));
    return it == header.end() ? kAbsent : static_cast<std::size_t>(it - header.begin());
  };
  // Time and the thermometers, shared by every axis: the accelerometers' thermometers are needed
  // only when a model reads them, and after them every further thermometer a model reads
  // (docs/logs.md, "More thermometers"). Then each axis's gyro.
  std::vector<std::string> names = {"time_s", first.dataset.target_column};
  for (std::string& c : set.thermometer_columns()) names.push_back(std::move(c));
  // Per column, whether some model reads it; per axis, where its further thermometers are.
  std::vector<bool> read(names.size(), false);
  std::vector<std::vector<std::size_t>> further_of;
  for (const CompensationModel& model : set.models) {
    const FeatureSpec& f = model.dataset.features;
    const std::vector<std::string> own = f.thermometer_columns();
    further_of.emplace_back();
    for (std::size_t k = 0; k < own.size(); ++k) {
      const auto at =
          static_cast<std::size_t>(std::find(names.begin(), names.end(), own[k]) - names.begin());
      if (f.reads(static_cast<Thermometer>(k))) read[at] = true;
      if (k >= 3) further_of.back().push_back(at);
    }
  }
  std::vector<std::size_t> column(names.size());
  column[0] = column_of(names[0], true);
  column[2] = column_of(names[2], true);
  for (std::size_t k = 3; k < names.size(); ++k) column[k] = column_of(names[k], read[k]);
  std::vector<double> further_degc;  // one axis's further thermometers, in its spec's order
  std::vector<std::size_t> gyro_column;
  std::vector<std::string> added;
  for (const CompensationModel& model : set.models) {
    const std::string& target = model.dataset.target_column;
    gyro_column.push_back(column_of(target, true));
    for (const std::string& out : compensated_columns(target)) added.push_back(out);
    added.push_back(target == "gyro_dph" ? "fault_flags" : "fault_flags_" + axis_name(target));
  }
  for (const std::string& column_name : added)
    if (std::find(header.begin(), header.end(), column_name) != header.end())
      throw InputError(
          name, 1, 0,
          fmt::format("already has a {} column; stream the original recording", column_name));
  std::cout << line << "," << fmt::format("{}", fmt::join(added, ",")) << "\n" << std::flush;
  check_standard_output();

  std::size_t line_no = 1, samples = 0, flagged = 0, skipped = 0;
  std::array<std::size_t, fault::count> per_flag{};
  double previous_time = std::nan("");
  std::string outputs;
  std::vector<double> values(names.size());
  std::vector<std::string_view> fields;  // the line's fields, views into it (or into quoted)
  std::vector<std::string> quoted;
  while (lines.next(line)) {
    ++line_no;
    if (line.empty()) continue;
    // The same reader as compensate's: a quoted field is its text; a line it cannot read (an
    // unterminated quote) is skipped as a torn one, never echoed with outputs inside the quote.
    try {
      csv::split_fields(line, ',', name, line_no, fields, quoted);
    } catch (const InputError& e) {
      if (a.options.strict) throw;
      std::cerr << fmt::format("{}:{}: skipped: {}\n", name, line_no, e.message());
      ++skipped;
      continue;
    }
    if (fields.size() != header.size()) {
      // A torn line cannot carry its outputs; the next sample sees the gap it leaves.
      const std::string what =
          fmt::format("has {} fields, the header {}", fields.size(), header.size());
      if (a.options.strict) throw InputError(name, line_no, 0, what);
      std::cerr << fmt::format("{}:{}: skipped: {}\n", name, line_no, what);
      ++skipped;
      continue;
    }
    // A field that is not a number is a faulty reading, as a NaN is; an absent thermometer the
    // model does not read is 0.
    auto value_of = [&](std::size_t c, const std::string& what) {
      if (c == kAbsent) return 0.0;
      const auto value = csv::parse_number(fields[c]);
      if (a.options.strict && (!value || !std::isfinite(*value)))
        throw InputError(
            name, line_no, c + 1,
            fmt::format("{} '{}' {}", what, csv::excerpt(fields[c]),
                        !value ? csv::why_not_a_number(fields[c]) : "is not a finite number"));
      return value ? *value : std::nan("");
    };
    std::vector<double>& v = values;
    for (std::size_t k = 0; k < v.size(); ++k)
      if (k != 1) v[k] = value_of(column[k], names[k]);
    // --strict keeps the fixed interval to 1 %: a sample off it would bend every rate after it.
    if (a.options.strict && std::isfinite(previous_time) &&
        std::abs(v[0] - previous_time - dt_s) > 0.01 * dt_s)
      throw InputError(name, line_no, column[0] + 1,
                       fmt::format("time_s steps by {} s, not the {} s of --rate-hz {}",
                                   v[0] - previous_time, dt_s, rate_hz));
    std::uint32_t any = 0;
    outputs.clear();
    for (std::size_t x = 0; x < compensators.size(); ++x) {
      names[1] = set.models[x].dataset.target_column;
      column[1] = gyro_column[x];
      v[1] = value_of(column[1], names[1]);
      StreamingCompensator& compensator = compensators[x];
      further_degc.clear();
      for (std::size_t k : further_of[x]) further_degc.push_back(v[k]);
      const StreamOutput out =
          compensator.update({v[0], v[1], v[2], v[3], v[4], std::span<const double>(further_degc)});
      if (a.options.strict && out.flags != 0)
        stop_at_fault(name, line_no, out.flags, names, column, v, a.options.stream.faults);
      any |= out.flags;
      for (double value :
           {out.drift_dph, out.gyro_comp_dph, compensator.novelty(), compensator.weight()}) {
        outputs += ',';
        outputs += csv::format_number(value);
      }
      outputs += ',';
      outputs += std::to_string(out.flags);
    }
    previous_time = v[0];
    ++samples;
    if (any != 0) ++flagged;
    for (std::size_t k = 0; k < fault::count; ++k)
      if (any & (1u << k)) ++per_flag[k];
    std::cout << line << outputs << '\n';
    // Each line goes out before stream waits for more input: at once from a logger's pipe, whose
    // lines arrive one by one, and a buffer at a time from a file, where a flush per line cost
    // a system call per sample.
    if (lines.buffered() == 0 && in.rdbuf()->in_avail() <= 0) std::cout.flush();
    if (!std::cout) check_standard_output();  // stop at the first line that could not be written
  }
  std::cout.flush();
  if (!std::cout) check_standard_output();
  if (samples == 0)
    throw InputError(name, line_no, 0, "has no sample after its header: nothing was compensated");
  if (flagged == 0 && skipped == 0) return;
  std::vector<std::string> counts;
  for (std::size_t k = 0; k < fault::count; ++k)
    if (per_flag[k] > 0) counts.push_back(fmt::format("{} {}", fault::names()[k], per_flag[k]));
  std::cerr << fmt::format("stream: {} of {} samples flagged ({}){}\n", flagged, samples,
                           counts.empty() ? "none" : fmt::format("{}", fmt::join(counts, ", ")),
                           skipped ? fmt::format("; {} torn lines skipped", skipped) : "");
}

}  // namespace

void add_stream(CLI::App& app) {
  auto args = std::make_shared<StreamArgs>();
  std::string bits;  // "temp_bad 1, temp_stuck 2, …", five to a line
  for (std::size_t k = 0; k < fault::count; ++k)
    bits += fmt::format("{}{} {}", k == 0 ? "" : (k % 5 == 0 ? ",\n  " : ", "), fault::names()[k],
                        1u << k);
  auto* cmd = app.add_subcommand(
      "stream",
      fmt::format(
          "Compensate samples as they arrive: read a recording's CSV line by line from a file or\n"
          "standard input, and write each line to standard output at once with drift_dph,\n"
          "gyro_comp_dph, novelty and guard_weight appended (as fogdrift compensate writes "
          "them),\n"
          "and fault_flags. The features are computed causally, sample by sample, as the firmware\n"
          "of export-c --stream-rate-hz does; train the model with --differentiator causal. Where\n"
          "the inputs are novel to the model the correction is reduced (docs/field.md);\n"
          "--no-guard switches that off.\n"
          "A faulty sample (a reading that is not a number or out of range, a stuck thermometer,\n"
          "a time gap, time not advancing) does not stop the stream: the sensor-fault policy of\n"
          "docs/compensation.md bridges, holds or stops the correction, and fault_flags says\n"
          "what happened, as the sum of these bits:\n  {}.\n"
          "--strict stops at the first faulty sample instead.\n"
          "temp_acc1_degc and temp_acc2_degc are needed only when the model reads them, and\n"
          "a further thermometer temp_NAME_degc when its features do (train --thermometers).\n"
          "Examples:\n"
          "  logger | fogdrift stream causal.json --rate-hz 1 > compensated.csv\n"
          "  fogdrift stream causal.json cal/cal_r4_20C.csv --rate-hz 1",
          bits));
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  add_model_load_flags(cmd, &args->load);
  cmd->add_option("input", args->input, "Recording CSV, or - for standard input")
      ->capture_default_str();
  cmd->add_option("--target", args->target,
                  "With a model of several axes (train --targets): stream this one alone, e.g. "
                  "gyro_y_dph (default: every axis, each with drift_y_dph, gyro_y_comp_dph, "
                  "novelty_y, guard_weight_y, fault_flags_y)");
  args->flags = add_stream_options(cmd);
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
