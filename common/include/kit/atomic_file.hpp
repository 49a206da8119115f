#pragma once
// Files appear whole or not at all: write a temporary sibling, then rename it into place.
#include <filesystem>
#include <string_view>

namespace kit {

/// A temporary name next to `path` ("name.ext.tmp-<pid>"), on the same file system, so the
/// final rename is atomic.
std::filesystem::path temporary_sibling(const std::filesystem::path& path);

/// Writes `content` to `path` through a temporary sibling. Throws std::runtime_error naming
/// the path when the write fails; no partial file is left behind.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Renames a finished temporary file onto its final name.
void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& path);

}  // namespace kit
