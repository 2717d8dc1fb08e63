// Helpers shared by the tests: temporary folders and file contents.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fogdrift::test {

/// A fresh folder under the system temp dir, removed with everything in it on destruction.
class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() /
            ("fogdrift_test_" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Compiles dir/driver.c as strict C99 (warnings are errors) with the system's C compiler, runs
/// it with `input` on standard input and returns its standard output. Throws std::runtime_error
/// naming the command that failed.
inline std::string compile_and_run_c(const TempDir& dir, const std::string& input) {
  write_file(dir / "input.txt", input);
  const std::string build = std::string(FOGDRIFT_C_COMPILER) +
                            " -std=c99 -Wall -Wextra -pedantic -Werror -O2 -o " +
                            (dir / "driver").string() + " " + (dir / "driver.c").string() + " -lm";
  if (std::system(build.c_str()) != 0) throw std::runtime_error("C compile failed: " + build);
  const std::string run = (dir / "driver").string() + " < " + (dir / "input.txt").string() + " > " +
                          (dir / "output.txt").string();
  if (std::system(run.c_str()) != 0) throw std::runtime_error("C driver failed: " + run);
  return read_file(dir / "output.txt");
}

inline std::string data_path(const std::string& relative) {
  // Appended step by step: GCC 12 warns falsely (-Warray-bounds) on string(…) + "/" + relative
  // once it is inlined into a unity batch.
  std::string path = FOGDRIFT_TEST_DATA;
  path += '/';
  path += relative;
  return path;
}

}  // namespace fogdrift::test
