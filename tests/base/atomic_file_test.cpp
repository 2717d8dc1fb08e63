#include "fogdrift/base/atomic_file.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"
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

// A killed writer's hidden temporary (".NAME.tmp-PID-…", PID no longer running) is removed by the
// next write of NAME; a running writer's (PID 1 runs), or another output's, is left alone.
TEST(AtomicFile, TheNextWriteClearsAKilledWritersTemporary) {
  test::TempDir dir;
  const fs::path target = dir / "out.csv";
  const fs::path dead = dir / ".out.csv.tmp-4194303-00000000abcd";  // above any live PID
  const fs::path live = dir / ".out.csv.tmp-1-00000000abcd";
  const fs::path other = dir / ".other.csv.tmp-4194303-00000000abcd";
  for (const fs::path& p : {dead, live, other}) test::write_file(p, "half");
  write_text_atomically(target, "new\n");
  EXPECT_EQ(test::read_file(target), "new\n");
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  fs::create_directory(dir / ".campaign.tmp-4194303-00000000abcd");
  fill_directory_atomically(dir / "campaign", false,
                            [](const fs::path& tmp) { test::write_file(tmp / "a.csv", "x"); });
  EXPECT_FALSE(fs::exists(dir / ".campaign.tmp-4194303-00000000abcd"));
}

// A device is written in place, never renamed over: /dev/full gives the system's reason.
TEST(AtomicFile, AFullDeviceIsAClearErrorAndStaysADevice) {
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "/dev/full is not a device here";
  try {
    write_text_atomically("/dev/full", std::string(1 << 16, 'x'));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: write failed (No space left on device)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
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
