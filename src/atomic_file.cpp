#include "fogdrift/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <system_error>

#include "fogdrift/error.hpp"

namespace fs = std::filesystem;

namespace fogdrift {
namespace {

// A temporary sibling name unique enough for concurrent writers in one folder.
fs::path temporary_sibling(const fs::path& path) {
  static thread_local std::mt19937_64 engine{std::random_device{}() ^
                                             (static_cast<std::uint64_t>(::getpid()) << 32)};
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  return parent /
         fmt::format(".{}.tmp-{:012x}", path.filename().string(), engine() & 0xffffffffffffULL);
}

void remove_quietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove_all(p, ignored);
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  const fs::path tmp = temporary_sibling(path);
  try {
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) {
        throw InputError(path.string(), 0, 0,
                         fmt::format("cannot create output file ({})", std::strerror(errno)));
      }
      write(out);
      out.flush();
      if (!out) throw InputError(path.string(), 0, 0, "write failed (disk full?)");
    }
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
  const fs::path tmp = temporary_sibling(dir);
  try {
    fs::create_directory(tmp, ec);
    if (ec) throw InputError(tmp.string(), 0, 0, "cannot create folder: " + ec.message());
    fill(tmp);
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
