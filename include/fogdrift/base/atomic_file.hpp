// Atomic output: a file or a folder appears complete under its final name, or not at all.
//
// Writers produce into a hidden temporary sibling (".NAME.tmp-PID-XXXX") and rename it into
// place once everything is written and synced to the device, so a failed run never leaves a
// half-written output under the output's name. A run that is killed leaves at most its hidden
// temporary; the next write of the same output removes the temporaries of writers that no longer
// run (the PID in the name). A device, pipe or terminal (/dev/stdout, /dev/full) is written in
// place: there is nothing to rename, and renaming over a device node would replace it.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace fogdrift {

/// Writes `path` atomically. `write` fills the stream; if it throws, or the stream fails (a full
/// disk: InputError naming `path` and the system's reason), the temporary file is removed,
/// `path` is left as it was, and the error propagates.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// Convenience: writes `text` to `path` atomically.
void write_text_atomically(const std::filesystem::path& path, const std::string& text);

/// Fills a folder atomically. `fill` receives a fresh temporary folder beside `dir`; when it
/// returns, the folder is renamed to `dir`. `dir` must not exist or be empty, unless `replace`
/// is true, in which case an existing `dir` is replaced only after `fill` succeeded, in one step
/// where the file system can swap folders. On any error the temporary folder is removed and `dir`
/// is left untouched.
void fill_directory_atomically(const std::filesystem::path& dir, bool replace,
                               const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace fogdrift
