// The row stores of src/svr/rows.hpp: rows in a solver's order against the kernel rows they
// stand for, through rounds of swaps and evictions, and the row memory kept between fits.
#include "svr/rows.hpp"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "svr/datasets.hpp"

namespace fogdrift::svr {
namespace {

TEST(OrderedRows, RowsCatchUpWithEveryRoundOfSwaps) {
  // Rows in solver order are brought up to date only when asked for, by replaying the swaps of
  // the rounds they missed or by gathering (computing) again; either way they must equal the
  // kernel row read through the current order, bit for bit, whether they are gathered from the
  // KernelCache or computed in order from features that follow the swaps. Small budgets make
  // both caches evict, rounds of up to 400 swaps make rows replay, start again, and outlive the
  // bounded swap log.
  const Data d = testing::smooth(300, 4, 0.1, 5);
  const TrainingSet set(d);
  for (const Kernel k : {Kernel::rbf_sigma(0.7), Kernel::linear()}) {
    for (const bool direct : {false, true}) {
      SCOPED_TRACE(direct ? "computed in order" : "gathered");
      KernelCache q(set, k, 0.02);
      const std::size_t n = d.rows;
      std::vector<std::int32_t> index(n);
      for (std::size_t t = 0; t < n; ++t) index[t] = static_cast<std::int32_t>(t);
      detail::OrderedRows rows(q, index.data(), n, n, 0.03, nullptr, direct);
      std::vector<float> expected(n);
      Rng rng(8);
      for (int round = 0; round < 60; ++round) {
        const int swaps = static_cast<int>(rng.uniform(0, round % 7 == 6 ? 400 : 20));
        for (int s = 0; s < swaps; ++s) {
          const auto a = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(n)));
          const auto b = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(n)));
          if (a == b) continue;
          std::swap(index[a], index[b]);
          rows.swapped(a, b);
        }
        rows.apply_swaps();
        for (int r = 0; r < 30; ++r) {
          const auto row = static_cast<std::int32_t>(rng.uniform(0, 40));  // a few, reused
          const auto len = static_cast<std::size_t>(rng.uniform(1, static_cast<double>(n) + 1));
          const float* got = rows.row(row, len);
          set.kernel_row(k, static_cast<std::size_t>(row), expected.data());
          for (std::size_t t = 0; t < len; ++t)
            ASSERT_EQ(got[t], expected[static_cast<std::size_t>(index[t])])
                << "round " << round << " row " << row << " position " << t;
        }
      }
      EXPECT_EQ(rows.rows_computed() > 0, direct);
    }
  }
}

