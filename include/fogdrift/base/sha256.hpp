// SHA-256 (FIPS 180-4) of bytes and files, as lowercase hex: the checksums a model's provenance
// records for its training files, comparable with `sha256sum`.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace fogdrift {

std::string sha256_hex(std::string_view bytes);
/// Throws InputError naming the file if it cannot be read.
std::string sha256_file_hex(const std::filesystem::path& path);

}  // namespace fogdrift
