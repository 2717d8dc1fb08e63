// The fogdrift tool's entry: main() calls run(), so that main.cpp compiles in a second and the
// command line's code (CLI11's, inline in its headers) is compiled once, with the commands.
#pragma once

namespace fogdrift::app {

/// Runs the command line `argv` and returns the exit status (0, 1 or CLI11's usage codes).
int run(int argc, char** argv);

}  // namespace fogdrift::app
