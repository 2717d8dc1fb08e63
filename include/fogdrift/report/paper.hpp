// The paper's experiment end to end on the simulator (docs/method.md §3, docs/paper.md):
//
//   1. simulate the calibration campaign (§4.1), the north-finding start-ups at the paper's seven
//      initial temperatures (§4.2) and the stable stage;
//   2. train BP, SVR, PSO-SVR, GWO-SVR and SSA-SVR on repetitions 1–3;
//   3. Table 2: MAE and compensated STD on repetition 4, beside the denoised STD;
//   4. Table 3: four-position north-finding RMSE per initial temperature, raw and compensated by
//      every method, and the stable stage's RMSE; Table 1 is SSA-SVR's C and σ;
//   5. repeat for several seeds (every random choice of a seed — simulator and optimizers —
//      derives from it), and, on the first seed, two studies beyond the paper: leave one
//      calibration temperature out, and the paper's training-loss fitness against grouped
//      cross-validation.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/eval/metrics.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/regress/mlp.hpp"
#include "fogdrift/report/figure.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/method.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift::report {

/// The compared methods, in the paper's order (Table 2, Table 3).
inline constexpr std::array<Method, 5> kPaperMethods = {Method::bp, Method::svr, Method::pso_svr,
                                                        Method::gwo_svr, Method::ssa_svr};

struct PaperOptions {
  /// The methods run and reported, in this order: the paper's, and any others (poly, gp) after
  /// them. BP and SSA-SVR must be among them (the report and the studies compare them).
  std::vector<Method> methods{kPaperMethods.begin(), kPaperMethods.end()};
  std::size_t seeds = 5;         ///< independent repetitions of the whole experiment, ≥ 1
  std::uint64_t first_seed = 1;  ///< the seeds are first_seed, first_seed + 1, …
  /// Optimizer budget of each tuned SVR. The paper does not state its budget; 10 × 20 keeps the
  /// default run under ten minutes and reaches the same optimum as 20 × 50 on the default
  /// instrument (docs/paper.md).
  std::size_t population = 10;
  std::size_t iterations = 20;
  tune::Fitness fitness = tune::Fitness::cv;  ///< fitness of the tuned SVRs
  /// Folds of the tuned SVRs' `cv` fitness: by default three folds of whole calibration
  /// temperatures, which score a candidate where it was not trained, as a start-up at a new
  /// temperature does; needs at least three calibration temperatures. `repetition` leaves one
  /// training repetition out instead (docs/paper.md compares them). With temperature
  /// folds, BP's early stopping holds out a training repetition (train.hpp): it is not refitted.
  tune::CvOptions cv{tune::CvScheme::temperature, 3};
  /// ε of the tuned SVRs' tube (standardised target), when fixed. The paper does not state it.
  /// Measured on the default instrument: the cv fitness improves from LIBSVM's 0.1 down to 0.05
  /// and no further at 0.03, while fits slow as the tube narrows (docs/paper.md).
  double epsilon = 0.05;
  bool search_epsilon = false;  ///< the tuned SVRs also search ε (beyond the paper's C and σ)
  MlpOptions mlp;               ///< BP's settings; its seed is each run's seed
  bool studies = true;          ///< leave-one-temperature-out and fitness studies on the first seed
  sim::Instrument instrument;
  /// docs/field.md's five-sweep protocol (sim::field_calibration(): repetitions 1–4 start up
  /// as calibration, soaked, warm and ramping; 5, the chamber's protocol, is Table 2's test);
  /// the paper's own is one approach, `calibration`, and 4 repetitions. Its seed is replaced by
  /// each run's seed.
  sim::CalibrationOptions calibration = sim::field_calibration();
  sim::NorthfindOptions northfind;  ///< its seed likewise
  sim::NorthfindOptions stable = sim::stable_defaults();
  /// The start-up conditions table (docs/field.md): every method finds north on start-ups of
  /// each of these approaches (same temperatures and findings as `northfind`), guarded and not.
  /// Empty: no table.
  std::vector<sim::Approach> start_ups{sim::Approach::calibration, sim::Approach::soaked,
                                       sim::Approach::warm, sim::Approach::ramping};
  /// Adds the causal SSA-SVR row to the start-up conditions table: the tuned C, σ and ε refitted
  /// on causal rates (`fogdrift train --differentiator causal`), the model `stream` and the C
  /// header run; one SVR fit per seed.
  bool causal = true;
  /// Runs the seeds' method tasks and the studies side by side (a search is then serial inside its
  /// task); results do not depend on it.
  ThreadPool* pool = nullptr;
  /// Called at every stage with what is being done and the fraction of the run done, [0, 1].
  std::function<void(const std::string& stage, double fraction)> progress;
};

