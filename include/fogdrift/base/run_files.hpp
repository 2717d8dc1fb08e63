// The files one run reads and writes: its inputs noted so that no output replaces one, its
// temporaries registered so that an interrupted run removes them, and the standard descriptors
// an output may name (docs/reliability.md, "Outputs").
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fogdrift {

/// What the command line sets up before any command runs (a library user, such as the Python
/// package, does not, so that a session may read a file and later rewrite it):
/// - the files the run reads are noted (note_input), and an output that is one of them is refused;
/// - a standard descriptor (0, 1, 2) that was closed is opened on /dev/null, so that no file the
///   run opens takes its number, and remembered as closed: `-o /dev/stdout` is then refused;
/// - SIGINT, SIGTERM and SIGHUP are taken by one thread of their own, which removes every
///   registered temporary and ends the process with status 128 + the signal's number.
/// Call first in main(), before any thread starts, so that every thread inherits the blocked
/// signals.
void begin_guarded_run();

/// Notes that this run reads `path` (a no-op unless begin_guarded_run() was called).
void note_input(const std::filesystem::path& path);

/// Throws OptionError(option, …) when writing `output` would replace a file this run reads:
/// the same file (device and inode) or, for a folder output, a folder holding one. Commands call
/// it once their inputs are noted and before their work; the atomic writers check again.
void check_output_not_input(const std::filesystem::path& output, const std::string& option);

/// Throws OptionError(option, …) when `output` is one of `inputs` (the same file, through any
/// link) or a folder that holds one. For hosts that run no guarded run and so note no inputs
/// (Python, Octave): a call names what it read.
void check_output_not_among(const std::filesystem::path& output,
                            const std::vector<std::filesystem::path>& inputs,
                            const std::string& option);

/// The input `output` would replace, if any (same device and inode as a noted input, or, when
/// `output` is a folder, a noted input inside it).
std::optional<std::filesystem::path> input_replaced_by(const std::filesystem::path& output);

/// The descriptor a path names when it is one of the process's own: /dev/stdout (1),
/// /dev/stderr (2), /dev/stdin (0), /dev/fd/N, /proc/self/fd/N, or a symbolic link that leads
/// to one of them. Such a path is written through the descriptor, never opened anew or replaced.
std::optional<int> standard_descriptor_of(const std::filesystem::path& path);

/// True when descriptor `fd` is open and was not closed when the run began.
bool descriptor_usable(int fd);

/// Registers a temporary file or folder that an interrupting signal removes; the destructor
/// unregisters it (a SignalHold keeps the signal waiting across renames that must not be cut in
/// two).
class TemporaryRegistration {
 public:
  explicit TemporaryRegistration(std::filesystem::path path);
  ~TemporaryRegistration();
  TemporaryRegistration(const TemporaryRegistration&) = delete;
  TemporaryRegistration& operator=(const TemporaryRegistration&) = delete;
  /// Registers a second path (the old folder moved aside) under the same registration.
  void also(std::filesystem::path path);

 private:
  std::vector<std::filesystem::path> paths_;
};

/// Holds off the signal thread for its lifetime (a critical pair of renames).
class SignalHold {
 public:
  SignalHold();
  ~SignalHold();
  SignalHold(const SignalHold&) = delete;
  SignalHold& operator=(const SignalHold&) = delete;
};

}  // namespace fogdrift
