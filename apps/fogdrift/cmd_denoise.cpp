// fogdrift denoise: wavelet-threshold denoising of one column of a CSV file (docs/method.md §2 step
// 1).
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/signal/denoise.hpp"
#include "fogdrift/signal/denoise_option_table.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct DenoiseArgs {
  std::string input;
  std::string output;
  std::string column = "gyro_dph";
  bool json = false;
  bool quiet = false;
  std::shared_ptr<OptionFlags> flags;  // the denoising options (denoise_option_table.hpp)
};

void run(const DenoiseArgs& a) {
  signal::DenoiseOptions options;
  a.flags->apply(signal::denoise_option_table(), options);

  csv::Table table = csv::read(a.input);
  check_output_not_input(a.output, "--output");
  const auto col = table.find(a.column);
  if (!col) {
    std::string names;
    for (const auto& h : table.header) names += (names.empty() ? "" : ", ") + h;
    throw InputError(table.file, 1, 0,
                     fmt::format("no column '{}' to denoise; the columns are {}", a.column, names));
  }
  std::vector<double> x(table.rows.size());
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto v = csv::parse_number(table.rows[i][*col]);
    if (!v) {
      throw InputError(
          table.file, table.row_line[i], *col + 1,
          fmt::format("'{}' in column {} is not a finite number", table.rows[i][*col], a.column));
    }
    x[i] = *v;
  }
  signal::DenoiseResult result;
  try {
    result = signal::denoise(x, options);
  } catch (const OptionError& e) {
    // Named by its flag, with the file whose length made it impossible.
    const OptionError named = a.flags->named(e);
    throw OptionError(named.option(),
                      fmt::format("{} ({}, column {})", named.message(), table.file, a.column));
  }

  std::string text;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    text += (c ? "," : "") + csv::quote(table.header[c]);
  }
  text += '\n';
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    const auto& row = table.rows[i];
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) text += ',';
      text += c == *col ? csv::format_number(result.signal[i]) : csv::quote(row[c]);
    }
    text += '\n';
  }
  write_text_atomically(a.output, text);

  const auto& s = result.summary;
  if (a.json) {
    nlohmann::ordered_json j;
    j["input"] = a.input;
    j["output"] = a.output;
    j["column"] = a.column;
    j["samples"] = x.size();
    j["wavelet"] = options.wavelet;
    j["level"] = s.level;
    j["threshold"] = signal::to_string(options.threshold);
    j["mode"] = signal::to_string(options.shrinkage);
    j["extension"] = signal::to_string(options.extension);
    j["noise_sigma"] = s.noise_sigma;
    for (const auto& b : s.bands) {
      j["bands"].push_back(
          {{"level", b.level}, {"size", b.size}, {"threshold", b.threshold}, {"kept", b.kept}});
    }
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    std::size_t kept = 0, total = 0;
    for (const auto& b : s.bands) {
      kept += b.kept;
      total += b.size;
    }
    std::cout << fmt::format(
        "{}: denoised {} ({} samples) with {}, {} levels, {} {} thresholds, {} extension\n"
        "  noise sigma {:.6g} (finest band); {} of {} detail coefficients kept\n"
        "  wrote {}\n",
        a.input, a.column, x.size(), options.wavelet, s.level, signal::to_string(options.threshold),
        signal::to_string(options.shrinkage), signal::to_string(options.extension), s.noise_sigma,
        kept, total, a.output);
  }
}

}  // namespace

void add_denoise(CLI::App& app) {
  auto args = std::make_shared<DenoiseArgs>();
  auto* cmd = app.add_subcommand(
      "denoise",
      "Wavelet-denoise one column of a CSV file (a recording's gyro_dph by default) and write the\n"
      "file again with that column replaced; every other column is left as it was.\n\n"
      "The column is decomposed with a multilevel DWT (PyWavelets' wavedec conventions), every\n"
      "detail band is shrunk towards zero, the approximation is kept, and the signal is rebuilt.\n"
      "Noise sigma = median(|finest detail|) / 0.6745. Threshold rules:\n"
      "  universal  sigma * sqrt(2 ln N) on every band (VisuShrink)\n"
      "  level      the same with sigma estimated per band (coloured noise)\n"
      "  sure       per band, minimising Stein's unbiased risk estimate (SureShrink)\n"
      "  bayes      per band, sigma^2 / sigma_signal (BayesShrink)\n"
      "The defaults (sym4, bayes, soft, maximum level) left the least noise on simulated FOG\n"
      "start-ups; docs/signal.md has the measurement.\n\n"
      "Example:\n"
      "  fogdrift denoise cal_rep1_25C.csv -o cal_rep1_25C_denoised.csv\n"
      "  fogdrift denoise log.csv -o out.csv --column rate --wavelet db4 --level 6 \\\n"
      "      --threshold universal --mode hard --extension periodization");
  cmd->add_option("INPUT", args->input, "CSV file with a header row")->required();
  cmd->add_option("-o,--output", args->output,
                  "Output CSV (written atomically; not INPUT, which it would destroy)")
      ->required();
  cmd->add_option("--column", args->column, "Column to denoise")->capture_default_str();
  const auto& table = signal::denoise_option_table();
  args->flags = std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table));
  cmd->add_flag("--json", args->json, "Print the thresholds per band as JSON");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->callback([args] { run(*args); });
}

}  // namespace fogdrift::app
