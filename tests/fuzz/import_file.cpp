// Fuzz target: `import`'s foreign-file reader and its unit and time specs, and `join`. The first
// line of the input is a unit spec for temp_fog_degc (parse_unit), or "clock" for clock stamps in
// time_s with the second line as their time zero and partial logs allowed; the second line is
// also read as a date-time (parse_datetime) and a time of day (parse_clock). The first byte
// chooses the reader's options (delimiter, decimal comma, held cells, comments, power cycles, a
// preamble line, time from zero); the rest is the file. Whatever imports is joined to itself,
// with the log half a step late and the nearest method on odd lengths.
#include <string>
#include <vector>

#include "fogdrift/io/import.hpp"
#include "fogdrift/io/join.hpp"
#include "fogdrift/io/timestamp.hpp"
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
  fogdrift::parse_clock(datetime);
  fogdrift::ImportOptions o;
  if (unit == "clock") {
    o.conversions["time_s"] = fogdrift::parse_unit("time_s", "clock");
    o.time_zero = datetime;
    o.allow_partial = true;
  } else {
    fogdrift::fuzz::expect_clean_errors([&] {
      if (!unit.empty())
        o.conversions["temp_fog_degc"] = fogdrift::parse_unit("temp_fog_degc", unit);
    });
  }
  o.delimiter = (choice & 3) == 1 ? ';' : ((choice & 3) == 2 ? '\t' : ',');
  o.decimal_comma = (choice & 4) != 0 && o.delimiter != ',';
  o.hold_empty = (choice & 8) != 0;
  o.comment = (choice & 16) != 0 ? '#' : 0;
  o.split_at_reset = (choice & 32) != 0;
  o.skip_lines = (choice & 64) != 0 ? 1 : 0;
  o.time_from_zero = (choice & 128) != 0;
  const auto path = fogdrift::fuzz::scratch_file("foreign.csv", rest);
  std::vector<fogdrift::Recording> imported;
  fogdrift::fuzz::expect_clean_errors([&] { imported = fogdrift::import_recordings(path, o); });
  if (imported.empty()) return 0;
  const fogdrift::Recording& rec = imported.front();
  fogdrift::Recording log = rec;
  log.partial = true;
  log.gyro_dph.clear();
  fogdrift::JoinOptions j;
  j.replace = true;
  j.offset_s = 0.5 * fogdrift::median_time_step_s(rec.time_s);
  if (rec.size() % 2 == 1) j.method = fogdrift::JoinMethod::nearest;
  fogdrift::fuzz::expect_clean_errors([&] { fogdrift::join(rec, log, j); });
  return 0;
}
