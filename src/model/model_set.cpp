#include "fogdrift/model/model_set.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <nlohmann/json.hpp>

#include <algorithm>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift {
namespace {

constexpr const char* kFormat = "fogdrift-model-set";

/// The text of each element of the top-level object's "models" array, as written: the models'
/// checksums cover their own text, so they are cut out, not parsed and written again. Strings
/// are skipped whole, so brackets and keys inside them do not count.
std::vector<std::string_view> model_texts(std::string_view text) {
  std::vector<std::string_view> out;
  int depth = 0;
  bool in_models = false;
  std::size_t element = 0;
  std::string_view last_string;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      const std::size_t start = ++i;
      while (i < text.size() && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
      last_string = text.substr(start, std::min(i, text.size()) - start);
      continue;
    }
    if (c == '{' || c == '[') {
      if (depth == 1 && c == '[' && last_string == "models") in_models = true;
      if (in_models && depth == 2 && c == '{') element = i;
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
      if (in_models && depth == 2 && c == '}') out.push_back(text.substr(element, i + 1 - element));
      if (in_models && depth == 1) in_models = false;
    } else if (c == ',' || c == ':') {
      if (c == ',') last_string = {};
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> ModelSet::targets() const {
  std::vector<std::string> out;
  for (const auto& m : models) out.push_back(m.dataset.target_column);
  return out;
}

std::vector<std::string> ModelSet::thermometer_columns() const {
  std::vector<std::string> out;
  for (const auto& m : models)
    for (std::string& column : m.dataset.features.thermometer_columns())
      if (std::find(out.begin(), out.end(), column) == out.end()) out.push_back(std::move(column));
  return out;
}

const CompensationModel* ModelSet::find(std::string_view target) const {
  for (const auto& m : models)
    if (m.dataset.target_column == target) return &m;
  return nullptr;
}

std::string to_json(const ModelSet& set) {
  if (set.models.empty()) throw OptionError("targets", "a model set needs at least one model");
  const std::vector<std::string> targets = set.targets();
  for (std::size_t i = 0; i < targets.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (targets[i] == targets[j])
        throw OptionError("targets", fmt::format("'{}' has two models", targets[i]));
  std::string text = fmt::format(
      "{{\n \"format\": \"{}\",\n \"version\": {},\n \"targets\": {},\n "
      "\"models\": [\n",
      kFormat, kModelSetVersion, nlohmann::json(targets).dump());
  for (std::size_t i = 0; i < set.models.size(); ++i) {
    std::string model = to_json(set.models[i]);
    while (!model.empty() && model.back() == '\n') model.pop_back();
    text += model;
    text += i + 1 < set.models.size() ? ",\n" : "\n";
  }
  return text + " ]\n}\n";
}

void save(const ModelSet& set, const std::filesystem::path& path) {
  write_text_atomically(path, to_json(set));
}

ModelSet model_set_from_json(const std::string& text, const std::string& source,
                             const ModelLoadOptions& options) {
  check_json_nesting(source, text);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw_json_syntax_error(source, text, e.byte, e.what());
  } catch (const nlohmann::json::exception& e) {
    throw_json_number_error(source, text, e.what());
  }
  ModelSet set;
  if (!doc.is_object() || !doc.contains("format") || doc["format"] != kFormat) {
    set.models.push_back(compensation_model_from_json(text, source, options));
    return set;
  }
  auto fail = [&](const std::string& where, const std::string& rule) {
    throw InputError(source, 0, 0, fmt::format("{}: {}", where, rule));
  };
  if (!doc.contains("version") || doc["version"] != kModelSetVersion)
    fail("version", fmt::format("model set version {} is not supported (this fogdrift reads "
                                "version {})",
                                doc.contains("version") ? doc["version"].dump() : "(missing)",
                                kModelSetVersion));
  if (!doc.contains("models") || !doc["models"].is_array() || doc["models"].empty())
    fail("models", "must be a list of one or more model files");
  const std::vector<std::string_view> texts = model_texts(text);
  if (texts.size() != doc["models"].size())
    fail("models", "every element must be a model file (a JSON object)");
  for (std::size_t i = 0; i < texts.size(); ++i)
    set.models.push_back(compensation_model_from_json(
        std::string(texts[i]), fmt::format("{} (models[{}])", source, i), options));
  std::vector<std::string> listed;
  try {
    listed = doc.at("targets").get<std::vector<std::string>>();
  } catch (const nlohmann::json::exception&) {
    fail("targets", "must be the list of the models' target columns");
  }
  if (listed != set.targets())
    fail("targets", fmt::format("lists {} but the models compensate {}", fmt::join(listed, ", "),
                                fmt::join(set.targets(), ", ")));
  try {
    to_json(set);  // no target twice
  } catch (const OptionError& e) {
    fail("targets", e.message());
  }
  return set;
}

ModelSet load_model_set(const std::filesystem::path& path, const ModelLoadOptions& options) {
  return model_set_from_json(read_text_file(path), path.string(), options);
}

const CompensationModel& choose_model(const ModelSet& set, const std::optional<std::string>& target,
                                      const std::string& option) {
  if (target) {
    if (const CompensationModel* m = set.find(*target)) return *m;
    throw OptionError(option, fmt::format("the model has no axis '{}' (it compensates {})", *target,
                                          fmt::join(set.targets(), ", ")));
  }
  if (set.models.size() == 1) return set.models.front();
  throw OptionError(option, fmt::format("the model compensates {} axes ({}); this command takes "
                                        "one: choose it with {} NAME",
                                        set.models.size(), fmt::join(set.targets(), ", "), option));
}

}  // namespace fogdrift
