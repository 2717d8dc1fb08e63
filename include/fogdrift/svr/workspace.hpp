// Memory that successive fits reuse (docs/svr.md, "Memory").
//
// A fit writes up to hundreds of megabytes of kernel rows and a dozen arrays per sample. Taken
// fresh for every fit, that memory comes as new pages, and on virtual machines the page faults
// cost a third of a cold fit. A Workspace keeps the row blocks and the solver's arrays of its
// last fit for the next one, so a search of many fits pays for its pages once per workspace.
// Whoever runs fits one after another owns one: fit_c_path for its path, fit_batch and the
// tuner one per running task (WorkspacePool). When a workspace ends, its row blocks go to the
// process's reserve for later fits (reserved_row_bytes below). A workspace changes no result:
// every array is written before it is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>

namespace fogdrift::svr {
namespace detail {
struct WorkspaceState;
}  // namespace detail

/// Memory held between fits: at most two blocks of kernel rows (each at most the fit's
/// Params::cache_mb), the pair solver's per-sample arrays (about 100 bytes a sample), and the
/// sample order and rows a fit leaves for the next fit on the same KernelCache. Used by one fit
/// at a time; it must outlive every KernelCache that uses it. A moved-from workspace may only be
/// assigned to or destroyed.
class Workspace {
 public:
  Workspace();
  ~Workspace();
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  /// Bytes reserved for reuse: the row blocks kept (committed as far as fits wrote them) and the
  /// solver's arrays.
  std::size_t bytes() const;
  /// Gives all of it back to the system.
  void clear();

  detail::WorkspaceState& state() { return *state_; }  ///< the engine's own view

 private:
  std::unique_ptr<detail::WorkspaceState> state_;
};

/// Workspaces for the tasks of a ThreadPool: a task borrows one for its fit and gives it back
/// when the lease ends. There are never more workspaces than tasks that ran at once, and a
/// task gets the one returned last, whose pages are the most likely still in the cache.
/// Thread-safe.
class WorkspacePool {
 public:
  class Lease {
   public:
    Lease(Lease&& other) noexcept : pool_(other.pool_), workspace_(std::move(other.workspace_)) {}
    Lease& operator=(Lease&&) = delete;
    ~Lease();
    Workspace& operator*() const { return *workspace_; }
    Workspace* get() const { return workspace_.get(); }

   private:
    friend class WorkspacePool;
    Lease(WorkspacePool& pool, std::unique_ptr<Workspace> workspace)
        : pool_(pool), workspace_(std::move(workspace)) {}
    WorkspacePool& pool_;
    std::unique_ptr<Workspace> workspace_;
  };

  Lease borrow();
  /// Workspaces made so far (the most tasks that held one at once).
  std::size_t size() const;
  /// Bytes the idle workspaces hold (Workspace::bytes).
  std::size_t bytes() const;
  /// Frees the idle workspaces' memory; returns the bytes freed. Leased ones keep theirs.
  std::size_t clear();

 private:
  mutable std::mutex mutex_;
  std::vector<std::unique_ptr<Workspace>> idle_;
  std::size_t made_ = 0;
};

/// Row memory the process keeps for its later fits after the workspaces and fits that used it
/// have ended (docs/svr.md, "Memory"): at most eight blocks and 1 GiB, committed as far as fits
/// wrote them.
std::size_t reserved_row_bytes();
/// Gives that memory back to the system; returns the bytes freed. Workspaces keep theirs.
std::size_t release_reserved_rows();
/// require_memory (fogdrift/base/memory.hpp) counting the reserved rows as free: when the need
/// does not fit, they are given back and the need checked again. Every check of memory a job
/// of the process will hold goes through it.
void require_memory_beside_reserve(std::uint64_t need_bytes, std::string_view what,
                                   std::string_view advice);

}  // namespace fogdrift::svr
