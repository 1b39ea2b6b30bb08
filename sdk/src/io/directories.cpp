#include "io/directories.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace octocap::internal {

std::vector<std::filesystem::path> sorted_subdirectories(const std::string& directory) {
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) throw Error(Errc::io, directory + ": not a directory");
  std::vector<std::filesystem::path> dirs;
  for (const auto& e : std::filesystem::directory_iterator(directory, ec))
    if (e.is_directory()) dirs.push_back(e.path());
  std::sort(dirs.begin(), dirs.end());
  return dirs;
}

std::vector<std::string> sorted_files(const std::string& directory, const std::vector<std::string>& extensions) {
  std::error_code ec;
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(directory, ec)) {
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (e.is_regular_file() && std::find(extensions.begin(), extensions.end(), ext) != extensions.end())
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

const std::vector<std::string>& picture_extensions() {
  static const std::vector<std::string> extensions = {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff"};
  return extensions;
}

const std::vector<std::string>& video_extensions() {
  static const std::vector<std::string> extensions = {".mp4", ".avi", ".mov", ".mkv", ".webm"};
  return extensions;
}

}  // namespace octocap::internal
