#include "fogdrift/base/run_files.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstring>
#include <mutex>
#include <thread>

#include "fogdrift/base/error.hpp"

namespace fs = std::filesystem;

namespace fogdrift {
namespace {

struct FileId {
  dev_t device;
  ino_t inode;
  bool operator==(const FileId&) const = default;
};

std::optional<FileId> file_id(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileId{st.st_dev, st.st_ino};
}

struct Inputs {
  std::mutex mutex;
  bool tracking = false;
  std::vector<std::pair<fs::path, FileId>> files;  // as given, and what it is
};

Inputs& inputs() {
  static Inputs state;
  return state;
}

struct Temporaries {
  std::recursive_mutex mutex;
  std::vector<fs::path> paths;
};

Temporaries& temporaries() {
  static Temporaries state;
  return state;
}

// The standard descriptors closed when the run began (reopened on /dev/null since).
std::array<bool, 3> closed_at_start{};

constexpr std::array<int, 3> kStopSignals{SIGINT, SIGTERM, SIGHUP};

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

// The signal thread: waits for a stop signal, removes every registered temporary (holding the
// lock, so no writer registers, renames or unregisters meanwhile) and ends the process.
void wait_for_stop_signal(sigset_t set) {
  int signal = 0;
  while (::sigwait(&set, &signal) != 0) {
  }
  Temporaries& t = temporaries();
  t.mutex.lock();  // never released: the process ends here
  for (const fs::path& p : t.paths) {
    std::error_code ignored;
    fs::remove_all(p, ignored);
  }
  const std::string line = fmt::format("fogdrift: stopped by {}{}\n", signal_name(signal),
                                       t.paths.empty() ? "" : "; its unfinished outputs removed");
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, line.data(), line.size());
  ::_exit(128 + signal);
}

// "N" of "PREFIX/N" when `text` is exactly that, N a whole number.
std::optional<int> number_after(const std::string& text, std::string_view prefix) {
  if (text.size() <= prefix.size() || text.compare(0, prefix.size(), prefix) != 0)
    return std::nullopt;
  int fd = -1;
  const char* first = text.data() + prefix.size();
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, fd);
  if (ec != std::errc() || end != last || fd < 0) return std::nullopt;
  return fd;
}

std::optional<int> descriptor_named(const std::string& text) {
  if (text == "/dev/stdin") return 0;
  if (text == "/dev/stdout") return 1;
  if (text == "/dev/stderr") return 2;
  if (auto fd = number_after(text, "/dev/fd/")) return fd;
  if (auto fd = number_after(text, "/proc/self/fd/")) return fd;
  if (auto fd = number_after(text, fmt::format("/proc/{}/fd/", ::getpid()))) return fd;
  return std::nullopt;
}

}  // namespace

void begin_guarded_run() {
  for (int fd = 0; fd < 3; ++fd) {
    if (::fcntl(fd, F_GETFD) != -1) continue;
    closed_at_start[static_cast<std::size_t>(fd)] = true;
    const int null_fd = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (null_fd >= 0 && null_fd != fd) {
      ::dup2(null_fd, fd);
      ::close(null_fd);
    }
  }
  {
    std::lock_guard lock(inputs().mutex);
    inputs().tracking = true;
  }
  sigset_t set;
  sigemptyset(&set);
  for (int s : kStopSignals) sigaddset(&set, s);
  ::pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread(wait_for_stop_signal, set).detach();
}

void note_input(const fs::path& path) {
  Inputs& in = inputs();
  std::lock_guard lock(in.mutex);
  if (!in.tracking) return;
  if (const auto id = file_id(path)) in.files.emplace_back(path, *id);
}

std::optional<fs::path> input_replaced_by(const fs::path& output) {
  Inputs& in = inputs();
  std::lock_guard lock(in.mutex);
  if (!in.tracking || in.files.empty()) return std::nullopt;
  std::error_code ec;
  const auto out_id = file_id(output);
  if (out_id) {
    for (const auto& [path, id] : in.files)
      if (id == *out_id) return path;
  }
  if (!fs::is_directory(output, ec)) return std::nullopt;
  // A folder output replaces everything under it.
  const fs::path folder = fs::weakly_canonical(output, ec);
  if (ec) return std::nullopt;
  for (const auto& [path, id] : in.files) {
    const fs::path file = fs::weakly_canonical(path, ec);
    if (ec) continue;
    if (std::mismatch(folder.begin(), folder.end(), file.begin(), file.end()).first == folder.end())
      return path;
  }
  return std::nullopt;
}

void check_output_not_among(const fs::path& output, const std::vector<fs::path>& inputs,
                            const std::string& option) {
  for (const auto& input : inputs) {
    std::error_code ec;
    if (fs::equivalent(output, input, ec))
      throw OptionError(option, fmt::format("'{}' is {}, which this call reads: writing it would "
                                            "destroy what is being read; choose another file",
                                            output.string(), input.string()));
    // A folder written whole (a campaign replaced) holds the input.
    const fs::path inside =
        fs::weakly_canonical(input, ec).lexically_relative(fs::weakly_canonical(output, ec));
    if (!ec && !inside.empty() && *inside.begin() != ".." && fs::is_directory(output, ec))
      throw OptionError(option, fmt::format("'{}' holds {}, which this call reads: replacing it "
                                            "would destroy what is being read; choose another "
                                            "folder",
                                            output.string(), input.string()));
  }
}

void check_output_not_input(const fs::path& output, const std::string& option) {
  if (const auto input = input_replaced_by(output)) {
    throw OptionError(
        option,
        fmt::format("'{}' {} '{}', which this run reads; writing it would destroy "
                    "the input: choose another output",
                    output.string(), *input == output ? "is the input" : "is or holds the input",
                    input->string()));
  }
}

std::optional<int> standard_descriptor_of(const fs::path& path) {
  fs::path current = path;
  for (int hop = 0; hop < 40; ++hop) {
    if (const auto fd = descriptor_named(current.lexically_normal().string())) return fd;
    struct stat st {};
    if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return std::nullopt;
    std::error_code ec;
    const fs::path target = fs::read_symlink(current, ec);
    if (ec) return std::nullopt;
    current = target.is_absolute() ? target : current.parent_path() / target;
  }
  return std::nullopt;
}

bool descriptor_usable(int fd) {
  if (fd >= 0 && fd < 3 && closed_at_start[static_cast<std::size_t>(fd)]) return false;
  return ::fcntl(fd, F_GETFD) != -1;
}

TemporaryRegistration::TemporaryRegistration(fs::path path) {
  also(std::move(path));
}

TemporaryRegistration::~TemporaryRegistration() {
  Temporaries& t = temporaries();
  std::lock_guard lock(t.mutex);
  for (const fs::path& p : paths_) {
    const auto it = std::find(t.paths.begin(), t.paths.end(), p);
    if (it != t.paths.end()) t.paths.erase(it);
  }
}

void TemporaryRegistration::also(fs::path path) {
  Temporaries& t = temporaries();
  std::lock_guard lock(t.mutex);
  t.paths.push_back(path);
  paths_.push_back(std::move(path));
}

SignalHold::SignalHold() {
  temporaries().mutex.lock();
}
SignalHold::~SignalHold() {
  temporaries().mutex.unlock();
}

}  // namespace fogdrift
