#include "fogdrift/io/campaign.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/io/target.hpp"

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace fogdrift {
namespace {

// Content errors carry the JSON path in the message; line/column are unknown after parsing.
[[noreturn]] void fail(const std::string& file, const std::string& json_path,
                       const std::string& rule) {
  throw InputError(file, 0, 0, fmt::format("{}: {}", json_path, rule));
}

void check_keys(const json& object, const std::set<std::string>& known, const std::string& file,
                const std::string& path) {
  for (const auto& [key, value] : object.items()) {
    if (!known.count(key)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      fail(file, path.empty() ? key : path + "." + key,
           fmt::format("unknown field (known: {}; free-form text goes under \"notes\")", list));
    }
  }
}

double number_in(const json& object, const std::string& key, double lo, double hi, bool hi_open,
                 const std::string& file, const std::string& path) {
  const std::string where = path.empty() ? key : path + "." + key;
  if (!object.contains(key)) fail(file, where, "required field is missing");
  const json& v = object.at(key);
  if (!v.is_number()) fail(file, where, fmt::format("must be a number, found {}", v.dump()));
  const double x = v.get<double>();
  const bool above = hi_open ? !(x < hi) : !(x <= hi);
  if (!std::isfinite(x) || x < lo || above) {
    fail(file, where,
         fmt::format("{} is outside [{}, {}{}", v.dump(), lo, hi, hi_open ? ")" : "]"));
  }
  return x;
}

std::string string_field(const json& object, const std::string& key, const std::string& file,
                         const std::string& path) {
  const std::string where = path + "." + key;
  if (!object.contains(key)) fail(file, where, "required field is missing");
  const json& v = object.at(key);
  if (!v.is_string()) fail(file, where, fmt::format("must be a string, found {}", v.dump()));
  return v.get<std::string>();
}

}  // namespace

namespace {

constexpr std::array<EnumName<Scenario>, 3> kScenarioNames = {
    {{Scenario::calibration, "calibration"},
     {Scenario::northfind, "northfind"},
     {Scenario::stable, "stable"}}};
constexpr std::array<EnumName<Role>, 2> kRoleNames = {
    {{Role::train, "train"}, {Role::test, "test"}}};

}  // namespace

std::string_view to_string(Scenario scenario) {
  return name_in(kScenarioNames, scenario);
}

std::string_view to_string(Role role) {
  return name_in(kRoleNames, role);
}

namespace {

// The manifest `text` (named `file` in errors) of a campaign in `dir`; with `files_exist`, each
// recording's file must be there.
Campaign parse_manifest(const std::string& text, const std::string& file, const fs::path& dir,
                        bool files_exist) {
  check_json_nesting(file, text);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw_json_syntax_error(file, text, e.byte, e.what());
  } catch (const json::out_of_range& e) {
    throw_json_number_error(file, text, e.what());
  }
  if (!doc.is_object()) fail(file, "(top level)", "must be a JSON object");
  // Another of fogdrift's files where a manifest belongs: say which, before any field's rule.
  if (doc.contains("format") && doc["format"].is_string()) {
    const std::string format = doc["format"].get<std::string>();
    if (format.rfind("fogdrift-", 0) == 0 && format.rfind("fogdrift-campaign", 0) != 0)
      throw InputError(file, 0, 0,
                       fmt::format("is a fogdrift file of format \"{}\" (a model), not a campaign "
                                   "manifest: give the campaign folder (or its campaign.json) "
                                   "here, and the model where a command takes MODEL",
                                   csv::excerpt(format)));
  }
  check_keys(doc, {"format", "latitude_deg", "recordings", "generator", "notes"}, file, "");
  if (!doc.contains("format")) fail(file, "format", "required field is missing");
  if (!doc["format"].is_string() || doc["format"].get<std::string>() != kCampaignFormat) {
    fail(file, "format",
         fmt::format("is {}, expected \"{}\" (a newer fogdrift may be needed)",
                     doc["format"].dump(), kCampaignFormat));
  }

  Campaign c;
  c.dir = dir;
  if (doc.contains("latitude_deg"))
    c.latitude_deg = number_in(doc, "latitude_deg", -90, 90, false, file, "");
  if (doc.contains("generator")) c.generator_json = doc["generator"].dump();
  if (doc.contains("notes")) c.notes_json = doc["notes"].dump();
  if (!doc.contains("recordings")) fail(file, "recordings", "required field is missing");
  const json& list = doc["recordings"];
  if (!list.is_array() || list.empty()) fail(file, "recordings", "must be a non-empty array");

  std::set<std::string> seen_files;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path_i = fmt::format("recordings[{}]", i);
    const json& r = list[i];
    if (!r.is_object()) fail(file, path_i, "must be an object");
    check_keys(r,
               {"file", "scenario", "role", "repetition", "initial_temp_degc", "true_azimuth_deg",
                "input_rate_dph", "references", "notes"},
               file, path_i);
    CampaignEntry e;
    e.file = string_field(r, "file", file, path_i);
    if (e.file.empty()) fail(file, path_i + ".file", "must not be empty");
    if (fs::path(e.file).is_absolute()) {
      fail(file, path_i + ".file", "must be relative to the campaign folder");
    }
    // Found by attack (issue 36, "reader leniency"): a NUL made "a.csv\u0000x" name a.csv, a
    // second entry for one file; "../" reached outside the campaign, as an absolute path may not.
    if (std::any_of(e.file.begin(), e.file.end(),
                    [](char ch) { return static_cast<unsigned char>(ch) < 0x20; }))
      fail(file, path_i + ".file", "must not hold a control character (a NUL, a line break, …)");
    for (const fs::path& part : fs::path(e.file))
      if (part == "..")
        fail(file, path_i + ".file",
             fmt::format("\"{}\" leaves the campaign folder; recordings lie inside it", e.file));
    if (!seen_files.insert(fs::path(e.file).lexically_normal().string()).second) {
      fail(file, path_i + ".file", fmt::format("\"{}\" is listed twice", e.file));
    }
    const std::string scenario = string_field(r, "scenario", file, path_i);
    if (const auto v = find_in(kScenarioNames, scenario))
      e.scenario = *v;
    else
      fail(file, path_i + ".scenario",
           fmt::format("\"{}\" is not one of {}", scenario, names_in(kScenarioNames)));
    const std::string role = string_field(r, "role", file, path_i);
    if (const auto v = find_in(kRoleNames, role))
      e.role = *v;
    else
      fail(file, path_i + ".role",
           fmt::format("\"{}\" is not one of {}", role, names_in(kRoleNames)));
    if (r.contains("repetition")) {
      const json& v = r["repetition"];
      if (!v.is_number_integer() || v.get<long long>() < 1 || v.get<long long>() > 1000000) {
        fail(file, path_i + ".repetition", fmt::format("{} is not an integer >= 1", v.dump()));
      }
      e.repetition = v.get<int>();
    }
    e.initial_temp_degc = number_in(r, "initial_temp_degc", -70, 100, false, file, path_i);
    if (r.contains("true_azimuth_deg")) {
      e.true_azimuth_deg = number_in(r, "true_azimuth_deg", 0, 360, true, file, path_i);
    } else if (e.scenario != Scenario::calibration) {
      fail(file, path_i + ".true_azimuth_deg",
           fmt::format("required for a {} recording (the north-finding reference)", scenario));
    }
    if (r.contains("input_rate_dph")) {
      e.input_rate_dph = number_in(r, "input_rate_dph", -1e7, 1e7, false, file, path_i);
    }
    if (r.contains("references")) {
      const json& refs = r["references"];
      const std::string at = path_i + ".references";
      if (!refs.is_object()) fail(file, at, "must be an object of target column: value");
      for (const auto& [column, value] : refs.items()) {
        if (!is_target_column(column))
          fail(file, at,
               fmt::format("\"{}\" is not a target column (gyro_NAME_dph, accel_NAME_g, "
                           "sf_NAME_ppm; docs/logs.md, \"Other targets\")",
                           column));
        e.references[column] =
            number_in(refs, column, -kReferenceLimit, kReferenceLimit, false, file, at);
      }
    }
    if (r.contains("notes")) e.notes_json = r["notes"].dump();
    const fs::path rec_path = c.dir / e.file;
    if (files_exist && !fs::is_regular_file(rec_path)) {
      std::error_code ec;
      fail(file, path_i + ".file",
           fmt::format("recording \"{}\" {}", rec_path.string(),
                       fs::exists(rec_path, ec)
                           ? "is not a regular file (a folder, a pipe, a device)"
                           : "does not exist"));
    }
    if (!c.latitude_deg &&
        (e.scenario != Scenario::calibration || (e.true_azimuth_deg && !e.input_rate_dph))) {
      fail(file, "latitude_deg",
           fmt::format("required field is missing: {} uses it ({})", path_i,
                       e.scenario != Scenario::calibration
                           ? "north-finding needs the Earth rate"
                           : "its input rate is the Earth rate at true_azimuth_deg"));
    }
    c.recordings.push_back(std::move(e));
  }
  return c;
}

}  // namespace

