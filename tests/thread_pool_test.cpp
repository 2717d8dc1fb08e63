#include "fogdrift/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
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

}  // namespace
}  // namespace fogdrift