/// Throws OptionError naming the option for impossible settings.
void validate(const PaperOptions& options);

/// One method on one seed.
struct MethodRun {
  Method method = Method::ssa_svr;
  eval::CompensationMetrics table2;  ///< on the test repetition, pooled
  std::vector<double> rmse_deg;      ///< Table 3: per north-finding temperature
  double mean_rmse_deg = 0;          ///< mean of rmse_deg, as the paper's "mean" column
  std::vector<std::pair<std::string, double>> hyperparameters;
  double fitness_value = 0;  ///< the training summary's fitness (standardised RMSE)
  double train_seconds = 0;
  /// Mean start-up north-finding RMSE under each of PaperOptions::start_ups, with the novelty
  /// guard (as every north-finding above) and without it.
  std::vector<double> start_up_rmse_deg, start_up_unguarded_rmse_deg;
  /// Under each start-up condition, guarded: the share of the drift's own error removed,
  /// finding by finding (eval/field.hpp, drift_error_removed); NaN without the true drift.
  std::vector<double> start_up_drift_error_removed;
  /// The named hyperparameter ("C", "sigma", "epsilon", "hidden", …), NaN if the method has none.
  double hyperparameter(std::string_view name) const;
};

struct SeedRun {
  std::uint64_t seed = 0;
  double denoised_std_dph = 0;       ///< Table 2's "denoised data" row
  std::vector<double> raw_rmse_deg;  ///< Table 3's raw row
  double raw_mean_rmse_deg = 0;
  /// Table 3 with the simulator's true thermal drift subtracted (its `drift_true_dph`): what a
  /// perfect compensation would reach, the floor for every method. Empty without that column.
  std::vector<double> oracle_rmse_deg;
  double oracle_mean_rmse_deg = 0;
  double stable_rmse_deg = 0;
  /// Under each of PaperOptions::start_ups: mean raw RMSE and the floor (true drift subtracted;
  /// NaN without it).
  std::vector<double> start_up_raw_rmse_deg, start_up_floor_rmse_deg;
  /// The same for SSA-SVR as firmware runs it (PaperOptions::causal): its C, σ and ε refitted on
  /// causal rates and applied causally, sample by sample, guarded and not. Empty when not run.
  std::vector<double> causal_start_up_rmse_deg, causal_start_up_unguarded_rmse_deg;
  std::vector<double> causal_start_up_drift_error_removed;  ///< as MethodRun's, guarded
  std::vector<MethodRun> methods;                           ///< in PaperOptions::methods order
  /// Time of the seed's own work (simulation and its methods' tasks, each on one thread); the
  /// seeds' tasks run side by side on the pool, so the seeds' sum exceeds the run's wall time.
  double seconds = 0;
  const MethodRun& method(Method m) const;  ///< throws std::out_of_range if not run
};

/// Leave-one-temperature-out: trained without every recording of one calibration temperature,
/// tested on that temperature's test recording; beside the model trained on everything.
struct LotoRow {
  double temp_degc = 0;
  Method method = Method::ssa_svr;  ///< ssa_svr (its tuned C, σ refitted) or bp
  double denoised_std_dph = 0;
  double std_all_dph = 0;   ///< compensated STD, model trained on every temperature
  double std_loto_dph = 0;  ///< compensated STD, this temperature left out
  double mae_all_dph = 0;
  double mae_loto_dph = 0;
};

/// SSA-SVR tuned with each fitness.
struct FitnessRow {
  tune::Fitness fitness = tune::Fitness::cv;
  double c = 0, sigma = 0;
  double fitness_value = 0;  ///< its own fitness at the optimum
  double std_dph = 0;        ///< Table 2 compensated STD
  double mae_dph = 0;
  double mean_rmse_deg = 0;  ///< Table 3 mean
};

struct PaperResult {
  PaperOptions options;  ///< as run (progress and pool cleared)
  std::vector<double> northfind_temps_degc;
  std::vector<SeedRun> seeds;
  std::vector<LotoRow> loto;        ///< first seed; empty without studies
  std::vector<FitnessRow> fitness;  ///< first seed; empty without studies
  std::vector<Figure> figures;      ///< drawn from the first seed (and the seeds' means)
  double seconds = 0;
};

PaperResult run_paper(const PaperOptions& options);

}  // namespace fogdrift::report
