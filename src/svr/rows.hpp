// Every store of kernel rows the solvers use, in one unit (docs/svr.md, "Memory"):
//  * RowArena — the memory: one block per store, reserved up front, in transparent huge pages;
//  * KeptBlocks — blocks a Workspace (workspace.hpp) keeps from one fit for the next;
//  * BlockReserve — blocks no workspace or arena holds any more, for the process's later fits;
//  * DataInOrder — the features in a solver's sample order, to compute rows straight into it;
//  * OrderedRows — kernel rows in a solver's variable order, least recently used evicted;
//  * SampleOrder — a pair solver's order and its rows, kept from one fit to the next.
// The rows as LIBSVM caches them, by training sample, are the public KernelCache (kernel.hpp),
// whose memory is a RowArena too. Internal header: not installed.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "fogdrift/svr/kernel.hpp"
#include "svr/loops.hpp"

namespace fogdrift::svr::detail {

/// Mapped blocks of row memory that outlived their RowArena, for the next one: their pages are
/// already committed, so a fit that takes one pays no page faults for it. At most two are kept,
/// the largest, since a fit holds two arenas (the kernel rows and the solver's order).
class KeptBlocks {
 public:
  struct Block {
    void* map = nullptr;
    std::size_t bytes = 0;
  };

  KeptBlocks() { blocks_.reserve(kMost); }
  ~KeptBlocks();  // the blocks go to the process's BlockReserve
  KeptBlocks(const KeptBlocks&) = delete;
  KeptBlocks& operator=(const KeptBlocks&) = delete;

  /// The smallest kept block of at least `bytes`, no longer kept; a null block when none is.
  Block take(std::size_t bytes);
  /// Keeps `block`; when two are kept already, the smallest of the three goes to the process's
  /// BlockReserve.
  void give(Block block) noexcept;
  /// Bytes mapped by the kept blocks.
  std::size_t bytes() const;
  /// Unmaps every kept block.
  void clear() noexcept;

 private:
  static constexpr std::size_t kMost = 2;
  std::vector<Block> blocks_;
};

/// The row blocks of a process that no workspace keeps and no arena uses any more: a workspace's
/// when it ends, a plain fit's when it ends, the smaller ones a workspace gives up. A later
/// RowArena of any thread takes one before it maps a new block, so a process commits its row
/// memory about once, at the most it uses at one time, instead of once per search or per fit
/// (docs/svr.md, "Memory": a page freed to the system and taken again seconds later can cost as
/// much as one never touched). At most kMostBlocks blocks and kMostBytes are kept, the largest;
/// svr::release_reserved_rows (workspace.hpp) unmaps them. Thread-safe.
class BlockReserve {
 public:
  using Block = KeptBlocks::Block;
  static constexpr std::size_t kMostBlocks = 8;
  static constexpr std::size_t kMostBytes = std::size_t{1} << 30;

  /// The process's reserve.
  static BlockReserve& process();

  /// The smallest block of at least `bytes`, no longer kept; a null block when none is.
  Block take(std::size_t bytes);
  /// Keeps `block`, then unmaps the smallest blocks while more than kMostBlocks or kMostBytes
  /// are kept; a block larger than kMostBytes is unmapped at once.
  void give(Block block) noexcept;
  std::size_t bytes() const;
  /// Unmaps every block kept; returns their bytes.
  std::size_t release() noexcept;

 private:
  BlockReserve() { blocks_.reserve(kMostBlocks + 1); }
  mutable std::mutex mutex_;
  std::vector<Block> blocks_;
};

/// One block of row memory, reserved up front and backed by the kernel's transparent huge pages
/// where it allows them. A fit touches up to hundreds of megabytes of fresh row memory, and on
/// the virtual machines this was measured on, the page faults of 4 KiB pages were a third of a
/// cold fit's time; pages of 2 MiB take 512 times fewer faults. Pages are committed when a row
/// is first written, so an unused budget costs no memory. The block comes from, and goes back
/// to, the KeptBlocks given, so that the next fit of a workspace reuses its committed pages;
/// without one, or when it has no block large enough, from the process's BlockReserve.
class RowArena {
 public:
  RowArena() = default;
  /// Room for `rows` rows of `row_floats` floats each, from `kept` when it holds a large enough
  /// block (and back to it at the end), else from the BlockReserve, else freshly mapped; `kept`
  /// may be null (the block goes back to the reserve) and must outlive the arena. Throws
  /// std::bad_alloc.
  RowArena(std::size_t rows, std::size_t row_floats, KeptBlocks* kept);
  ~RowArena();
  RowArena(RowArena&& other) noexcept;
  RowArena& operator=(RowArena&& other) noexcept;
  RowArena(const RowArena&) = delete;
  RowArena& operator=(const RowArena&) = delete;

  float* row(std::size_t r) const { return base_ + r * row_floats_; }
  std::size_t rows() const { return rows_; }

