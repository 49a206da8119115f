#include <kit/atomic_file.hpp>

#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

namespace kit {

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  auto temporary = path;
  temporary += fmt::format(".tmp-{}", ::getpid());
  return temporary;
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  const auto temporary = temporary_sibling(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(fmt::format("cannot write {}", path.string()));
    }
  }
  commit_file(temporary, path);
}

void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::filesystem::remove(temporary, error);
    throw std::runtime_error(fmt::format("cannot move {} into place: {}", path.string(), error.message()));
  }
}

}  // namespace kit
