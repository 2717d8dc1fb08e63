#include "fogdrift/base/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace fogdrift {
namespace {

TEST(ThreadPool, RunsEveryIndexOnceAndRethrowsTheLowestFailure) {
  for (unsigned threads : {1u, 2u, 4u}) {
    ThreadPool pool(threads);
    EXPECT_EQ(pool.size(), threads);
    std::vector<int> hits(1000, 0);
    pool.parallel_for(hits.size(), [&](std::size_t i) { hits[i] += 1; });
    for (int h : hits) EXPECT_EQ(h, 1);
    try {
      pool.parallel_for(100, [](std::size_t i) {
        if (i == 17 || i == 60) throw std::runtime_error("index " + std::to_string(i));
      });
      FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "index 17");
    }
    // Nested loops run serially inside a task instead of deadlocking.
    std::atomic<int> count{0};
    pool.parallel_for(8, [&](std::size_t) { pool.parallel_for(8, [&](std::size_t) { ++count; }); });
    EXPECT_EQ(count.load(), 64);
  }
}

TEST(ThreadPool, AFreshPoolsFirstLoopRunsOnEveryThread) {
  // Two tasks that each wait for the other can only finish together if two threads run them.
  // A worker that started after the first loop had begun used to miss that loop, so the calling
  // thread ran both tasks alone (fit_batch on a new pool ran serially).
  for (int trial = 0; trial < 20; ++trial) {
    ThreadPool pool(2);
    std::atomic<int> arrived{0};
    std::atomic<int> met{0};
    pool.parallel_for(2, [&](std::size_t) {
      ++arrived;
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (arrived.load() < 2 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
      if (arrived.load() == 2) ++met;
    });
    ASSERT_EQ(met.load(), 2) << "trial " << trial << ": the tasks ran one after the other";
  }
}

}  // namespace
}  // namespace fogdrift
