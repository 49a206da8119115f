#pragma once
// The --scene flag of the chapters with scene files (5, 6): a bare name is a file shipped in the
// chapter's scenes/ folder, anything with a '/' or ending in .toml is a path.
#include <filesystem>
#include <string>

namespace kit {

/// The file `--scene value` names: scenes_dir/value.toml for a bare name, else value itself.
/// UsageError for a bare name with no such file, listing the shipped scenes.
std::filesystem::path scene_file(const std::string& value, const std::filesystem::path& scenes_dir);

}  // namespace kit
