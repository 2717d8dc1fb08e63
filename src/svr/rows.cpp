// The row stores of rows.hpp: RowArena's blocks, kept per thread between fits.
#include "svr/rows.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <new>
#include <utility>
#include <vector>

namespace fogdrift::svr::detail {
namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
constexpr std::size_t kKeptPerThread = 2;  // a fit holds two arenas (kernel rows, solver order)

struct Mapping {
  void* map = nullptr;
  std::size_t bytes = 0;
};

// Mappings released by this thread's last fits, reused by its next ones: their pages are already
// committed, so a search of many fits pays the page faults once per thread, not once per fit.
struct Kept {
  std::vector<Mapping> maps;
  ~Kept() {
    for (const auto& m : maps) munmap(m.map, m.bytes);
  }
};
thread_local Kept kept;

// The start of the rows inside a mapping: its first huge-page boundary.
float* rows_start(void* map) {
  const auto start = reinterpret_cast<std::uintptr_t>(map);
  return reinterpret_cast<float*>((start + kHugePage - 1) & ~(kHugePage - 1));
}
}  // namespace

RowArena::RowArena(std::size_t rows, std::size_t row_floats)
    : rows_(rows), row_floats_(row_floats) {
  const std::size_t bytes = rows * row_floats * sizeof(float);
  if (bytes == 0) return;
  // One huge page more than needed, so that the rows can start on a huge-page boundary.
  const std::size_t need = bytes + kHugePage;
  std::size_t best = kept.maps.size();
  for (std::size_t k = 0; k < kept.maps.size(); ++k)
    if (kept.maps[k].bytes >= need &&
        (best == kept.maps.size() || kept.maps[k].bytes < kept.maps[best].bytes))
      best = k;
  if (best < kept.maps.size()) {
    map_ = kept.maps[best].map;
    map_bytes_ = kept.maps[best].bytes;
    kept.maps.erase(kept.maps.begin() + static_cast<std::ptrdiff_t>(best));
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
    // Keep the largest mappings for the next fit of this thread; unmap the rest.
    Mapping m{map_, map_bytes_};
    if (kept.maps.size() < kKeptPerThread) {
      kept.maps.push_back(m);
    } else {
      auto smallest =
          std::min_element(kept.maps.begin(), kept.maps.end(),
                           [](const Mapping& a, const Mapping& b) { return a.bytes < b.bytes; });
      if (smallest->bytes < m.bytes) std::swap(*smallest, m);
      munmap(m.map, m.bytes);
    }
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
    map_ = std::exchange(other.map_, nullptr);
    map_bytes_ = std::exchange(other.map_bytes_, 0);
    base_ = std::exchange(other.base_, nullptr);
    rows_ = std::exchange(other.rows_, 0);
    row_floats_ = std::exchange(other.row_floats_, 0);
  }
  return *this;
}

}  // namespace fogdrift::svr::detail
