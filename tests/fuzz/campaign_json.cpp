// Fuzz target: a campaign's manifest (read_campaign on campaign.json). The recordings it names
// are not there, so most inputs end at a missing file, after the JSON was read and checked.
#include "fogdrift/campaign.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path =
      fogdrift::fuzz::scratch_file("campaign.json", fogdrift::fuzz::text_of(data, size));
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::read_campaign(path); });
  return 0;
}
