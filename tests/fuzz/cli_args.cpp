// Fuzz target: the command line. The input's lines are the arguments after `fogdrift`. The
// command set stops once parsing is complete, before any subcommand runs, so what is tested is
// the parsing itself: CLI11 with fogdrift's options, their validators, enumerations, defaults and
// requirements. Option values that are texts of their own (feature specs, unit specs) have
// targets of their own.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "commands.hpp"
#include "fuzz_util.hpp"

namespace {

struct Parsed {};

// CLI11 calls pre_callback() after parsing, requirements and extras, and before the subcommands'
// actions: the place to stop. (Replacing the actions would free the option values their closures
// own.)
class ParseOnly : public CLI::App {
  void pre_callback() override { throw Parsed{}; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args = {"fogdrift"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 64; ++i) {
    if (data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) args.push_back(current);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());

  ParseOnly app;
  fogdrift::app::add_commands(app);
  fogdrift::fuzz::expect_clean_errors([&] {
    try {
      app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const Parsed&) {
    } catch (const CLI::ParseError&) {  // usage errors, --help and --version
    }
  });
  return 0;
}
