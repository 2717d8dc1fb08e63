#include "fogdrift/train/method.hpp"

#include <fmt/format.h>

#include <array>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/train/trainers.hpp"

namespace fogdrift {
namespace {

constexpr std::array<EnumName<Search>, 5> kSearchNames = {{{Search::own, "auto"},
                                                           {Search::none, "none"},
                                                           {Search::ssa, "ssa"},
                                                           {Search::pso, "pso"},
                                                           {Search::gwo, "gwo"}}};

}  // namespace

std::string_view to_string(Search search) {
  return name_in(kSearchNames, search);
}

Search parse_search(std::string_view text, std::string_view option) {
  return parse_in(kSearchNames, text, option, "a search");
}

std::string search_names() {
  return names_in(kSearchNames);
}

bool is_optimizer(Search s) {
  return s == Search::ssa || s == Search::pso || s == Search::gwo;
}

std::string to_string(const Method& method) {
  const TrainerEntry& t = trainer(method.trainer);
  for (const MethodName& m : t.methods)
    if (m.search == method.search) return std::string(m.name);
  return std::string(t.name);
}

Method parse_method(std::string_view text, std::string_view option) {
  for (const TrainerEntry& t : trainer_entries())
    for (const MethodName& m : t.methods)
      if (m.name == text) return {t.name, m.search};
  throw OptionError(std::string(option),
                    fmt::format("'{}' is not a method ({})", text, method_names()));
}

std::string method_names() {
  std::string out;
  for (const TrainerEntry& t : trainer_entries())
    for (const MethodName& m : t.methods) out += (out.empty() ? "" : ", ") + std::string(m.name);
  return out;
}

std::string method_docs() {
  std::string out;
  for (const TrainerEntry& t : trainer_entries())
    for (const MethodName& m : t.methods)
      out += fmt::format("{}{} {}", out.empty() ? "" : "; ", m.name, m.doc);
  return out;
}

}  // namespace fogdrift
