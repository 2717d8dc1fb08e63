// Fuzz target: the recording reader (read_recording), the file every command reads.
#include "fogdrift/io/recording.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path =
      fogdrift::fuzz::scratch_file("recording.csv", fogdrift::fuzz::text_of(data, size));
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::read_recording(path); });
  return 0;
}
