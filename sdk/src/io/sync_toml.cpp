#include "io/sync_toml.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <toml++/toml.h>

#include "core/error.h"

namespace octocap::internal {

void write_sync_toml(const std::string& path, const SyncFile& s) {
  toml::table offsets;
  for (size_t c = 0; c < s.cameras.size(); ++c) offsets.insert_or_assign(s.cameras[c], s.offsets_frames.at(c));
  toml::table root{{"rate", s.rate_hz}, {"offsets_frames", offsets}};
  std::ofstream out(path);
  if (!out) throw Error(Errc::io, path + ": cannot open for writing");
  out << "# camera c's frame i was captured at (i + offset_c) / rate on the first camera's clock (octocap sync)\n";
  out << root << "\n";
  if (!out) throw Error(Errc::io, path + ": write failed");
}

SyncFile read_sync_toml(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw Error(Errc::io, path + ": cannot open sync file");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw Error(Errc::parse, path + ": malformed TOML: " + std::string(e.description()));
  }
  SyncFile s;
  const std::optional<double> rate = root["rate"].value<double>();
  if (!rate || !std::isfinite(*rate) || *rate <= 0 || *rate > 1e5) throw Error(Errc::parse, path + ": 'rate' must be a positive number");
  s.rate_hz = *rate;
  const toml::table* offsets = root["offsets_frames"].as_table();
  if (!offsets) throw Error(Errc::parse, path + ": no [offsets_frames] table");
  for (const auto& [key, node] : *offsets) {
    const std::optional<double> v = node.value<double>();
    if (!v || !std::isfinite(*v) || std::abs(*v) > 1e6)
      throw Error(Errc::parse, path + ": offsets_frames." + std::string(key.str()) + " is not a number of frames");
    s.cameras.emplace_back(key.str());
    s.offsets_frames.push_back(*v);
  }
  return s;
}

}  // namespace octocap::internal
