#include "fogdrift/base/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include "fogdrift/base/error.hpp"

namespace fs = std::filesystem;

namespace fogdrift {
namespace {

fs::path parent_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// ".NAME.tmp-": the start of every temporary sibling of `path`; the writer's PID follows.
std::string temporary_head(const fs::path& path) {
  return fmt::format(".{}.tmp-", path.filename().string());
}

// A temporary sibling name unique enough for concurrent writers in one folder, carrying the
// writer's process id so that a later run can tell a killed writer's leftovers.
fs::path temporary_sibling(const fs::path& path) {
  static thread_local std::mt19937_64 engine{std::random_device{}() ^
                                             (static_cast<std::uint64_t>(::getpid()) << 32)};
  return parent_of(path) / fmt::format("{}{}-{:012x}", temporary_head(path), ::getpid(),
                                       engine() & 0xffffffffffffULL);
}

void remove_quietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove_all(p, ignored);
}

// Removes the temporary siblings of `path` left by writers that no longer run (a killed run):
// ".NAME.tmp-PID-…" whose PID names no live process. A live writer's are left alone.
void remove_stale_temporaries(const fs::path& path) {
  const std::string head = temporary_head(path);
  std::error_code ec;
  for (fs::directory_iterator it(parent_of(path), ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, head.size(), head) != 0) continue;
    char* after = nullptr;
    const long pid = std::strtol(name.c_str() + head.size(), &after, 10);
    if (pid <= 0 || after == nullptr || *after != '-') continue;
    if (pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
    remove_quietly(it->path());
  }
}

// Flushes a written file to the device, so that a crash after the rename cannot leave the new
// name with lost content.
void sync_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Flushes `out`; false when it or an earlier write failed. errno then holds the system's reason
// for the failed write (a write that fails leaves the stream bad, and later output does nothing).
bool flushed(std::ofstream& out) {
  if (out) {
    errno = 0;
    out.flush();
  }
  return static_cast<bool>(out);
}

std::string last_error() {
  return errno != 0 ? std::strerror(errno) : "I/O error";
}

// True when `path` exists and is not a regular file or a folder: a device (/dev/null,
// /dev/full), a pipe or a terminal, which can only be written in place.
bool is_special(const fs::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return false;
  return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

// Writes to a device or pipe in place: there is nothing to rename, and renaming over a device
// node would replace it.
void write_in_place(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  std::ofstream out(path, std::ios::binary);
  if (!out)
    throw InputError(path.string(), 0, 0,
                     fmt::format("cannot open for writing ({})", std::strerror(errno)));
  write(out);
  if (!flushed(out))
    throw InputError(path.string(), 0, 0, fmt::format("write failed ({})", last_error()));
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  if (is_special(path)) return write_in_place(path, write);
  remove_stale_temporaries(path);
  const fs::path tmp = temporary_sibling(path);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) {
        throw InputError(path.string(), 0, 0,
                         fmt::format("cannot create output file ({})", std::strerror(errno)));
      }
      write(out);
      if (!flushed(out))
        throw InputError(path.string(), 0, 0,
                         fmt::format("write failed ({}); nothing was written", last_error()));
    }
    sync_file(tmp);
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
      throw InputError(path.string(), 0, 0,
                       fmt::format("cannot rename into place ({})", ec.message()));
    }
  } catch (...) {
    remove_quietly(tmp);
    throw;
  }
}

void write_text_atomically(const fs::path& path, const std::string& text) {
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

void fill_directory_atomically(const fs::path& dir, bool replace,
                               const std::function<void(const fs::path&)>& fill) {
  std::error_code ec;
  const bool exists = fs::exists(dir, ec);
  if (exists && !fs::is_directory(dir, ec)) {
    throw InputError(dir.string(), 0, 0, "exists and is not a folder");
  }
  if (exists && !replace && !fs::is_empty(dir, ec)) {
    throw InputError(dir.string(), 0, 0,
                     "folder exists and is not empty (choose another --out, or pass --force to "
                     "replace it)");
  }
  if (dir.has_parent_path() && !fs::exists(dir.parent_path(), ec)) {
    fs::create_directories(dir.parent_path(), ec);
    if (ec)
      throw InputError(dir.parent_path().string(), 0, 0, "cannot create folder: " + ec.message());
  }
  remove_stale_temporaries(dir);
  const fs::path tmp = temporary_sibling(dir);
  try {
    fs::create_directory(tmp, ec);
    if (ec) throw InputError(tmp.string(), 0, 0, "cannot create folder: " + ec.message());
    fill(tmp);
    // Replacing: swap the two folders in one step where the file system can (no moment without
    // `dir`), then remove the old one under the temporary name.
    if (exists && ::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) == 0) {
      remove_quietly(tmp);
      return;
    }
    fs::path old;
    if (exists) {
      old = temporary_sibling(dir);
      fs::rename(dir, old, ec);
      if (ec) throw InputError(dir.string(), 0, 0, "cannot move old folder aside: " + ec.message());
    }
    fs::rename(tmp, dir, ec);
    if (ec) {
      if (!old.empty()) fs::rename(old, dir, ec);
      throw InputError(dir.string(), 0, 0, "cannot rename into place: " + ec.message());
    }
    if (!old.empty()) remove_quietly(old);
  } catch (...) {
    remove_quietly(tmp);
    throw;
  }
}

}  // namespace fogdrift
