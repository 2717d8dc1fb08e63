#include "fogdrift/base/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <streambuf>
#include <system_error>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"

namespace fs = std::filesystem;

namespace fogdrift {
namespace {

fs::path parent_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// ".NAME.tmp-": the start of every temporary sibling of `path`; the writer's PID follows. A long
// name is shortened (its start and a hash of the whole), so that a name the file system accepts
// never fails for want of the 27 characters the temporary adds.
std::string temporary_head(const fs::path& path) {
  const std::string name = path.filename().string();
  constexpr std::size_t kKept = 160;
  if (name.size() <= kKept) return fmt::format(".{}.tmp-", name);
  return fmt::format(".{}~{:016x}.tmp-", name.substr(0, kKept), std::hash<std::string>{}(name));
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
// name with lost content. A late write error (ENOSPC or EIO on a network file system or under a
// quota) surfaces here or at close: either is an error, and nothing is renamed into place. A file
// system that cannot sync (EINVAL) is not one.
void sync_file(const fs::path& tmp, const fs::path& path) {
  const int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    throw InputError(
        path.string(), 0, 0,
        fmt::format("cannot reopen to sync ({}); nothing was written", std::strerror(errno)));
  const int synced = ::fsync(fd);
  const int sync_errno = errno;
  const int closed = ::close(fd);
  const int close_errno = errno;
  if (synced != 0 && sync_errno != EINVAL && sync_errno != EROFS)
    throw InputError(
        path.string(), 0, 0,
        fmt::format("write failed at sync ({}); nothing was written", std::strerror(sync_errno)));
  if (closed != 0 && close_errno != EINTR)
    throw InputError(
        path.string(), 0, 0,
        fmt::format("write failed at close ({}); nothing was written", std::strerror(close_errno)));
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

// A stream buffer over a descriptor the process already has (standard output, /dev/fd/N): the
// bytes go where the shell pointed it, at its offset, with its mode (a `>>` appends).
class DescriptorBuffer : public std::streambuf {
 public:
  explicit DescriptorBuffer(int fd) : fd_(fd) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (sync() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    const char* p = pbase();
    while (p < pptr()) {
      const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        error_ = n < 0 ? errno : EIO;
        return -1;
      }
      p += n;
    }
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return 0;
  }

 private:
  int fd_;
  int error_ = 0;
  std::array<char, 1 << 16> buffer_{};
};

// Writes through descriptor `fd` (`-o /dev/stdout`): never opened anew, never replaced.
void write_to_descriptor(const fs::path& path, int fd,
                         const std::function<void(std::ostream&)>& write) {
  if (!descriptor_usable(fd))
    throw InputError(path.string(), 0, 0,
                     fmt::format("descriptor {} is closed, so nothing can be written there; "
                                 "redirect it (e.g. > model.h) or name a file with -o",
                                 fd));
  // What the process printed before goes first (`-o /dev/stdout` after a progress line).
  std::cout.flush();
  std::fflush(nullptr);
  DescriptorBuffer buffer(fd);
  std::ostream out(&buffer);
  write(out);
  out.flush();
  if (!out || buffer.error() != 0)
    throw InputError(path.string(), 0, 0,
                     fmt::format("write failed ({}); the output is incomplete",
                                 std::strerror(buffer.error() != 0 ? buffer.error() : EIO)));
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

// The file a symbolic link leads to, followed to its end (a dangling link: the file it names,
// which the write creates). The link itself stays; its target is what gets written.
fs::path resolved_output(const fs::path& path) {
  fs::path current = path;
  for (int hop = 0; hop < 40; ++hop) {
    std::error_code ec;
    if (!fs::is_symlink(current, ec)) return current;
    const fs::path target = fs::read_symlink(current, ec);
    if (ec)
      throw InputError(path.string(), 0, 0,
                       fmt::format("is a symbolic link that cannot be read ({}); name its "
                                   "target instead",
                                   ec.message()));
    current = target.is_absolute() ? target : parent_of(current) / target;
  }
  throw InputError(path.string(), 0, 0,
                   "is a chain of more than 40 symbolic links (a loop?); name the file itself");
}

void refuse_input(const fs::path& path) {
  if (const auto input = input_replaced_by(path))
    throw InputError(path.string(), 0, 0,
                     fmt::format("is also an input of this run ('{}'); writing it would destroy "
                                 "what is being read: choose another output",
                                 input->string()));
}

}  // namespace

void write_file_atomically(const fs::path& given, const std::function<void(std::ostream&)>& write) {
  if (const auto fd = standard_descriptor_of(given)) return write_to_descriptor(given, *fd, write);
  const fs::path path = resolved_output(given);
  refuse_input(path);
  if (is_special(path)) return write_in_place(path, write);
  std::error_code dir_ec;
  if (fs::is_directory(path, dir_ec))
    throw InputError(given.string(), 0, 0, "is a folder; name a file to write");
  remove_stale_temporaries(path);
  const fs::path tmp = temporary_sibling(path);
  TemporaryRegistration registration(tmp);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) {
        throw InputError(given.string(), 0, 0,
                         fmt::format("cannot create output file ({})", std::strerror(errno)));
      }
      write(out);
      if (!flushed(out))
        throw InputError(given.string(), 0, 0,
                         fmt::format("write failed ({}); nothing was written", last_error()));
      errno = 0;
      out.close();
      if (!out)
        throw InputError(
            given.string(), 0, 0,
            fmt::format("write failed at close ({}); nothing was written", last_error()));
    }
    sync_file(tmp, given);
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
      throw InputError(given.string(), 0, 0,
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

void fill_directory_atomically(const fs::path& given, bool replace,
                               const std::function<void(const fs::path&)>& fill) {
  const fs::path dir = resolved_output(given);
  std::error_code ec;
  const bool exists = fs::exists(dir, ec);
  if (exists && !fs::is_directory(dir, ec)) {
    throw InputError(dir.string(), 0, 0, "exists and is not a folder");
  }
  if (exists && !replace && !fs::is_empty(dir, ec)) {
    throw InputError(
        dir.string(), 0, 0,
        "folder exists and is not empty (choose another folder, or replace it: --force "
        "on the command line, replace=True in Python, 'replace', true in Octave)");
  }
  if (dir.has_parent_path() && !fs::exists(dir.parent_path(), ec)) {
    fs::create_directories(dir.parent_path(), ec);
    if (ec)
      throw InputError(dir.parent_path().string(), 0, 0, "cannot create folder: " + ec.message());
  }
  if (exists) refuse_input(dir);
  remove_stale_temporaries(dir);
  const fs::path tmp = temporary_sibling(dir);
  TemporaryRegistration registration(tmp);
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
    // The old folder moved aside and the new one moved in: no signal between the two renames.
    const SignalHold hold;
    fs::path old;
    if (exists) {
      old = temporary_sibling(dir);
      registration.also(old);
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
