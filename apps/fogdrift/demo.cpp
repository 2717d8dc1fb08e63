// fogdrift demo: the main job. Runs `fogdrift paper` — the paper's experiment on the built-in
// simulator, Tables 1–3 beside the paper's values, the two studies and the figures — with two
// seeds instead of five, which finishes in about six minutes on two cores (the field protocol's
// five repetitions: docs/field.md), writing into ./fogdrift-demo/.
#include <memory>

#include "commands.hpp"

namespace fogdrift::app {

void add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "demo",
      "The main job: `fogdrift paper` with 2 seeds instead of 5 (the same search, population\n"
      "10 × 20 iterations), about six minutes on two cores. Prints the paper's Tables 1-3\n"
      "beside fogdrift's and the start-up conditions table, and writes report.md, paper.json\n"
      "and the figures into ./fogdrift-demo/ (replaced on every run). `fogdrift paper --help`\n"
      "explains every option.");
  auto a = std::make_shared<PaperArgs>();
  a->seeds = 2;
  a->out = "fogdrift-demo";
  a->force = true;
  add_paper_options(cmd, *a);
  cmd->callback([a] { run_paper_command(*a); });
}

}  // namespace fogdrift::app
