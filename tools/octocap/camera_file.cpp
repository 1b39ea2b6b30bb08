#include "camera_file.h"

#include <sys/stat.h>

#include <stdexcept>
#include <toml++/toml.h>

void read_camera_file(const std::string& path, std::vector<std::string>& cameras, std::vector<std::string>& names) {
  struct stat st{};
  if (stat(path.c_str(), &st) != 0) throw std::runtime_error("--cameras " + path + ": no such file");
  if (st.st_mode & (S_IRWXG | S_IRWXO))
    throw std::runtime_error("--cameras " + path + ": others may read it, and it holds camera passwords (chmod 600 " +
                             path + ")");
  toml::table file;
  try {
    file = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw std::runtime_error("--cameras " + path + ": line " + std::to_string(e.source().begin.line) + ": " +
                             std::string(e.description()));
  }
  const toml::array* list = file["camera"].as_array();
  if (!list || list->empty())
    throw std::runtime_error("--cameras " + path + ": no [[camera]] tables (each with url = \"...\")");
  for (size_t i = 0; i < list->size(); ++i) {
    const toml::table* camera = list->get(i)->as_table();
    const std::optional<std::string> url = camera ? (*camera)["url"].value<std::string>() : std::nullopt;
    if (!url || url->empty())
      throw std::runtime_error("--cameras " + path + ": camera " + std::to_string(i + 1) + " has no url = \"...\"");
    cameras.push_back(*url);
    names.push_back((*camera)["name"].value_or(std::string()));
  }
}
