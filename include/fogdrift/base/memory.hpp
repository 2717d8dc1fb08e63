// How much memory a run may still take, and the check that a large job fits before it starts
// (docs/reliability.md, "Size limits"). A job that would not fit fails at once with a
// ResourceError that says what needs how much, what limits it, and what to change, instead of
// running for minutes and then being killed or failing with std::bad_alloc.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fogdrift {

/// A job larger than this machine (or the process's limits) can hold, or than fogdrift's own
/// limits allow. what() names the job, the bytes it needs, the limit and what to change.
class ResourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The memory this process may still take, and what sets it.
struct MemoryLimit {
  std::uint64_t bytes = UINT64_MAX;  ///< UINT64_MAX when nothing is known
  std::string source;                ///< e.g. "MemAvailable in /proc/meminfo", "ulimit -v"
};

/// The smallest of: the system's available memory (MemAvailable in /proc/meminfo); the memory
/// cgroup's limit less its usage (cgroup v2 memory.max − memory.current, or v1's
/// memory.limit_in_bytes − memory.usage_in_bytes, in the process's cgroup or at the mount's
/// root); the address-space limit (ulimit -v) less this process's virtual size. Parts that
/// cannot be read are left out. About 0.2 ms: it reads a few small files.
MemoryLimit available_memory();

/// Below this a job is not checked: reading the limits (about 0.2 ms) would cost more than the
/// check is worth.
inline constexpr std::uint64_t kMemoryCheckFromBytes = std::uint64_t{64} << 20;

/// Throws ResourceError when `need_bytes` exceeds available_memory(): "WHAT needs about N GiB;
/// SOURCE leaves M GiB. ADVICE". Needs below kMemoryCheckFromBytes pass unchecked.
void require_memory(std::uint64_t need_bytes, std::string_view what, std::string_view advice);

/// "512 KiB", "3.2 MiB", "1.5 GiB": bytes for messages, three significant digits.
std::string format_bytes(std::uint64_t bytes);

namespace detail {
/// MemAvailable of a /proc/meminfo text, in bytes.
std::optional<std::uint64_t> meminfo_available(std::string_view meminfo);
/// A cgroup limit file's value ("max" or a count of bytes); nullopt for "max" or unreadable text.
std::optional<std::uint64_t> cgroup_bytes(std::string_view text);
}  // namespace detail

}  // namespace fogdrift
