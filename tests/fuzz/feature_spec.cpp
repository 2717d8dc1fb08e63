// Fuzz target: feature-spec strings (FeatureSpec::parse), and the round trip of what parses:
// parse(to_string()) must give the same spec.
#include <cstdlib>

#include "fogdrift/features/features.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = fogdrift::fuzz::text_of(data, size);
  fogdrift::fuzz::expect_clean_errors([&] {
    const fogdrift::FeatureSpec spec = fogdrift::FeatureSpec::parse(text);
    const std::string canonical = spec.to_string();
    if (fogdrift::FeatureSpec::parse(canonical).to_string() != canonical) std::abort();
  });
  return 0;
}
