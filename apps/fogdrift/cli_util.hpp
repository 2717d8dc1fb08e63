// Small helpers shared by the subcommands: parsing lists, reading files, terminal detection.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/model_set.hpp"

namespace CLI {
class App;
}

namespace fogdrift::app {

/// "a,b,c" -> {"a", "b", "c"} (an empty text is one empty item).
std::vector<std::string> split_list(const std::string& text);

/// The one model a command that compensates one gyro uses: the model file's, or the model set's
/// for the axis `target` (--target; model_set.hpp).
CompensationModel load_one_model(const std::string& path, const ModelLoadOptions& load,
                                 const std::optional<std::string>& target);

/// The axes a command that runs them together (stream, export-c) runs: the one `target` names
/// (--target), else every axis of the set. Throws OptionError("--target") when the axes' models
/// differ in sample interval, block or rate window, which one update cannot serve.
ModelSet axes_to_run(const ModelSet& set, const std::optional<std::string>& target);

/// The output path of piece `index` of `count` a command splits its result into: out.csv itself
/// for one piece, else out_1.csv, out_2.csv, ...
std::filesystem::path piece_path(const std::filesystem::path& target, std::size_t index,
                                 std::size_t count);

/// "-40,-30,25" -> {-40, -30, 25}; throws OptionError naming `option` on a bad element.
std::vector<double> parse_number_list(const std::string& text, const std::string& option);

/// Whole file as text; throws InputError if it cannot be read.
std::string read_text_file(const std::string& path);

/// Library field paths ("calibration.temps_degc", "cv.folds") and the flags that set them in one
/// command: the one place a command says which of its flags sets which field.
using FlagTable = std::map<std::string, std::string>;

/// `e` named by the flag that sets its field, when `flags` has one; otherwise as the library
/// named it (a field the command has no flag for).
OptionError as_flag(const OptionError& e, const FlagTable& flags);

/// The flag that sets library field `field`, or the field's own name when there is none.
std::string flag_for(const std::string& field, const FlagTable& flags);

/// Runs `body`, naming every option error by its flag.
void with_flags(const FlagTable& flags, const std::function<void()>& body);

/// Runs `body`, a command that applies the model file `model_path`. A setting fixed in the model
/// that the data cannot meet (the library names it: window_s, block_s, denoise, ...) is reported
/// as the model's, with the train flag that sets it, since the command itself cannot change it.
void with_model_settings(const std::string& model_path, const std::function<void()>& body);

/// The flags of every command that loads a model file, --allow-edited and --allow-old-format,
/// from their one description (model_load_option_table.hpp).
void add_model_load_flags(CLI::App* cmd, ModelLoadOptions* options);

/// Flushes standard output and throws InputError("standard output: …") when a write to it
/// failed (a full disk, /dev/full, a closed file): a command whose output is incomplete must not
/// exit 0 (docs/reliability.md, "Standard output").
void check_standard_output();

/// True when standard error is a terminal (progress lines are shown only then).
bool stderr_is_terminal();

}  // namespace fogdrift::app
