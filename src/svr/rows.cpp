// The row stores of rows.hpp: RowArena's blocks, the blocks a workspace keeps between fits, and
// the process's reserve of the others.
#include "svr/rows.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

namespace fogdrift::svr::detail {
namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;

// The start of the rows inside a mapping: its first huge-page boundary.
float* rows_start(void* map) {
  const auto start = reinterpret_cast<std::uintptr_t>(map);
  return reinterpret_cast<float*>((start + kHugePage - 1) & ~(kHugePage - 1));
}

using Blocks = std::vector<KeptBlocks::Block>;

std::size_t total_bytes(const Blocks& blocks) {
  std::size_t sum = 0;
  for (const KeptBlocks::Block& b : blocks) sum += b.bytes;
  return sum;
}

Blocks::iterator smallest(Blocks& blocks) {
  return std::min_element(blocks.begin(), blocks.end(),
                          [](const auto& a, const auto& b) { return a.bytes < b.bytes; });
}

// The smallest of `blocks` of at least `bytes`, removed from them; a null block when none is.
KeptBlocks::Block take_smallest(Blocks& blocks, std::size_t bytes) {
  auto best = blocks.end();
  for (auto b = blocks.begin(); b != blocks.end(); ++b)
    if (b->bytes >= bytes && (best == blocks.end() || b->bytes < best->bytes)) best = b;
  if (best == blocks.end()) return {};
  const KeptBlocks::Block out = *best;
  blocks.erase(best);
  return out;
}
}  // namespace

KeptBlocks::Block KeptBlocks::take(std::size_t bytes) {
  return take_smallest(blocks_, bytes);
}

KeptBlocks::~KeptBlocks() {
  for (const Block& b : blocks_) BlockReserve::process().give(b);
}

void KeptBlocks::give(Block block) noexcept {
  if (blocks_.size() < kMost) {
    blocks_.push_back(block);  // within the capacity reserved: no allocation
    return;
  }
  const auto least = smallest(blocks_);
  if (least->bytes < block.bytes) std::swap(*least, block);
  BlockReserve::process().give(block);
}

std::size_t KeptBlocks::bytes() const {
  return total_bytes(blocks_);
}

void KeptBlocks::clear() noexcept {
  for (const Block& b : blocks_) munmap(b.map, b.bytes);
  blocks_.clear();
}

BlockReserve& BlockReserve::process() {
  // Never destroyed: an arena or workspace of a static object may end after any static would.
  static BlockReserve* const reserve = new BlockReserve;
  return *reserve;
}

BlockReserve::Block BlockReserve::take(std::size_t bytes) {
  const std::lock_guard lock(mutex_);
  return take_smallest(blocks_, bytes);
}

void BlockReserve::give(Block block) noexcept {
  if (block.bytes > kMostBytes) {
    munmap(block.map, block.bytes);
    return;
  }
  const std::lock_guard lock(mutex_);
  blocks_.push_back(block);  // within the capacity reserved: no allocation
  std::size_t sum = total_bytes(blocks_);
  while (blocks_.size() > kMostBlocks || sum > kMostBytes) {
    const auto least = smallest(blocks_);
    sum -= least->bytes;
    munmap(least->map, least->bytes);
    blocks_.erase(least);
  }
}

std::size_t BlockReserve::bytes() const {
  const std::lock_guard lock(mutex_);
  return total_bytes(blocks_);
}

std::size_t BlockReserve::release() noexcept {
  const std::lock_guard lock(mutex_);
  const std::size_t sum = total_bytes(blocks_);
  for (const Block& b : blocks_) munmap(b.map, b.bytes);
  blocks_.clear();
  return sum;
}

RowArena::RowArena(std::size_t rows, std::size_t row_floats, KeptBlocks* kept)
    : kept_(kept), rows_(rows), row_floats_(row_floats) {
  const std::size_t bytes = rows * row_floats * sizeof(float);
  if (bytes == 0) return;
  // One huge page more than needed, so that the rows can start on a huge-page boundary.
  const std::size_t need = bytes + kHugePage;
  KeptBlocks::Block block = kept_ != nullptr ? kept_->take(need) : KeptBlocks::Block{};
  if (block.map == nullptr) block = BlockReserve::process().take(need);
  if (block.map != nullptr) {
    map_ = block.map;
    map_bytes_ = block.bytes;
    base_ = rows_start(map_);
    return;
  }
  map_bytes_ = need;
  map_ = mmap(nullptr, map_bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (map_ == MAP_FAILED) {
    map_ = nullptr;
    throw std::bad_alloc();
  }
  base_ = rows_start(map_);
#ifdef MADV_HUGEPAGE
  madvise(base_, (bytes + kHugePage - 1) & ~(kHugePage - 1), MADV_HUGEPAGE);  // advice only
#endif
}

RowArena::~RowArena() {
  release();
}

void RowArena::release() noexcept {
  if (map_ != nullptr) {
    if (kept_ != nullptr)
      kept_->give({map_, map_bytes_});
    else
      BlockReserve::process().give({map_, map_bytes_});
  }
  map_ = nullptr;
  base_ = nullptr;
}

RowArena::RowArena(RowArena&& other) noexcept {
  *this = std::move(other);
}

RowArena& RowArena::operator=(RowArena&& other) noexcept {
  if (this != &other) {
    release();
    kept_ = std::exchange(other.kept_, nullptr);
    map_ = std::exchange(other.map_, nullptr);
    map_bytes_ = std::exchange(other.map_bytes_, 0);
    base_ = std::exchange(other.base_, nullptr);
    rows_ = std::exchange(other.rows_, 0);
    row_floats_ = std::exchange(other.row_floats_, 0);
  }
  return *this;
}

}  // namespace fogdrift::svr::detail
