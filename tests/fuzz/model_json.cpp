// Fuzz target: the model file (compensation_model_from_json), then a prediction with the model
// when it loads. The first byte's lowest bit chooses whether a checksum that does not match is
// allowed (--allow-edited), so that edited content reaches the field checks; its next bit
// whether format versions 1 and 2 load (--allow-old-format).
#include <vector>

#include "fogdrift/model/model.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = fogdrift::fuzz::text_of(data + 1, size - 1);
  fogdrift::fuzz::expect_clean_errors([&] {
    const fogdrift::CompensationModel model = fogdrift::compensation_model_from_json(
        text, "fuzz", {(data[0] & 1) != 0, (data[0] & 2) != 0});
    std::vector<double> features(model.inputs(), 0.5), work(model.inputs());
    model.predict(features, work);
  });
  return 0;
}
