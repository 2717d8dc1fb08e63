#include "cli_util.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/model/model_load_option_table.hpp"
#include "fogdrift/model/model_set.hpp"

namespace fogdrift::app {

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const auto comma = text.find(',', pos);
    out.push_back(text.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos));
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return out;
}

CompensationModel load_one_model(const std::string& path, const ModelLoadOptions& load,
                                 const std::optional<std::string>& target) {
  return choose_model(load_model_set(path, load), target, "--target");
}

ModelSet axes_to_run(const ModelSet& set, const std::optional<std::string>& target) {
  ModelSet out;
  if (target || set.models.size() == 1) {
    out.models.push_back(choose_model(set, target, "--target"));
    return out;
  }
  const FeatureOptions& p = set.models.front().dataset.preprocessing;
  for (const CompensationModel& other : set.models) {
    const FeatureOptions& q = other.dataset.preprocessing;
    if (q.sample_interval_s != p.sample_interval_s || q.rates.window_s != p.rates.window_s ||
        q.rates.poly_order != p.rates.poly_order || q.block.block_s != p.block.block_s)
      throw OptionError(
          "--target",
          fmt::format("the axes' models differ in interval, block or rate window "
                      "({} against {}); run each with --target NAME",
                      other.dataset.target_column, set.models.front().dataset.target_column));
  }
  return set;
}

std::filesystem::path piece_path(const std::filesystem::path& target, std::size_t index,
                                 std::size_t count) {
  if (count == 1) return target;
  return target.parent_path() /
         fmt::format("{}_{}{}", target.stem().string(), index + 1, target.extension().string());
}

std::vector<double> parse_number_list(const std::string& text, const std::string& option) {
  std::vector<double> values;
  for (const std::string& item : split_list(text)) {
    const auto v = csv::parse_number(item);
    if (!v) {
      throw OptionError(option, fmt::format("'{}' in '{}' is not a number (give a comma-separated "
                                            "list such as -40,-30,25)",
                                            item, text));
    }
    values.push_back(*v);
  }
  return values;
}

std::string read_text_file(const std::string& path) {
  return fogdrift::read_text_file(std::filesystem::path(path));
}

OptionError as_flag(const OptionError& e, const FlagTable& flags) {
  return flags.contains(e.option()) ? OptionError(flag_for(e.option(), flags), e.message()) : e;
}

std::string flag_for(const std::string& field, const FlagTable& flags) {
  const auto it = flags.find(field);
  return it == flags.end() ? field : it->second;
}

void with_flags(const FlagTable& flags, const std::function<void()>& body) {
  try {
    body();
  } catch (const OptionError& e) {
    throw as_flag(e, flags);
  }
}

void with_model_settings(const std::string& model_path, const std::function<void()>& body) {
  try {
    body();
  } catch (const OptionError& e) {
    static const std::map<std::string, std::string> train_flag = {{"window_s", "--rate-window-s"},
                                                                  {"poly_order", "--rate-window-s"},
                                                                  {"block_s", "--block-s"},
                                                                  {"denoise", "--denoise"},
                                                                  {"dt_s", "--rate-hz"}};
    const auto it = train_flag.find(e.option());
    if (it == train_flag.end() || e.option() == "dt_s") throw;
    throw InputError(model_path, 0, 0,
                     fmt::format("the model's {} (set by train {}) does not fit this data: {}",
                                 e.option(), it->second, e.message()));
  }
}

bool stderr_is_terminal() {
  return ::isatty(STDERR_FILENO) == 1;
}

void check_standard_output() {
  int error = errno;  // the reason of a write that already failed, if one did
  if (std::cout) {
    errno = 0;
    std::cout.flush();
    if (std::cout && std::fflush(stdout) == 0 && !std::ferror(stdout)) return;
    if (errno != 0) error = errno;
  }
  throw InputError("standard output", 0, 0,
                   fmt::format("write failed ({}); the output is incomplete",
                               error != 0 ? std::strerror(error) : "an I/O error"));
}

void add_model_load_flags(CLI::App* cmd, ModelLoadOptions* options) {
  const auto& table = model_load_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  // Both are switches off by default: a flag turns each on (option_flags.hpp's rule).
  for (const Option<ModelLoadOptions>& o : table)
    cmd->add_flag_callback(
        o.spec.flag, [&o, options] { o.set(*options, "true"); }, option_help(o.spec, specs, true));
}

}  // namespace fogdrift::app