TEST(RowArena, ReusesTheBlocksKeptForItAndKeepsAtMostTheTwoLargest) {
  release_reserved_rows();  // no block of an earlier test serves these arenas
  detail::KeptBlocks kept;
  float* first = nullptr;
  {
    detail::RowArena a(8, 1000, &kept);
    first = a.row(0);
    for (std::size_t r = 0; r < 8; ++r) a.row(r)[999] = static_cast<float>(r);  // writable
    EXPECT_EQ(a.row(7)[999], 7.0f);
    EXPECT_EQ(a.row(1) - a.row(0), 1000);
    EXPECT_EQ(kept.bytes(), 0u);
  }
  const std::size_t one = kept.bytes();
  EXPECT_GE(one, 8u * 1000 * sizeof(float));
  {
    detail::RowArena again(4, 1000, &kept);  // smaller: the kept block serves it
    EXPECT_EQ(again.row(0), first);
    EXPECT_EQ(again.row(3)[999], 3.0f);  // the same committed pages
    EXPECT_EQ(kept.bytes(), 0u);
    detail::RowArena alone(8, 1000, nullptr);  // no workspace: a block of its own
    EXPECT_NE(alone.row(0), first);
  }
  EXPECT_EQ(kept.bytes(), one);  // `alone`'s block went to the process's reserve
  EXPECT_EQ(reserved_row_bytes(), one);
  release_reserved_rows();
  {
    detail::RowArena larger(1 << 20, 1, &kept);  // too large for the kept block: a new one
    EXPECT_NE(larger.row(0), first);
    detail::RowArena second(8, 1000, &kept);  // the kept block is taken again
    EXPECT_EQ(second.row(0), first);
    detail::RowArena third(2, 1000, &kept);  // nothing kept is left
    EXPECT_NE(third.row(0), first);
    detail::RowArena moved = std::move(third);  // a moved arena still gives its block back
  }
  // Three blocks came back; the two largest are kept: `larger` (its rows and the huge page of
  // alignment room) and `second`'s. The third went to the reserve.
  const std::size_t larger_bytes = (std::size_t{4} << 20) + (std::size_t{2} << 20);
  EXPECT_EQ(kept.bytes(), larger_bytes + one);
  EXPECT_EQ(reserved_row_bytes(), (std::size_t{2} << 20) + 2 * 1000 * sizeof(float));
  const detail::KeptBlocks::Block big = kept.take(std::size_t{4} << 20);
  ASSERT_NE(big.map, nullptr);
  EXPECT_EQ(kept.bytes(), one);
  kept.give(big);
  kept.clear();
  EXPECT_EQ(kept.bytes(), 0u);
  EXPECT_EQ(kept.take(1).map, nullptr);
  detail::RowArena empty(0, 1000, &kept);  // nothing reserved
  EXPECT_EQ(empty.rows(), 0u);
  release_reserved_rows();
}

TEST(BlockReserve, ServesLaterArenasOfAnyWorkspaceAndKeepsTheLargestWithinItsBounds) {
  using detail::BlockReserve;
  release_reserved_rows();
  EXPECT_EQ(reserved_row_bytes(), 0u);
  const std::size_t room = std::size_t{2} << 20;  // each block's alignment room
  float* first = nullptr;
  {
    detail::KeptBlocks kept;  // a workspace's blocks, which go to the reserve when it ends
    detail::RowArena a(4, 1000, &kept);
    first = a.row(0);
    a.row(1)[999] = 3.0f;
  }
  const std::size_t one = reserved_row_bytes();
  EXPECT_EQ(one, room + 4 * 1000 * sizeof(float));
  {
    detail::KeptBlocks other;  // another workspace, or a fit of its own, takes that block
    detail::RowArena b(2, 1000, &other);
    EXPECT_EQ(b.row(0), first);
    EXPECT_EQ(b.row(1)[999], 3.0f);  // the same committed pages
    EXPECT_EQ(reserved_row_bytes(), 0u);
    detail::RowArena c(2, 1000, nullptr);  // nothing left: a new block
    EXPECT_NE(c.row(0), first);
  }
  EXPECT_EQ(reserved_row_bytes(), one + room + 2 * 1000 * sizeof(float));
  // At most kMostBlocks blocks: the smallest go first. The first two arenas take the blocks of
  // `c` and `a`, of room for 2 and 4 rows; the others map blocks of 3 to 11 rows.
  {
    std::vector<detail::RowArena> arenas;
    for (std::size_t k = 0; k < BlockReserve::kMostBlocks + 3; ++k)
      arenas.emplace_back(k + 1, 1000, nullptr);
  }
  EXPECT_EQ(reserved_row_bytes(), BlockReserve::kMostBlocks * room +
                                      (4 + 5 + 6 + 7 + 8 + 9 + 10 + 11) * 1000 * sizeof(float));
  // At most kMostBytes: a block larger than that is not kept at all, and the others stay.
  const std::size_t before = reserved_row_bytes();
  {
    detail::RowArena large(1, BlockReserve::kMostBytes / sizeof(float), nullptr);
    large.row(0)[0] = 1.0f;  // commits one page
  }
  EXPECT_EQ(reserved_row_bytes(), before);
  EXPECT_EQ(release_reserved_rows(), before);
  EXPECT_EQ(reserved_row_bytes(), 0u);
}

}  // namespace
}  // namespace fogdrift::svr
