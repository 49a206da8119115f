// The --scene flag (scene_flag.hpp).
#include <kit/app/scene_flag.hpp>

#include <algorithm>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <kit/base/usage.hpp>

namespace kit {

std::filesystem::path scene_file(const std::string& value, const std::filesystem::path& scenes_dir) {
  const bool is_path = value.find('/') != std::string::npos || value.ends_with(".toml");
  if (is_path) return value;
  const std::filesystem::path file = scenes_dir / (value + ".toml");
  if (std::filesystem::exists(file)) return file;
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(scenes_dir, ec))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  throw UsageError(
      fmt::format("--scene: no scene named '{}'; the shipped scenes are {} (or give a .toml path)", value,
                  fmt::join(names, ", ")));
}

}  // namespace kit
