// A fixed pool of worker threads for data-parallel loops.
//
// parallel_for(n, fn) runs fn(i) once for every i in [0, n) on the pool's workers and the calling
// thread, and returns when all are done. Which thread runs which i is not fixed, so callers write
// results by index and never accumulate across indices: that is how fogdrift's results stay the
// same whatever the thread count. A parallel_for called from inside a task runs serially on that
// thread (no nested parallelism, no deadlock); loops started from several outside threads run one
// after another.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fogdrift {

class ThreadPool {
 public:
  /// `threads` counts the calling thread: 1 runs everything on the caller, 0 means one per
  /// hardware thread.
  explicit ThreadPool(unsigned threads = 0);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  /// Threads that work on a loop, the caller included.
  unsigned size() const { return static_cast<unsigned>(workers_.size()) + 1; }

  /// Runs fn(i) for i in [0, n). If any call throws, the exception of the lowest such i is
  /// rethrown after all calls have finished.
  void parallel_for(std::size_t n, const std::function<void(std::size_t)>& fn);

 private:
  void worker_loop();
  void run_tasks();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t task_count_ = 0;
  std::size_t next_ = 0;
  std::size_t unfinished_ = 0;
  std::size_t generation_ = 0;
  std::size_t busy_workers_ = 0;
  bool stopping_ = false;
  bool running_ = false;  // a parallel_for is in progress (callers from other threads wait)
  std::size_t error_index_ = 0;
  std::exception_ptr error_;
};

}  // namespace fogdrift
