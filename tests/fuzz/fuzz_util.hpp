// Shared by the fuzz targets (docs/reliability.md): what counts as a clean rejection, and a
// scratch file for readers that take a path.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "fogdrift/base/error.hpp"

namespace fogdrift::fuzz {

/// Runs `body` on one input. Bad input must end in the errors fogdrift promises, InputError or
/// OptionError (each naming the file, line, column or option); any other exception escapes, and
/// the fuzzer reports it as a finding, as it reports crashes, leaks and undefined behaviour.
template <class Body>
void expect_clean_errors(Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  } catch (const OptionError&) {
  }
}

/// The input as text.
inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

/// This process's scratch folder, removed at exit. The exit handler is registered once the
/// path is built, so it runs before the path is destroyed (handlers and static destructors run
/// in the reverse order of their registration): registered inside the path's own initializer,
/// it ran after and removed nothing, leaving a folder in /tmp per run.
inline const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path d =
        std::filesystem::temp_directory_path() / ("fogdrift_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  static const bool removed_at_exit = [] {
    return std::atexit([] {
             std::error_code ignored;
             std::filesystem::remove_all(dir, ignored);
           }) == 0;
  }();
  (void)removed_at_exit;
  return dir;
}

/// Writes `text` to `name` in the scratch folder and returns its path.
inline std::filesystem::path scratch_file(const std::string& name, const std::string& text) {
  const std::filesystem::path path = scratch_dir() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  return path;
}

}  // namespace fogdrift::fuzz
