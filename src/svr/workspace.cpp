#include "fogdrift/svr/workspace.hpp"

#include <cstdint>
#include <utility>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/memory.hpp"
#include "svr/workspace_state.hpp"

namespace fogdrift::svr {

Workspace::Workspace() : state_(std::make_unique<detail::WorkspaceState>()) {}
Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

std::size_t Workspace::bytes() const {
  return state_->blocks.bytes() + state_->values.capacity() * sizeof(double) +
         state_->flags.capacity();
}

void Workspace::clear() {
  state_->order.reset();
  state_->order_cache = nullptr;
  state_->blocks.clear();
  std::vector<double>().swap(state_->values);  // assignment would keep the capacity
  std::vector<std::uint8_t>().swap(state_->flags);
}

WorkspacePool::Lease::~Lease() {
  if (!workspace_) return;
  const std::lock_guard lock(pool_.mutex_);
  pool_.idle_.push_back(std::move(workspace_));
}

WorkspacePool::Lease WorkspacePool::borrow() {
  const std::lock_guard lock(mutex_);
  if (idle_.empty()) {
    auto w = std::make_unique<Workspace>();
    idle_.reserve(made_ + 1);  // room for every lease to come back without allocating
    ++made_;
    return Lease(*this, std::move(w));
  }
  std::unique_ptr<Workspace> w = std::move(idle_.back());
  idle_.pop_back();
  return Lease(*this, std::move(w));
}

std::size_t WorkspacePool::size() const {
  const std::lock_guard lock(mutex_);
  return made_;
}

std::size_t WorkspacePool::bytes() const {
  const std::lock_guard lock(mutex_);
  std::size_t sum = 0;
  for (const auto& w : idle_) sum += w->bytes();
  return sum;
}

std::size_t WorkspacePool::clear() {
  const std::lock_guard lock(mutex_);
  std::size_t freed = 0;
  for (const auto& w : idle_) {
    freed += w->bytes();
    w->clear();
  }
  return freed;
}

std::size_t reserved_row_bytes() {
  return detail::BlockReserve::process().bytes();
}

std::size_t release_reserved_rows() {
  return detail::BlockReserve::process().release();
}

void require_memory_beside_reserve(std::uint64_t need_bytes, std::string_view what,
                                   std::string_view advice) {
  try {
    require_memory(need_bytes, what, advice);
  } catch (const ResourceError&) {
    if (release_reserved_rows() == 0) throw;
    require_memory(need_bytes, what, advice);
  }
}

}  // namespace fogdrift::svr