 private:
  KeptBlocks* kept_ = nullptr;
  void* map_ = nullptr;
  std::size_t map_bytes_ = 0;
  float* base_ = nullptr;
  std::size_t rows_ = 0, row_floats_ = 0;
  void release() noexcept;
};

/// The training features in a solver's sample order, feature-major, so that kernel rows can be
/// computed straight into that order: row r at positions [begin, end) is K(x_r, x_index[j]), the
/// same floats as TrainingSet::kernel_row(r)[index[j]] in the same arithmetic (the same
/// operations and rounding). The single-arithmetic RBF kernel reads the features in float, the
/// others in double.
class DataInOrder {
 public:
  /// The identity order. `set` must outlive this object and keep no distance matrix.
  DataInOrder(const TrainingSet& set, const Kernel& kernel, KernelArithmetic arithmetic)
      : set_(set), kernel_(kernel), n_(set.size()), d_(set.dims()) {
    in_float_ = kernel_.type != KernelType::linear && arithmetic == KernelArithmetic::single;
    if (in_float_) {
      xt_f32_.resize(n_ * d_);
      for (std::size_t j = 0; j < n_; ++j)
        for (std::size_t f = 0; f < d_; ++f) xt_f32_[f * n_ + j] = set.row_f32(j)[f];
    } else {
      xt_.resize(n_ * d_);
      sq_.resize(n_);
      for (std::size_t j = 0; j < n_; ++j) {
        for (std::size_t f = 0; f < d_; ++f) xt_[f * n_ + j] = set.data().row(j)[f];
        sq_[j] = set.squared_norm(j);
      }
    }
  }

  /// Positions a and b trade samples.
  void swap(std::size_t a, std::size_t b) {
    if (in_float_) {
      for (std::size_t f = 0; f < d_; ++f) std::swap(xt_f32_[f * n_ + a], xt_f32_[f * n_ + b]);
    } else {
      for (std::size_t f = 0; f < d_; ++f) std::swap(xt_[f * n_ + a], xt_[f * n_ + b]);
      std::swap(sq_[a], sq_[b]);
    }
  }

  /// out[j] = K(x_r, x at position j) for begin ≤ j < end.
  void row(std::size_t r, std::size_t begin, std::size_t end, float* out) const {
    if (kernel_.type == KernelType::linear)
      loops_.linear_row(set_.data().row(r), xt_.data() + begin, n_, end - begin, d_, out + begin);
    else if (in_float_)
      loops_.rbf_row(set_.row_f32(r), xt_f32_.data() + begin, n_, end - begin, d_, kernel_.gamma,
                     out + begin);
    else
      loops_.libsvm_rbf_row(set_.data().row(r), set_.squared_norm(r), xt_.data() + begin, n_,
                            sq_.data() + begin, end - begin, d_, kernel_.gamma, out + begin);
  }

 private:
  const Loops& loops_ = loops();
  const TrainingSet& set_;
  Kernel kernel_;
  std::size_t n_, d_;
  bool in_float_ = false;
  std::vector<double> xt_;     // d × n, column j the sample at position j
  std::vector<double> sq_;     // its squared norm
  std::vector<float> xt_f32_;  // the same in float, for the single-arithmetic RBF kernel
};

/// Kernel rows in a solver's variable order: row r of the kernel read at the solver's positions,
/// K_r[index[j]], so that an iteration reads contiguous memory instead of gathering two rows
/// (LIBSVM gathers both rows every iteration). The order changes only when shrinking swaps
/// variables (every ~1000 iterations); in between the working sets reuse a few hundred rows.
/// Bounded by a row count, least recently used evicted first. Rows come from the KernelCache, one
/// indexed copy each, or, with `direct`, are computed straight into the solver's order from a
/// DataInOrder that follows every swap: then no second copy of a row exists, and a row is
/// computed only as far as the active set reaches (about half of it at C = 1, N = 6000).
///
/// The swaps of each shrinking round are kept in a log, and a row catches up with them only when
/// it is next asked for: by replaying them, or by starting again when it is far behind. Rows that
/// are never used again cost nothing (bringing every cached row up to date at each round took a
/// tenth of a fit at C = 1, N = 6000).
class OrderedRows {
 public:
  /// Rows of `length` entries over `kernel_rows` distinct kernel rows; `index` maps a solver
  /// position to a kernel row and must outlive this object. `direct` (only when positions are
  /// samples, length = kernel_rows, and the data keeps no distance matrix): compute rows in order.
  /// The row memory comes from, and goes back to, `kept` (may be null: no reuse).
  OrderedRows(KernelCache& q, const std::int32_t* index, std::size_t length,
              std::size_t kernel_rows, double cache_mb, KeptBlocks* kept, bool direct = false)
      : q_(q), index_(index), length_(length), slot_of_row_(kernel_rows, -1) {
    if (direct)
      direct_ = std::make_unique<DataInOrder>(q.training_set(), q.kernel(), q.arithmetic());
    const double slot_bytes = static_cast<double>(length) * sizeof(float);
    capacity_ = static_cast<std::size_t>(std::max(
        2.0,
        std::min(std::floor(cache_mb * (1 << 20) / slot_bytes), static_cast<double>(kernel_rows))));
    arena_ = RowArena(capacity_, length, kept);
  }

