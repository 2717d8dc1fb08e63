// Choosing the table of inner loops (loops.hpp) once: the fastest the processor has, or the one
// FOGDRIFT_ISA names.
#include "svr/loops.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>
#include <cstdlib>
#include <string>
#include <vector>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr {
namespace detail {
namespace {

constexpr std::array<EnumName<Isa>, 3> kIsaNames = {
    {{Isa::portable, "portable"}, {Isa::avx2, "avx2"}, {Isa::avx512, "avx512"}}};

}  // namespace

const Loops& loops_named(std::string_view wanted) {
  if (wanted.empty() || wanted == "auto") {
    for (const Isa isa : {Isa::avx512, Isa::avx2})
      if (const Loops* table = loops_for(isa)) return *table;
    return portable_loops();
  }
  const Isa isa = parse_in(kIsaNames, wanted, "FOGDRIFT_ISA", "an instruction set");
  if (const Loops* table = loops_for(isa)) return *table;
  std::vector<std::string_view> here;
  for (const auto& [each, name] : kIsaNames)
    if (loops_for(each) != nullptr) here.push_back(name);
  throw OptionError("FOGDRIFT_ISA",
                    fmt::format("this processor cannot run '{}' (it can run {}, or auto)", wanted,
                                fmt::join(here, ", ")));
}

std::string_view isa_name(Isa isa) {
  return name_in(kIsaNames, isa);
}

const Loops* loops_for(Isa isa) {
  switch (isa) {
    case Isa::portable:
      return &portable_loops();
    case Isa::avx2:
      return avx2_loops();
    case Isa::avx512:
      return avx512_loops();
  }
  return nullptr;
}

const Loops& loops() {
  // A throw leaves it unset: the next call tries again.
  static const Loops& chosen = []() -> const Loops& {
    const char* env = std::getenv("FOGDRIFT_ISA");
    return loops_named(env != nullptr ? env : "");
  }();
  return chosen;
}

}  // namespace detail

std::string_view instruction_set() {
  return detail::isa_name(detail::loops().isa);
}

}  // namespace fogdrift::svr
