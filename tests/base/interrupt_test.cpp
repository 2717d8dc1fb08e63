// A host's interrupt (base/interrupt.hpp): a pending request stops the thread pool before its
// next task and an SVR fit at its first shrinking round, and once cleared changes nothing.
#include "fogdrift/base/interrupt.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>

#include "fogdrift/base/random.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift {
namespace {

svr::Data sine_data(std::size_t rows) {
  svr::Data d;
  d.rows = rows;
  d.cols = 2;
  Rng rng(3);
  for (std::size_t i = 0; i < rows; ++i) {
    const double a = rng.uniform(-3, 3), b = rng.uniform(-3, 3);
    d.x.insert(d.x.end(), {a, b});
    d.y.push_back(std::sin(a) * std::cos(b) + rng.normal(0, 0.1));
  }
  return d;
}

TEST(Interrupt, APendingRequestStopsThePoolAndIsCleared) {
  ThreadPool pool(2);
  std::atomic<int> ran{0};
  request_interrupt();
  EXPECT_THROW(pool.parallel_for(8, [&](std::size_t) { ++ran; }), Interrupted);
  EXPECT_EQ(ran.load(), 0);
  clear_interrupt();
  pool.parallel_for(8, [&](std::size_t) { ++ran; });
  EXPECT_EQ(ran.load(), 8);
}

TEST(Interrupt, AnSvrFitStopsWithinARoundOfTheRequest) {
  const svr::TrainingSet set(sine_data(3000));
  svr::Params p;
  p.c = 1000;
  p.epsilon = 0.001;
  p.tolerance = 1e-6;
  const svr::FitResult whole = svr::fit(set, p);
  ASSERT_GT(whole.summary.solver.iterations, 1000);  // so the fit reaches a shrinking round
  request_interrupt();
  EXPECT_THROW(svr::fit(set, p), Interrupted);
  clear_interrupt();
  const svr::FitResult again = svr::fit(set, p);
  EXPECT_EQ(again.summary.solver.iterations, whole.summary.solver.iterations);
  EXPECT_EQ(again.model.rho, whole.model.rho);
}

}  // namespace
}  // namespace fogdrift
