// Memory for kernel rows: one block per cache, reserved up front and backed by the kernel's
// transparent huge pages where it allows them. Internal header: not installed.
//
// Why: a fit touches up to hundreds of megabytes of fresh row memory, and on the virtual machines
// this was measured on, the page faults of 4 KiB pages were a third of a cold fit's time. Pages
// of 2 MiB take 512 times fewer faults. The block is only reserved; pages are committed when a row
// is first written, so an unused budget costs no memory.
#pragma once

#include <cstddef>

namespace fogdrift::svr::detail {

class RowArena {
 public:
  RowArena() = default;
  /// Room for `rows` rows of `row_floats` floats each. Throws std::bad_alloc.
  RowArena(std::size_t rows, std::size_t row_floats);
  ~RowArena();
  RowArena(RowArena&& other) noexcept;
  RowArena& operator=(RowArena&& other) noexcept;
  RowArena(const RowArena&) = delete;
  RowArena& operator=(const RowArena&) = delete;

  float* row(std::size_t r) const { return base_ + r * row_floats_; }
  std::size_t rows() const { return rows_; }

 private:
  void* map_ = nullptr;
  std::size_t map_bytes_ = 0;
  float* base_ = nullptr;
  std::size_t rows_ = 0, row_floats_ = 0;
  void release() noexcept;
};

}  // namespace fogdrift::svr::detail
