#include "fogdrift/base/memory.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <charconv>
#include <fstream>
#include <sstream>

namespace fogdrift {
namespace {

std::optional<std::string> read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::optional<std::uint64_t> whole_number(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

/// The cgroup this process is in: the path of the "0::" line (v2) or of the memory controller's
/// line (v1) in /proc/self/cgroup.
std::optional<std::string> cgroup_path(std::string_view controller_line_prefix) {
  const auto text = read_text("/proc/self/cgroup");
  if (!text) return std::nullopt;
  std::istringstream lines(*text);
  for (std::string line; std::getline(lines, line);) {
    // v2: "0::/path"; v1: "N:memory:/path"
    const auto first = line.find(':');
    if (first == std::string::npos) continue;
    const auto second = line.find(':', first + 1);
    if (second == std::string::npos) continue;
    if (line.substr(first + 1, second - first - 1) == controller_line_prefix)
      return line.substr(second + 1);
  }
  return std::nullopt;
}

void take_smaller(MemoryLimit& limit, std::optional<std::uint64_t> bytes, std::string source) {
  if (bytes && *bytes < limit.bytes) limit = {*bytes, std::move(source)};
}

// A cgroup's headroom: its limit less its usage, when both can be read.
std::optional<std::uint64_t> headroom(const std::string& limit_file,
                                      const std::string& usage_file) {
  const auto limit = read_text(limit_file);
  const auto usage = read_text(usage_file);
  if (!limit || !usage) return std::nullopt;
  const auto l = detail::cgroup_bytes(*limit);
  const auto u = whole_number(*usage);
  if (!l || !u) return std::nullopt;
  return *l > *u ? *l - *u : 0;
}

}  // namespace

namespace detail {

std::optional<std::uint64_t> meminfo_available(std::string_view meminfo) {
  constexpr std::string_view kKey = "MemAvailable:";
  const auto at = meminfo.find(kKey);
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view rest = meminfo.substr(at + kKey.size());
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  std::uint64_t kib = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), kib);
  const std::string_view unit(end, static_cast<std::size_t>(rest.data() + rest.size() - end));
  if (ec != std::errc() || !unit.starts_with(" kB")) return std::nullopt;
  return kib * 1024;
}

std::optional<std::uint64_t> cgroup_bytes(std::string_view text) {
  const auto v = whole_number(text);
  // v1 writes "no limit" as a huge page-rounded number.
  if (!v || *v >= (std::uint64_t{1} << 62)) return std::nullopt;
  return v;
}

}  // namespace detail

MemoryLimit available_memory() {
  MemoryLimit limit;
  if (const auto meminfo = read_text("/proc/meminfo"))
    take_smaller(limit, detail::meminfo_available(*meminfo), "MemAvailable in /proc/meminfo");
  // The cgroup's own folder, or the mount's root inside a container whose cgroup namespace
  // hides the path.
  const std::string v2 = cgroup_path("").value_or("/");
  for (const std::string& dir : {"/sys/fs/cgroup" + v2, std::string("/sys/fs/cgroup")})
    take_smaller(limit, headroom(dir + "/memory.max", dir + "/memory.current"),
                 "the memory cgroup's limit (memory.max)");
  const std::string v1 = cgroup_path("memory").value_or("/");
  for (const std::string& dir :
       {"/sys/fs/cgroup/memory" + v1, std::string("/sys/fs/cgroup/memory")})
    take_smaller(limit, headroom(dir + "/memory.limit_in_bytes", dir + "/memory.usage_in_bytes"),
                 "the memory cgroup's limit (memory.limit_in_bytes)");
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY) {
    std::uint64_t used = 0;
    if (const auto statm = read_text("/proc/self/statm")) {
      std::istringstream fields(*statm);
      std::uint64_t pages = 0;
      if (fields >> pages) used = pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
    }
    const std::uint64_t cap = as.rlim_cur;
    take_smaller(limit, cap > used ? cap - used : 0, "the address-space limit (ulimit -v)");
  }
  return limit;
}

std::string format_bytes(std::uint64_t bytes) {
  constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (v >= 1024 && unit + 1 < std::size(kUnits)) {
    v /= 1024;
    ++unit;
  }
  if (unit == 0) return fmt::format("{} bytes", bytes);
  return fmt::format("{:.3g} {}", v, kUnits[unit]);
}

void require_memory(std::uint64_t need_bytes, std::string_view what, std::string_view advice) {
  if (need_bytes < kMemoryCheckFromBytes) return;
  const MemoryLimit limit = available_memory();
  if (need_bytes <= limit.bytes) return;
  throw ResourceError(fmt::format("{} needs about {} of memory; {} leaves {}. {}", what,
                                  format_bytes(need_bytes), limit.source, format_bytes(limit.bytes),
                                  advice));
}

}  // namespace fogdrift
