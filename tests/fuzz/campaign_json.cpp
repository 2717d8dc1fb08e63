// Fuzz target: a campaign's manifest (read_campaign on campaign.json), then its recordings. Each
// plain file name the manifest holds after a "file" key (letters, digits, '_', '-' and '.', not
// starting with '.') is written as a small valid recording first, so that inputs get past the
// missing-file check to the checks on names (listed twice, the same file under two names) and to
// reading every recording, as train and evaluate do.
#include <string>

#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/recording.hpp"
#include "fuzz_util.hpp"

namespace {

bool plain_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.') return false;
  for (char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
          c == '-' || c == '.'))
      return false;
  return name != "campaign.json";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = fogdrift::fuzz::text_of(data, size);
  std::error_code ignored;
  for (const auto& entry : std::filesystem::directory_iterator(fogdrift::fuzz::scratch_dir()))
    std::filesystem::remove_all(entry.path(), ignored);
  for (std::size_t at = text.find("\"file\""); at != std::string::npos;
       at = text.find("\"file\"", at + 6)) {
    const std::size_t open = text.find('"', text.find(':', at + 6));
    if (open == std::string::npos) break;
    const std::size_t close = text.find('"', open + 1);
    if (close == std::string::npos) break;
    const std::string name = text.substr(open + 1, close - open - 1);
    if (plain_name(name))
      fogdrift::fuzz::scratch_file(name, "time_s,gyro_dph,temp_fog_degc\n0,0.1,20\n1,0.2,20.5\n");
  }
  const auto path = fogdrift::fuzz::scratch_file("campaign.json", text);
  fogdrift::fuzz::expect_clean_errors([&] {
    const fogdrift::Campaign campaign = fogdrift::read_campaign(path);
    for (const auto& entry : campaign.recordings) fogdrift::read_recording(campaign.path_of(entry));
  });
  return 0;
}
