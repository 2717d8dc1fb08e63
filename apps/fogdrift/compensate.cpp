// fogdrift compensate: subtract a model's predicted drift from a recording (METHOD.md §2 step 5).
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "fogdrift/atomic_file.hpp"
#include "fogdrift/csv.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/eval/metrics.hpp"
#include "fogdrift/model.hpp"

namespace fogdrift::app {
namespace {

struct CompensateArgs {
  std::string model;
  std::string input;
  std::string output;
  bool json = false;
  bool quiet = false;
};

void run(const CompensateArgs& a) {
  const CompensationModel model = load_compensation_model(a.model);
  const csv::Table table = csv::read(a.input);
  for (const char* name : {"drift_dph", "gyro_comp_dph"})
    if (table.find(name))
      throw InputError(
          table.file, 1, *table.find(name) + 1,
          fmt::format("already has a {} column; compensate the original recording", name));
  const Recording recording = read_recording(a.input);
  const std::vector<double> drift = model.predict_dph(recording);
  std::vector<double> compensated(drift.size());
  for (std::size_t i = 0; i < drift.size(); ++i) compensated[i] = recording.gyro_dph[i] - drift[i];

  std::string text;
  auto add_fields = [&text](const std::vector<std::string>& fields) {
    for (const auto& f : fields) {
      text += csv::quote(f);
      text += ',';
    }
  };
  add_fields(table.header);
  text += "drift_dph,gyro_comp_dph\n";
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    add_fields(table.rows[i]);
    text += csv::format_number(drift[i]);
    text += ',';
    text += csv::format_number(compensated[i]);
    text += '\n';
  }
  write_text_atomically(a.output, text);
  // STD of the gyro before and after (gyro − drift), as evaluate computes them.
  const eval::CompensationMetrics m = eval::compensation_metrics(recording.gyro_dph, drift);

  if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.model;
    j["method"] = to_string(model.provenance.method);
    j["input"] = a.input;
    j["output"] = a.output;
    j["samples"] = drift.size();
    j["gyro_std_dph"] = m.std_before_dph;
    j["gyro_comp_std_dph"] = m.std_after_dph;
    j["drift_first_dph"] = drift.front();
    j["drift_last_dph"] = drift.back();
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    std::cout << fmt::format(
        "{}: {} samples compensated with {} ({})\n"
        "  predicted drift {:.4f} → {:.4f} °/h from first to last sample\n"
        "  gyro STD {:.4f} °/h, compensated {:.4f} °/h (sample rate, noise included)\n"
        "  wrote {}\n",
        a.input, drift.size(), a.model, to_string(model.provenance.method), drift.front(),
        drift.back(), m.std_before_dph, m.std_after_dph, a.output);
  }
}

}  // namespace

void add_compensate(CLI::App& app) {
  auto args = std::make_shared<CompensateArgs>();
  auto* cmd = app.add_subcommand(
      "compensate",
      "Subtract a compensation model's predicted drift from a recording. Every column of IN is\n"
      "written back as read, followed by drift_dph (the predicted drift, °/h) and gyro_comp_dph\n"
      "(gyro_dph − drift_dph). The features are computed at the recording's own rate with the\n"
      "model's differentiator, so the output has one row per input row.\n"
      "Example:\n"
      "  fogdrift train cal -o model.json && fogdrift compensate model.json cal/cal_r4_20C.csv "
      "-o comp.csv");
  cmd->add_option("model", args->model, "Model file written by `fogdrift train`")->required();
  cmd->add_option("input", args->input, "Recording CSV")->required();
  cmd->add_option("-o,--output", args->output, "CSV to write (atomically)")->required();
  cmd->add_flag("--json", args->json, "Print a summary as JSON");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->callback([args] { run(*args); });
}

}  // namespace fogdrift::app
