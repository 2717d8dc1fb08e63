// fogdrift's version, written into every file it produces (provenance).
#pragma once

namespace fogdrift {

inline constexpr const char* kVersion = "0.1.0";

}  // namespace fogdrift