  /// Kernel row r in solver order, entries [0, len) current at least. Valid until the next call
  /// that has to evict a row (at least two are kept). Not to be called between swapped() and
  /// apply_swaps().
  const float* row(std::int32_t r, std::size_t len) {
    std::int32_t s = slot_of_row_[r];
    if (s < 0) {
      if (slots_.size() < capacity_) {
        s = static_cast<std::int32_t>(slots_.size());
        slots_.emplace_back();
      } else {
        s = 0;
        for (std::size_t t = 1; t < slots_.size(); ++t)
          if (slots_[t].last_use < slots_[s].last_use) s = static_cast<std::int32_t>(t);
        slot_of_row_[slots_[s].kernel_index] = -1;
      }
      slots_[s].kernel_index = r;
      slots_[s].valid = 0;
      slots_[s].order = order_;
      slot_of_row_[r] = s;
    }
    Slot& slot = slots_[s];
    if (slot.order != order_) catch_up(slot, data(s));
    slot.last_use = ++clock_;
    if (slot.valid < len) {
      if (direct_) {
        direct_->row(static_cast<std::size_t>(r), slot.valid, len, data(s));
        ++rows_computed_;
      } else {
        gather(q_.row(static_cast<std::size_t>(r)), index_, slot.valid, len, data(s));
      }
      slot.valid = len;
    }
    return data(s);
  }

  /// Rows (or parts of rows) computed in order; the KernelCache counts the rest.
  std::int64_t rows_computed() const { return rows_computed_; }

  /// Records that the solver swapped positions a and b (the index array is already swapped).
  void swapped(std::size_t a, std::size_t b) {
    log_.emplace_back(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b));
    if (direct_) direct_->swap(a, b);
  }

  /// Ends a round of swaps: the rows are now out of date and catch up when next asked for.
  void apply_swaps() {
    if (log_.size() == round_begin_) return;
    round_start_.push_back(round_begin_);
    ++order_;
    // The log is bounded: past a few row lengths of swaps, a row gathers again anyway.
    if (log_.size() > 4 * length_) {
      log_.clear();
      round_start_.clear();
      first_logged_order_ = order_;
    }
    round_begin_ = log_.size();
  }

 private:
  struct Slot {
    std::int32_t kernel_index = -1;
    std::size_t valid = 0;  // entries [0, valid) are current for `order`
    std::uint64_t order = 0, last_use = 0;
  };
  KernelCache& q_;
  const std::int32_t* index_;
  std::size_t length_;
  std::unique_ptr<DataInOrder> direct_;  // set when rows are computed in order
  std::vector<std::int32_t> slot_of_row_;
  std::vector<Slot> slots_;
  std::size_t capacity_ = 2;
  std::uint64_t order_ = 1, clock_ = 0;
  std::int64_t rows_computed_ = 0;
  // The swaps of the rounds from first_logged_order_ on; round o (taking order o to o + 1)
  // starts at log_[round_start_[o − first_logged_order_]].
  std::vector<std::pair<std::int32_t, std::int32_t>> log_;
  std::vector<std::size_t> round_start_;
  std::uint64_t first_logged_order_ = 1;
  std::size_t round_begin_ = 0;  // where the swaps of the round under way start
  RowArena arena_;               // capacity_ rows of length_ floats

  // Brings a row from its order to the current one. Replaying a swap costs less than rebuilding an
  // entry, which may mean recomputing the row, so a row replays the swaps it missed unless they
  // outnumber its valid entries four to one; then it starts again.
  void catch_up(Slot& slot, float* d) {
    const std::uint64_t from = slot.order;
    slot.order = order_;
    if (from < first_logged_order_ || slot.valid == 0) {
      slot.valid = 0;
      return;
    }
    const std::size_t begin = round_start_[static_cast<std::size_t>(from - first_logged_order_)];
    if ((log_.size() - begin) >= 4 * slot.valid) {
      slot.valid = 0;
      return;
    }
    if (slot.valid == length_) {  // a whole row: every swap applies, no bounds to check
      for (std::size_t k = begin; k < log_.size(); ++k)
        std::swap(d[log_[k].first], d[log_[k].second]);
      return;
    }
    for (std::size_t k = begin; k < log_.size(); ++k) {
      const auto [a, b] = log_[k];
      const auto lo = static_cast<std::size_t>(std::min(a, b));
      const auto hi = static_cast<std::size_t>(std::max(a, b));
      if (hi < slot.valid)
        std::swap(d[lo], d[hi]);
      else if (lo < slot.valid)
        slot.valid = lo;
    }
  }

  float* data(std::int32_t s) const { return arena_.row(static_cast<std::size_t>(s)); }
};

/// A pair solver's sample order and its rows in that order. The workspace of a KernelCache keeps
/// it from one fit on that cache to the next (fit_c_path), which starts in this order with the
/// rows still valid instead of building them again from the identity order.
struct SampleOrder {
  std::vector<std::int32_t> index;  // position → training sample
  std::unique_ptr<OrderedRows> rows;
};

}  // namespace fogdrift::svr::detail
