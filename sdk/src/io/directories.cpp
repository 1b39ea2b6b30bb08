#include "io/directories.h"

#include <algorithm>

#include "core/error.h"

namespace octocap {

std::vector<std::filesystem::path> sorted_subdirectories(const std::string& directory) {
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) throw Error(Errc::io, directory + ": not a directory");
  std::vector<std::filesystem::path> dirs;
  for (const auto& e : std::filesystem::directory_iterator(directory, ec))
    if (e.is_directory()) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

}  // namespace octocap
