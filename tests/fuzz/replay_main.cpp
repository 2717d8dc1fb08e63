// Replays fuzz inputs without libFuzzer: `fuzz_replay TARGET PATH...` feeds the target every
// file given, and every file of every folder given, one call each. The CTest suite runs each
// target over its committed corpus this way, in the Release build and under the sanitizers
// (docs/reliability.md). The targets' entry points are renamed fogdrift_fuzz_TARGET in this
// build (tests/fuzz/CMakeLists.txt), so that all of them fit in one program.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#define FOGDRIFT_FUZZ_TARGET(name) \
  extern "C" int fogdrift_fuzz_##name(const std::uint8_t* data, std::size_t size);
#include "fuzz_targets.inc"
#undef FOGDRIFT_FUZZ_TARGET

namespace {

using Target = int (*)(const std::uint8_t*, std::size_t);

struct Entry {
  const char* name;
  Target run;
};

#define FOGDRIFT_FUZZ_TARGET(name) {#name, fogdrift_fuzz_##name},
const Entry kTargets[] = {
#include "fuzz_targets.inc"
};
#undef FOGDRIFT_FUZZ_TARGET

void replay(Target target, const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  target(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
  Target target = nullptr;
  for (const Entry& e : kTargets)
    if (argc > 1 && std::strcmp(argv[1], e.name) == 0) target = e.run;
  if (target == nullptr) {
    std::fprintf(stderr, "usage: fuzz_replay TARGET FILE|FOLDER...; targets:");
    for (const Entry& e : kTargets) std::fprintf(stderr, " %s", e.name);
    std::fprintf(stderr, "\n");
    return 2;
  }
  std::size_t inputs = 0;
  for (int i = 2; i < argc; ++i) {
    const std::filesystem::path arg = argv[i];
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(arg)) {
      for (const auto& e : std::filesystem::directory_iterator(arg))
        if (e.is_regular_file()) files.push_back(e.path());
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(arg);
    }
    for (const auto& f : files) replay(target, f), ++inputs;
  }
  std::printf("%s: replayed %zu inputs\n", argv[1], inputs);
  return inputs > 0 ? 0 : 1;
}
