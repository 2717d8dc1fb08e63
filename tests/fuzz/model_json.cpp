// Fuzz target: the model file (compensation_model_from_json), then a prediction with the model
// when it loads, and its C header. The first byte's lowest bit chooses whether a checksum that
// does not match is allowed (--allow-edited), so that edited content reaches the field checks;
// its next bit whether format versions 1 and 2 load (--allow-old-format).
//
// The header must hold nothing of the model's text outside its comments and string literals
// (docs/reliability.md, "Generated code"): its code, with every comment and literal cut out, is
// the code of the header of the same model whose free text (method, version) is "x". Any
// difference is text that escaped, and aborts as a finding.
#include <cstdlib>
#include <string>
#include <vector>

#include "fogdrift/firmware/c_header.hpp"
#include "fogdrift/model/model.hpp"
#include "fuzz_util.hpp"

namespace {

// The header's code without its comments and the contents of its string and character literals,
// read as a C compiler reads them (a backslash escapes the next character inside a literal).
std::string code_of(const std::string& c) {
  std::string out;
  for (std::size_t i = 0; i < c.size();) {
    if (c.compare(i, 2, "/*") == 0) {
      const std::size_t end = c.find("*/", i + 2);
      i = end == std::string::npos ? c.size() : end + 2;
      out += ' ';
    } else if (c.compare(i, 2, "//") == 0) {
      i = c.find('\n', i);
      if (i == std::string::npos) i = c.size();
    } else if (c[i] == '"' || c[i] == '\'') {
      const char quote = c[i++];
      while (i < c.size() && c[i] != quote) i += c[i] == '\\' ? 2 : 1;
      ++i;
      out += quote;
      out += quote;
    } else {
      out += c[i++];
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text = fogdrift::fuzz::text_of(data + 1, size - 1);
  fogdrift::fuzz::expect_clean_errors([&] {
    const fogdrift::CompensationModel model = fogdrift::compensation_model_from_json(
        text, "fuzz", {(data[0] & 1) != 0, (data[0] & 2) != 0});
    std::vector<double> features(model.inputs(), 0.5), work(model.inputs());
    model.predict(features, work);
    fogdrift::CompensationModel plain = model;
    plain.provenance.method = "x";
    plain.provenance.fogdrift_version = "x";
    for (const double dt_s : {0.0, 1.0}) {
      std::string header, reference;
      try {
        header = fogdrift::to_c_header(model, "fz", dt_s);
        reference = fogdrift::to_c_header(plain, "fz", dt_s);
      } catch (const fogdrift::OptionError&) {
        continue;  // a model the streaming part cannot run (its rate window, say)
      }
      if (code_of(header) != code_of(reference)) std::abort();
    }
  });
  return 0;
}
