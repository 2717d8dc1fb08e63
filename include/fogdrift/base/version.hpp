// fogdrift's version, written into every file it produces (provenance). The one place it is
// set: CMakeLists.txt and setup.py read it from here.
#pragma once

namespace fogdrift {

inline constexpr const char* kVersion = "0.1.0";

}  // namespace fogdrift
