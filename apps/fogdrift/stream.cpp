// fogdrift stream: the causal streaming compensator on samples as they arrive
// (StreamingCompensator, compensator.hpp), one CSV line in, one line out, flushed, as firmware
// would run it.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/compensator.hpp"
#include "fogdrift/csv.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/features.hpp"
#include "fogdrift/model.hpp"
#include "fogdrift/recording.hpp"

namespace fogdrift::app {
namespace {

struct StreamArgs {
  bool allow_edited = false;
  std::string model;
  std::string input = "-";
  double rate_hz = 0;
  bool no_guard = false;
};

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',')
      out.emplace_back();
    else if (c != '\r')
      out.back() += c;
  }
  return out;
}

void run(const StreamArgs& a) {
  if (!(a.rate_hz > 0) || a.rate_hz > 1000)
    throw OptionError("--rate-hz", fmt::format("{} is outside (0, 1000] Hz", a.rate_hz));
  const CompensationModel model = load_compensation_model(a.model, {a.allow_edited});
  const double dt_s = 1.0 / a.rate_hz;
  StreamingCompensator compensator(model, dt_s, !a.no_guard);

  std::ifstream file;
  if (a.input != "-") {
    file.open(a.input);
    if (!file) throw InputError(a.input, 0, 0, "cannot be opened for reading");
  }
  std::istream& in = a.input == "-" ? std::cin : file;
  const std::string name = a.input == "-" ? "<stdin>" : a.input;

  std::string line;
  if (!std::getline(in, line)) throw InputError(name, 1, 0, "is empty; a header line is needed");
  const std::vector<std::string> header = split(line);
  constexpr std::array<const char*, 5> kNeeded = {"time_s", "gyro_dph", "temp_fog_degc",
                                                  "temp_acc1_degc", "temp_acc2_degc"};
  // The accelerometers' thermometers are needed only when the model reads them.
  const FeatureSpec& spec = model.dataset.features;
  const std::array<bool, 5> needed = {true, true, true, spec.reads(Thermometer::acc1),
                                      spec.reads(Thermometer::acc2)};
  constexpr std::size_t kAbsent = static_cast<std::size_t>(-1);
  std::array<std::size_t, 5> column{};
  for (std::size_t k = 0; k < kNeeded.size(); ++k) {
    const auto it = std::find(header.begin(), header.end(), kNeeded[k]);
    if (it == header.end() && needed[k])
      throw InputError(name, 1, 0, fmt::format("has no {} column", kNeeded[k]));
    column[k] = it == header.end() ? kAbsent : static_cast<std::size_t>(it - header.begin());
  }
  for (const char* added : {"drift_dph", "gyro_comp_dph", "novelty", "guard_weight"})
    if (std::find(header.begin(), header.end(), added) != header.end())
      throw InputError(
          name, 1, 0, fmt::format("already has a {} column; stream the original recording", added));
  std::cout << line << ",drift_dph,gyro_comp_dph,novelty,guard_weight\n" << std::flush;

  std::size_t line_no = 1;
  double previous_time = std::nan("");
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line == "\r") continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != header.size())
      throw InputError(name, line_no, 0,
                       fmt::format("has {} fields, the header {}", fields.size(), header.size()));
    std::array<double, 5> v{};  // a thermometer the model does not read, and the file lacks: 0
    for (std::size_t k = 0; k < kNeeded.size(); ++k) {
      if (column[k] == kAbsent) continue;
      const auto value = csv::parse_number(fields[column[k]]);
      if (!value || !std::isfinite(*value))
        throw InputError(
            name, line_no, column[k] + 1,
            fmt::format("{} '{}' is not a finite number", kNeeded[k], fields[column[k]]));
      v[k] = *value;
    }
    // The compensator's rates assume the fixed interval: a sample off it by more than 1 % is
    // a gap or a wrong --rate-hz, and would bend every rate after it.
    if (std::isfinite(previous_time) && std::abs(v[0] - previous_time - dt_s) > 0.01 * dt_s)
      throw InputError(name, line_no, column[0] + 1,
                       fmt::format("time_s steps by {} s, not the {} s of --rate-hz {}",
                                   v[0] - previous_time, dt_s, a.rate_hz));
    previous_time = v[0];
    const double drift = compensator.update({v[0], v[1], v[2], v[3], v[4]});
    std::cout << line << ',' << csv::format_number(drift) << ',' << csv::format_number(v[1] - drift)
              << ',' << csv::format_number(compensator.novelty()) << ','
              << csv::format_number(compensator.weight()) << '\n'
              << std::flush;
  }
}

}  // namespace

void add_stream(CLI::App& app) {
  auto args = std::make_shared<StreamArgs>();
  auto* cmd = app.add_subcommand(
      "stream",
      "Compensate samples as they arrive: read a recording's CSV line by line from a file or\n"
      "standard input, and write each line to standard output at once with drift_dph,\n"
      "gyro_comp_dph, novelty and guard_weight appended (as fogdrift compensate writes them). The\n"
      "features are computed causally, sample by sample, as the firmware of export-c\n"
      "--stream-rate-hz does; train the model with --differentiator causal. Where the inputs are\n"
      "novel to the model the correction is reduced (docs/field.md); --no-guard switches that "
      "off.\n"
      "A sample whose time step is off the fixed interval stops the stream with its line.\n"
      "temp_acc1_degc and temp_acc2_degc are needed only when the model reads them.\n"
      "Examples:\n"
      "  logger | fogdrift stream causal.json --rate-hz 1 > compensated.csv\n"
      "  fogdrift stream causal.json cal/cal_r4_20C.csv --rate-hz 1");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  cmd->add_flag("--allow-edited", args->allow_edited,
                "Load a model file whose content no longer matches its checksum (an edit made on "
                "purpose); its fields are still checked");
  cmd->add_option("input", args->input, "Recording CSV, or - for standard input")
      ->capture_default_str();
  cmd->add_option("--rate-hz", args->rate_hz, "The logger's fixed sample rate, Hz")->required();
  cmd->add_flag("--no-guard", args->no_guard,
                "Apply the model's full correction even where its inputs are novel");
  cmd->callback([args] { with_model_settings(args->model, [&] { run(*args); }); });
}

}  // namespace fogdrift::app
