// Folder listings shared by the readers that take "one sub-folder per camera".
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace octocap::internal {

// The sub-folders of `directory`, sorted by name (the order cameras are matched in). Throws Error(io) when
// `directory` is not a folder.
std::vector<std::filesystem::path> sorted_subdirectories(const std::string& directory);

// The files of `directory` whose extension (compared without case, with its dot: ".png") is one of `extensions`,
// sorted by name (the order pictures are taken in); empty when there are none or `directory` is not a folder.
std::vector<std::string> sorted_files(const std::string& directory, const std::vector<std::string>& extensions);

// What a folder of pictures (a camera's, a board's) counts as pictures, and a take's folder as videos: extensions in
// lower case, with the dot.
const std::vector<std::string>& picture_extensions();
const std::vector<std::string>& video_extensions();

}  // namespace octocap::internal
