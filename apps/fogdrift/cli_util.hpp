// Small helpers shared by the subcommands: parsing lists, reading files, terminal detection.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace fogdrift::app {

/// "-40,-30,25" -> {-40, -30, 25}; throws OptionError naming `option` on a bad element.
std::vector<double> parse_number_list(const std::string& text, const std::string& option);

/// Whole file as text; throws InputError if it cannot be read.
std::string read_text_file(const std::string& path);

/// Runs `body`, a command that applies the model file `model_path`. A setting fixed in the model
/// that the data cannot meet (the library names it: window_s, block_s, denoise, ...) is reported
/// as the model's, with the train flag that sets it, since the command itself cannot change it.
void with_model_settings(const std::string& model_path, const std::function<void()>& body);

/// True when standard error is a terminal (progress lines are shown only then).
bool stderr_is_terminal();

}  // namespace fogdrift::app
