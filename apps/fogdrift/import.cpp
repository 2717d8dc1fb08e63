// fogdrift import: turn a foreign logger CSV into a fogdrift recording.
#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/import.hpp"
#include "fogdrift/recording.hpp"

namespace fs = std::filesystem;

namespace fogdrift::app {
namespace {

struct ImportArgs {
  std::vector<std::string> inputs;
  std::string out;
  std::vector<std::string> maps;
  std::vector<std::string> units;
  std::string delimiter = ",";
  bool decimal_comma = false;
  bool time_from_zero = false;
  bool drop_extra = false;
};

std::pair<std::string, std::string> split_assignment(const std::string& text,
                                                     const std::string& option) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size()) {
    throw OptionError(fmt::format("{} {}", option, text),
                      "expected FOGDRIFT_COLUMN=VALUE, e.g. gyro_dph=\"Rate X [rad/s]\"");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

char parse_delimiter(const std::string& text) {
  if (text == "," || text == ";" || text == "|") return text[0];
  if (text == "\\t" || text == "\t" || text == "tab") return '\t';
  throw OptionError("--delimiter", fmt::format("'{}' is not one of ',', ';', '|', tab", text));
}

}  // namespace

void add_import(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "import",
      "Convert foreign logger CSV files into fogdrift recordings: map their columns onto\n"
      "fogdrift's and convert units. Unmapped columns are kept as extra columns. Example:\n"
      "  fogdrift import run7.csv -o run7_fd.csv --map time_s=\"t [ms]\" --unit time_s=ms \\\n"
      "    --map gyro_dph=\"Rate X [rad/s]\" --unit gyro_dph=rad/s \\\n"
      "    --map temp_fog_degc=T0 --unit temp_fog_degc=counts:0.0625:-40 ...\n"
      "Units: time_s s|ms|us; gyro_dph deg/h|deg/s|rad/s|mrad/s|arcsec/s; temperatures\n"
      "degC|K|degF|counts:SCALE:OFFSET (°C = counts·SCALE + OFFSET); accel_*_g g|mg|m/s2;\n"
      "table_deg deg|rad. See docs/formats.md.");
  auto a = std::make_shared<ImportArgs>();
  cmd->add_option("INPUT", a->inputs, "Foreign CSV file(s)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", a->out,
                  "Output recording (one input), or an existing folder (several inputs)")
      ->required();
  cmd->add_option("--map", a->maps, "FOGDRIFT_COLUMN=FOREIGN_COLUMN (repeatable)");
  cmd->add_option("--unit", a->units, "FOGDRIFT_COLUMN=UNIT (repeatable)");
  cmd->add_option("--delimiter", a->delimiter, "Field separator: ',' ';' '|' or tab")
      ->capture_default_str();
  cmd->add_flag("--decimal-comma", a->decimal_comma, "Numbers use ',' as the decimal point");
  cmd->add_flag("--time-from-zero", a->time_from_zero,
                "Subtract the first time stamp (for loggers that count from their own boot)");
  cmd->add_flag("--drop-extra", a->drop_extra, "Do not keep unmapped columns");
  cmd->callback([a] {
    ImportOptions o;
    for (const auto& m : a->maps) {
      auto [target, source] = split_assignment(m, "--map");
      o.columns[target] = source;
    }
    for (const auto& u : a->units) {
      auto [target, unit] = split_assignment(u, "--unit");
      o.conversions[target] = parse_unit(target, unit);
    }
    o.delimiter = parse_delimiter(a->delimiter);
    o.decimal_comma = a->decimal_comma;
    o.time_from_zero = a->time_from_zero;
    o.keep_extra = !a->drop_extra;
    const bool to_folder = a->inputs.size() > 1 || fs::is_directory(a->out);
    if (to_folder && !fs::is_directory(a->out)) {
      throw OptionError("--out", fmt::format("'{}' must be an existing folder when importing "
                                             "several files",
                                             a->out));
    }
    // Read and convert everything first, so a bad file leaves no partial set of outputs.
    std::vector<std::pair<fs::path, Recording>> converted;
    for (const auto& input : a->inputs) {
      const fs::path target =
          to_folder ? fs::path(a->out) / fs::path(input).filename() : fs::path(a->out);
      converted.emplace_back(target, import_recording(input, o));
    }
    for (const auto& [target, rec] : converted) {
      write_recording(target, rec);
      std::cout << fmt::format("{} -> {} ({} samples)\n", rec.source, target.string(), rec.size());
    }
  });
}

}  // namespace fogdrift::app
