// The memory a run may still take (memory.hpp): the parsers of the kernel's files, the limits as
// this process sees them, the messages, and the limit of an address space (ulimit -v) honoured in
// a child process.
#include "fogdrift/base/memory.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

#include "fogdrift/svr/svr.hpp"

namespace fogdrift {
namespace {

TEST(Memory, ReadsMemAvailableAndCgroupLimits) {
  const std::string meminfo =
      "MemTotal:       24576000 kB\nMemFree:         1000000 kB\nMemAvailable:   12345678 kB\n";
  EXPECT_EQ(detail::meminfo_available(meminfo), std::uint64_t{12345678} * 1024);
  EXPECT_EQ(detail::meminfo_available("MemTotal: 1 kB\n"), std::nullopt);
  EXPECT_EQ(detail::meminfo_available("MemAvailable: 12"), std::nullopt);  // no unit
  EXPECT_EQ(detail::cgroup_bytes("1073741824\n"), std::uint64_t{1} << 30);
  EXPECT_EQ(detail::cgroup_bytes("max\n"), std::nullopt);
  EXPECT_EQ(detail::cgroup_bytes("9223372036854771712\n"), std::nullopt);  // v1's "no limit"
  EXPECT_EQ(detail::cgroup_bytes("12 kB"), std::nullopt);
}

TEST(Memory, AvailableIsAtMostWhatTheSystemHasFree) {
  const MemoryLimit limit = available_memory();
  std::ifstream in("/proc/meminfo");
  std::stringstream text;
  text << in.rdbuf();
  const auto system = detail::meminfo_available(text.str());
  ASSERT_TRUE(system.has_value());
  EXPECT_GT(limit.bytes, 0u);
  // Another process may free memory between the two reads; 1 GiB of slack.
  EXPECT_LE(limit.bytes, *system + (std::uint64_t{1} << 30));
  EXPECT_FALSE(limit.source.empty());
}

TEST(Memory, RequireNamesTheJobTheNeedTheLimitAndTheAdvice) {
  EXPECT_NO_THROW(require_memory(4096, "a small job", "n/a"));
  try {
    require_memory(std::uint64_t{1} << 60, "a job of 2^60 bytes", "Ask for less.");
    FAIL() << "an exabyte was granted";
  } catch (const ResourceError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("a job of 2^60 bytes needs about 1 EiB of memory; ", 0), 0u) << what;
    EXPECT_NE(what.find(available_memory().source), std::string::npos) << what;
    EXPECT_NE(what.find("Ask for less."), std::string::npos) << what;
  }
}

TEST(Memory, FormatsBytesForPeople) {
  EXPECT_EQ(format_bytes(512), "512 bytes");
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(std::uint64_t{3} << 30), "3 GiB");
  EXPECT_EQ(format_bytes(std::uint64_t{1234} << 20), "1.21 GiB");
}

TEST(Memory, FitBytesCountsTheCacheAtMostTheWholeMatrix) {
  svr::Params p;
  p.cache_mb = 200;
  // 1000 rows: the whole kernel matrix (4 MB) is below the budget.
  EXPECT_EQ(svr::fit_bytes(1000, 9, p), 4'000'000u + 16'000u + 1000u * (160 + 256));
  // 100,000 rows: the budget bounds the rows.
  EXPECT_EQ(svr::fit_bytes(100'000, 9, p),
            (std::uint64_t{200} << 20) + 1'600'000u + 100'000u * (160 + 256));
  p.libsvm_path = true;  // rows of 2l entries
  EXPECT_EQ(svr::fit_bytes(1000, 9, p), 16'000'000u + 32'000u + 1000u * (160 + 256));
}

#if !defined(__SANITIZE_ADDRESS__)
// In a child process: a limit 256 MiB above the current size leaves at most 256 MiB, and a
// 1 GiB job is refused. Exit status 0 when all holds.
[[noreturn]] void under_an_address_space_limit() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  statm >> pages;
  const std::uint64_t cap =
      pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)) + (std::uint64_t{256} << 20);
  rlimit r{};
  r.rlim_cur = r.rlim_max = cap;
  if (setrlimit(RLIMIT_AS, &r) != 0) std::_Exit(3);
  const MemoryLimit limit = available_memory();
  if (limit.source != "the address-space limit (ulimit -v)") std::_Exit(4);
  if (limit.bytes > (std::uint64_t{256} << 20)) std::_Exit(5);
  try {
    require_memory(std::uint64_t{1} << 30, "a 1 GiB job", "");
  } catch (const ResourceError&) {
    std::_Exit(0);
  }
  std::_Exit(6);
}

TEST(MemoryDeathTest, AnAddressSpaceLimitIsHonoured) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(under_an_address_space_limit(), ::testing::ExitedWithCode(0), "");
}
#endif

}  // namespace
}  // namespace fogdrift
