// Fuzz target: LIBSVM's model format (parse_libsvm_model), then a prediction when it loads.
#include <vector>

#include "fogdrift/svr/libsvm_format.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = fogdrift::fuzz::text_of(data, size);
  fogdrift::fuzz::expect_clean_errors([&] {
    const fogdrift::svr::Model model = fogdrift::svr::parse_libsvm_model(text, "fuzz");
    const std::vector<double> x(model.dims, 0.25);
    model.predict(x.data());
  });
  return 0;
}
