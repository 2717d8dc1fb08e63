// Workspaces (fogdrift/svr/workspace.hpp): memory reused from fit to fit, results unchanged.
#include "fogdrift/svr/workspace.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <cstring>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "fogdrift/base/memory.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/svr.hpp"
#include "svr/datasets.hpp"
#include "svr/rows.hpp"

namespace fogdrift::svr {
namespace {

// Two models are the same when every number is the same bit pattern.
void expect_same(const Model& a, const Model& b, const char* what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(&a.rho, &b.rho, sizeof a.rho), 0);
  EXPECT_EQ(a.coef, b.coef);
  EXPECT_EQ(a.support_vectors, b.support_vectors);
}

TEST(Workspace, FitsOfEverySizeAndSolverGiveTheModelsTheyGiveAlone) {
  // One workspace through fits that grow, shrink and change solver, kernel and data: whatever
  // the last fit left in it (rows, arrays, a sample order) must not change the next one.
  const Data big = testing::startup_like(900, 2), small = testing::smooth(250, 3, 0.1, 4);
  const TrainingSet big_set(big), small_set(small);
  Workspace workspace;
  EXPECT_EQ(workspace.bytes(), 0u);
  struct Case {
    const TrainingSet* set;
    double c;
    Kernel kernel;
    bool libsvm_path, conjugate;
  };
  const Case cases[] = {
      {&small_set, 1, Kernel::rbf_sigma(1.0), false, true},
      {&big_set, 10, Kernel::rbf_sigma(0.7), false, true},
      {&small_set, 100, Kernel::rbf_sigma(1.0), false, false},
      {&big_set, 1, Kernel::rbf_sigma(1.0), true, true},
      {&big_set, 3, Kernel::linear(), false, true},
      {&small_set, 10, Kernel::rbf_sigma(2.0), true, true},
      {&big_set, 10, Kernel::rbf_sigma(0.7), false, true},
  };
  for (const Case& k : cases) {
    Params p;
    p.c = k.c;
    p.kernel = k.kernel;
    p.libsvm_path = k.libsvm_path;
    p.conjugate = k.conjugate;
    p.cache_mb = 1;  // small enough that rows are evicted and recomputed
    const FitResult alone = fit(*k.set, p);
    const FitResult shared = fit(*k.set, p, nullptr, &workspace);
    expect_same(shared.model, alone.model, k.libsvm_path ? "LIBSVM path" : "pair solver");
    EXPECT_EQ(shared.summary.solver.iterations, alone.summary.solver.iterations);
    EXPECT_GT(workspace.bytes(), 0u);
  }
  // The pair solver's arrays for 900 samples (11 doubles each) and at least one row block.
  EXPECT_GE(workspace.bytes(), 900u * 11 * sizeof(double) + 900u * sizeof(float));
  workspace.clear();
  EXPECT_EQ(workspace.bytes(), 0u);
}

TEST(Workspace, AFitReusesTheMemoryOfTheLastOneInsteadOfGrowing) {
  const Data d = testing::startup_like(600, 3);
  const TrainingSet set(d);
  Workspace workspace;
  Params p;
  p.kernel = Kernel::rbf_sigma(1.0);
  fit(set, p, nullptr, &workspace);
  const std::size_t after_one = workspace.bytes();
  for (const double c : {0.5, 2.0, 8.0}) {
    p.c = c;
    fit(set, p, nullptr, &workspace);
    EXPECT_EQ(workspace.bytes(), after_one) << "C=" << c;
  }
}

TEST(Workspace, ACPathGivesTheSameModelsWithTheCallersWorkspaceOrItsOwn) {
  const Data d = testing::startup_like(500, 6);
  const TrainingSet set(d);
  Params base;
  base.kernel = Kernel::rbf_sigma(1.0);
  const std::vector<double> cs{0.3, 3, 30};
  Workspace workspace;
  fit(set, base, nullptr, &workspace);  // leaves rows and arrays behind
  const auto own = fit_c_path(set, base, cs);
  const auto given = fit_c_path(set, base, cs, &workspace);
  const auto again = fit_c_path(set, base, cs, &workspace);
  for (std::size_t k = 0; k < cs.size(); ++k) {
    expect_same(given[k].model, own[k].model, "given");
    expect_same(again[k].model, own[k].model, "given again");
  }
}

TEST(Workspace, AnOrderLeftOnACacheEndsWithThatCache) {
  // The pair solver leaves its order and rows in the workspace for the next fit on the same
  // cache; a new cache, even at the same address, must start from the identity order. Under
  // AddressSanitizer a row kept past its cache would also be a use after free.
  const Data a = testing::smooth(300, 3, 0.1, 1), b = testing::smooth(300, 3, 0.1, 2);
  const TrainingSet set_a(a), set_b(b);
  Workspace workspace;
  const Kernel kernel = Kernel::rbf_sigma(1.0);
  SolverOptions options;
  std::vector<double> alpha_alone;
  {
    KernelCache q(set_b, kernel, 0);
    DualSolution out;
    solve_epsilon_svr(q, b.y, 10, 0.1, options, out);
    alpha_alone = out.alpha;
  }
  {
    KernelCache q(set_a, kernel, 0, &workspace);
    DualSolution out;
    solve_epsilon_svr(q, a.y, 10, 0.1, options, out);
  }
  KernelCache q(set_b, kernel, 0, &workspace);
  DualSolution out;
  solve_epsilon_svr(q, b.y, 10, 0.1, options, out);
  EXPECT_EQ(out.alpha, alpha_alone);
}

#if !defined(__SANITIZE_ADDRESS__)
// A 200 MB block (mapped, not written) for the reserve; exit status 3 when it is not there.
void fill_the_reserve() {
  release_reserved_rows();
  { detail::RowArena block(1, 50'000'000, nullptr); }  // goes to the reserve at its end
  if (reserved_row_bytes() < 200'000'000) std::_Exit(3);
}

// In a child process: the reserve holds 200 MB, the address space is limited to 100 MB above the
// current size, and a fit needs about 152 MB. The check must give the reserve back rather than
// refuse the fit; so must the same check of any other need (a training set's, a campaign's).
// Exit status 0 when all holds.
[[noreturn]] void needs_that_fit_only_without_the_reserve() {
  const Data d = testing::startup_like(7000, 3);
  const TrainingSet set(d);
  Params p;
  p.cache_mb = 150;  // below the whole matrix (196 MB): the fit needs the cache and a little
  fill_the_reserve();
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  rlimit r{};
  r.rlim_cur = r.rlim_max =
      pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)) + (std::uint64_t{100} << 20);
  if (setrlimit(RLIMIT_AS, &r) != 0) std::_Exit(4);
  try {
    require_fit_memory(set, p, 1);
  } catch (const std::exception&) {
    std::_Exit(5);
  }
  if (reserved_row_bytes() != 0) std::_Exit(6);
  fill_the_reserve();
  try {
    require_memory_beside_reserve(std::uint64_t{150} << 20, "a 150 MB job", "");
  } catch (const std::exception&) {
    std::_Exit(7);
  }
  std::_Exit(reserved_row_bytes() == 0 ? 0 : 8);
}

