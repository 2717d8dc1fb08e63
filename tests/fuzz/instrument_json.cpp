// Fuzz target: the simulator's instrument file (instrument_from_json).
#include "fogdrift/sim/instrument.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = fogdrift::fuzz::text_of(data, size);
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::sim::instrument_from_json(text, "fuzz"); });
  return 0;
}
