#include "fogdrift/base/thread_pool.hpp"

#include <exception>

#include "fogdrift/base/interrupt.hpp"

namespace fogdrift {
namespace {
thread_local bool t_inside_task = false;
}

ThreadPool::ThreadPool(unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  workers_.reserve(threads - 1);
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& w : workers_) w.join();
}

void ThreadPool::run_tasks() {
  // Called with mutex_ held; takes indices one at a time until none are left.
  while (next_ < task_count_) {
    const std::size_t i = next_++;
    const auto* fn = task_;
    mutex_.unlock();
    std::exception_ptr err;
    const bool was_inside = t_inside_task;
    t_inside_task = true;
    try {
      check_interrupt();  // base/interrupt.hpp: no new task once a stop was asked
      (*fn)(i);
    } catch (...) {
      err = std::current_exception();
    }
    t_inside_task = was_inside;
    mutex_.lock();
    if (err && (!error_ || i < error_index_)) {
      error_ = err;
      error_index_ = i;
    }
    if (--unfinished_ == 0) done_.notify_all();
  }
}

void ThreadPool::worker_loop() {
  std::unique_lock lock(mutex_);
  // Every loop since construction is new to a worker: one that starts only after the first
  // parallel_for has begun must still join it (reading generation_ here missed that loop, and a
  // fresh pool's first loop then ran on the calling thread alone).
  std::size_t seen = 0;
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
    if (stopping_) return;
    seen = generation_;
    ++busy_workers_;
    run_tasks();
    if (--busy_workers_ == 0) done_.notify_all();
  }
}

void ThreadPool::parallel_for(std::size_t n, const std::function<void(std::size_t)>& fn) {
  if (n == 0) return;
  if (workers_.empty() || n == 1 || t_inside_task) {
    // Serial, still with lowest-index-first exception semantics.
    std::exception_ptr first;
    for (std::size_t i = 0; i < n; ++i) {
      try {
        check_interrupt();
        fn(i);
      } catch (...) {
        if (!first) first = std::current_exception();
      }
    }
    if (first) std::rethrow_exception(first);
    return;
  }
  std::unique_lock lock(mutex_);
  // Wait until workers from a previous loop have left run_tasks (they hold no task pointer).
  done_.wait(lock, [&] { return !running_ && busy_workers_ == 0; });
  running_ = true;
  task_ = &fn;
  task_count_ = n;
  next_ = 0;
  unfinished_ = n;
  error_ = nullptr;
  ++generation_;
  wake_.notify_all();
  run_tasks();
  done_.wait(lock, [&] { return unfinished_ == 0; });
  task_ = nullptr;
  task_count_ = 0;
  running_ = false;
  auto err = error_;
  error_ = nullptr;
  lock.unlock();
  done_.notify_all();
  if (err) std::rethrow_exception(err);
}

}  // namespace fogdrift
