// Fuzz target: `import`'s foreign-file reader and its unit and time specs. The first line of the
// input is a unit spec for temp_fog_degc (parse_unit), the second a date-time (parse_datetime);
// the first byte chooses the reader's options (delimiter, decimal comma, held cells, comments,
// power cycles, a preamble line, time from zero); the rest is the file.
#include <string>

#include "fogdrift/import.hpp"
#include "fuzz_util.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t choice = data[0];
  std::string rest = fogdrift::fuzz::text_of(data + 1, size - 1);
  auto take_line = [&] {
    const std::size_t end = rest.find('\n');
    std::string line = rest.substr(0, end);
    rest = end == std::string::npos ? std::string() : rest.substr(end + 1);
    return line;
  };
  const std::string unit = take_line();
  const std::string datetime = take_line();
  fogdrift::parse_datetime(datetime);
  fogdrift::ImportOptions o;
  fogdrift::fuzz::expect_clean_errors([&] {
    if (!unit.empty()) o.conversions["temp_fog_degc"] = fogdrift::parse_unit("temp_fog_degc", unit);
  });
  o.delimiter = (choice & 3) == 1 ? ';' : ((choice & 3) == 2 ? '\t' : ',');
  o.decimal_comma = (choice & 4) != 0 && o.delimiter != ',';
  o.hold_empty = (choice & 8) != 0;
  o.comment = (choice & 16) != 0 ? '#' : 0;
  o.split_at_reset = (choice & 32) != 0;
  o.skip_lines = (choice & 64) != 0 ? 1 : 0;
  o.time_from_zero = (choice & 128) != 0;
  const auto path = fogdrift::fuzz::scratch_file("foreign.csv", rest);
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::import_recordings(path, o); });
  return 0;
}
