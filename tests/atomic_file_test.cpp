#include "fogdrift/atomic_file.hpp"

#include <gtest/gtest.h>

#include "fogdrift/error.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

namespace fs = std::filesystem;

std::size_t entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, FailedWriteLeavesTheOldFileAndNoTemporary) {
  test::TempDir dir;
  const fs::path target = dir / "out.csv";
  write_text_atomically(target, "old\n");
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_EQ(test::read_file(target), "old\n");
  EXPECT_EQ(entries(dir.path()), 1u);
}

TEST(AtomicFile, UnwritableFolderIsAnInputError) {
  EXPECT_THROW(write_text_atomically("/nonexistent-folder/x.csv", "x"), InputError);
}

TEST(AtomicDirectory, FailureLeavesNothingBehind) {
  test::TempDir dir;
  const fs::path target = dir / "campaign";
  EXPECT_THROW(fill_directory_atomically(target, false,
                                         [](const fs::path& tmp) {
                                           test::write_file(tmp / "a.csv", "x");
                                           throw std::runtime_error("simulated failure");
                                         }),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(entries(dir.path()), 0u);
}

TEST(AtomicDirectory, RefusesANonEmptyFolderUnlessReplacing) {
  test::TempDir dir;
  const fs::path target = dir / "campaign";
  fs::create_directories(target);
  test::write_file(target / "keep.txt", "precious");
  auto fill = [](const fs::path& tmp) { test::write_file(tmp / "new.txt", "new"); };
  EXPECT_THROW(fill_directory_atomically(target, false, fill), InputError);
  EXPECT_EQ(test::read_file(target / "keep.txt"), "precious");
  fill_directory_atomically(target, true, fill);
  EXPECT_FALSE(fs::exists(target / "keep.txt"));
  EXPECT_EQ(test::read_file(target / "new.txt"), "new");
  EXPECT_EQ(entries(dir.path()), 1u);
}

}  // namespace
}  // namespace fogdrift
