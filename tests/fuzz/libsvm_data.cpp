// Fuzz target: LIBSVM's data format (parse_libsvm_data).
#include "fogdrift/svr/libsvm_format.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = fogdrift::fuzz::text_of(data, size);
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::svr::parse_libsvm_data(text, "fuzz"); });
  return 0;
}
