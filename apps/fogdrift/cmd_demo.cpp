// fogdrift demo: the main job. Runs `fogdrift paper` — the paper's experiment on the built-in
// simulator, Tables 1–3 beside the paper's values, the start-up conditions table and the figures —
// with two seeds instead of five, a search of 10 × 10 instead of 10 × 20, and without the two
// studies, writing into ./fogdrift-demo/. docs/paper.md, "The demo", gives the measurements that
// chose this: the same tables and goals in under a third of the time.
#include <memory>

#include "commands.hpp"

namespace fogdrift::app {

void add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "demo",
      "The main job: `fogdrift paper` with 2 seeds instead of 5, a search of population 10 ×\n"
      "10 iterations instead of 20, and without the leave-one-temperature-out and fitness\n"
      "studies: about a minute on two cores (docs/paper.md, \"The demo\"). Prints the\n"
      "paper's Tables 1-3 beside fogdrift's, the goals and the start-up conditions table, and\n"
      "writes report.md, paper.json and the figures into ./fogdrift-demo/ (replaced on every\n"
      "run). Every option of `fogdrift paper --help` applies: --iterations 20 for paper's search.");
  auto a = std::make_shared<PaperArgs>();
  a->defaults.seeds = 2;
  a->defaults.iterations = 10;
  a->defaults.studies = false;
  a->out = "fogdrift-demo";
  a->force = true;
  add_paper_options(cmd, *a);
  cmd->callback([a] { run_paper_command(*a); });
}

}  // namespace fogdrift::app