Campaign read_campaign(const fs::path& path) {
  const fs::path manifest = fs::is_directory(path) ? path / "campaign.json" : path;
  const std::string file = manifest.string();
  std::ifstream in(manifest, std::ios::binary);
  if (!in) {
    throw InputError(file, 0, 0,
                     fs::exists(manifest) ? "cannot be read"
                                          : "not found (a campaign folder holds campaign.json)");
  }
  note_input(manifest);
  std::stringstream buffer;
  buffer << in.rdbuf();
  Campaign c =
      parse_manifest(buffer.str(), file,
                     manifest.has_parent_path() ? manifest.parent_path() : fs::path("."), true);
  for (const CampaignEntry& e : c.recordings) note_input(c.path_of(e));
  return c;
}

Campaign campaign_from_json(const std::string& text, const std::string& source) {
  return parse_manifest(text, source, fs::path(), false);
}

std::string manifest_json(const Campaign& c) {
  using ojson = nlohmann::ordered_json;
  ojson doc = ojson::object();
  doc["format"] = kCampaignFormat;
  if (c.latitude_deg) doc["latitude_deg"] = *c.latitude_deg;
  if (!c.generator_json.empty()) doc["generator"] = ojson::parse(c.generator_json);
  if (!c.notes_json.empty()) doc["notes"] = ojson::parse(c.notes_json);
  ojson list = ojson::array();
  for (const auto& e : c.recordings) {
    ojson r = ojson::object();
    r["file"] = e.file;
    r["scenario"] = to_string(e.scenario);
    r["role"] = to_string(e.role);
    r["repetition"] = e.repetition;
    r["initial_temp_degc"] = e.initial_temp_degc;
    if (e.true_azimuth_deg) r["true_azimuth_deg"] = *e.true_azimuth_deg;
    if (e.input_rate_dph) r["input_rate_dph"] = *e.input_rate_dph;
    if (!e.references.empty()) {
      r["references"] = ojson::object();
      for (const auto& [column, value] : e.references) r["references"][column] = value;
    }
    if (!e.notes_json.empty()) r["notes"] = ojson::parse(e.notes_json);
    list.push_back(std::move(r));
  }
  doc["recordings"] = std::move(list);
  return doc.dump(2) + "\n";
}

void write_manifest(const fs::path& dir, const Campaign& campaign) {
  write_text_atomically(dir / "campaign.json", manifest_json(campaign));
}

}  // namespace fogdrift