TEST(WorkspaceDeathTest, AMemoryCheckGivesTheReservedRowsBackFirst) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(needs_that_fit_only_without_the_reserve(), ::testing::ExitedWithCode(0), "");
}
#endif

// A search's memory check counts the solutions it keeps as warm starts beside its fits, and
// names them when they are what does not fit.
TEST(Workspace, AMemoryCheckCountsTheSolutionsACallerKeeps) {
  const TrainingSet set(testing::startup_like(300, 3));
  const Params p;
  EXPECT_NO_THROW(require_fit_memory(set, p, 2));
  try {
    require_fit_memory(set, p, 2, std::uint64_t{1} << 62);
    ADD_FAILURE() << "4 EiB of kept solutions were not refused";
  } catch (const ResourceError& e) {
    EXPECT_NE(std::string(e.what()).find("2 SVR fits at once of 300 rows with a 200 MB kernel "
                                         "cache each, and 4 EiB of solutions kept as warm "
                                         "starts needs about 4 EiB"),
              std::string::npos)
        << e.what();
  }
}

TEST(WorkspacePool, LendsOneWorkspaceToEachTaskRunningAtOnce) {
  WorkspacePool pool;
  Workspace* first = nullptr;
  {
    const auto a = pool.borrow();
    const auto b = pool.borrow();
    EXPECT_NE(a.get(), b.get());
    first = a.get();  // `a` goes back last
    EXPECT_EQ(pool.size(), 2u);
  }
  {
    const auto c = pool.borrow();  // the one returned last
    EXPECT_EQ(c.get(), first);
  }
  EXPECT_EQ(pool.size(), 2u);
  EXPECT_EQ(pool.bytes(), 0u);
  {
    const auto w = pool.borrow();
    const TrainingSet set(testing::smooth(200, 3, 0.1, 2));
    fit(set, Params{}, nullptr, w.get());
  }
  const std::size_t held = pool.bytes();
  EXPECT_GT(held, 0u);
  EXPECT_EQ(pool.clear(), held);
  EXPECT_EQ(pool.bytes(), 0u);

  // From threads: never more workspaces than tasks held at once, never one in two hands.
  ThreadPool threads(2);
  std::vector<Workspace*> used(64);
  threads.parallel_for(used.size(), [&](std::size_t k) {
    const auto w = pool.borrow();
    used[k] = w.get();
    std::this_thread::yield();
  });
  EXPECT_EQ(pool.size(), 2u);  // two threads, and two were made already
  EXPECT_LE(std::set<Workspace*>(used.begin(), used.end()).size(), 2u);
}

TEST(WorkspacePool, ABatchGivesTheSameModelsAsFitsAlone) {
  const Data d = testing::startup_like(400, 7);
  const TrainingSet set(d);
  std::vector<Params> grid;
  for (const double c : {1.0, 10.0, 100.0})
    for (const double sigma : {0.7, 1.4}) {
      Params p;
      p.c = c;
      p.kernel = Kernel::rbf_sigma(sigma);
      grid.push_back(p);
    }
  ThreadPool threads(2);
  const auto batch = fit_batch(set, grid, threads);
  for (std::size_t k = 0; k < grid.size(); ++k)
    expect_same(batch[k].model, fit(set, grid[k]).model, "batch");
}

}  // namespace
}  // namespace fogdrift::svr
