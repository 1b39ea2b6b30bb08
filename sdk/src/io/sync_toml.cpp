#include "io/sync_toml.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <toml++/toml.h>

#include "core/error.h"

namespace octocap::internal {

namespace {

// What a sync file may hold, written or read (so that every file written reads back): a rate above 0 and at most
// 100000 Hz, offsets finite and within a million frames.
bool valid_rate(double hz) { return std::isfinite(hz) && hz > 0 && hz <= 1e5; }
bool valid_offset(double frames) { return std::isfinite(frames) && std::abs(frames) <= 1e6; }

}  // namespace

void write_sync_toml(const std::string& path, const SyncFile& s) {
  if (!valid_rate(s.rate_hz)) throw Error(Errc::invalid_argument, "rate_hz must be > 0 and at most 100000");
  if (s.offsets_frames.size() != s.cameras.size())
    throw Error(Errc::invalid_argument, "one offset per camera");
  for (double v : s.offsets_frames)
    if (!valid_offset(v)) throw Error(Errc::invalid_argument, "an offset is NaN, infinite or beyond a million frames");
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
  if (!rate || !valid_rate(*rate)) throw Error(Errc::parse, path + ": 'rate' must be a positive number");
  s.rate_hz = *rate;
  const toml::table* offsets = root["offsets_frames"].as_table();
  if (!offsets) throw Error(Errc::parse, path + ": no [offsets_frames] table");
  for (const auto& [key, node] : *offsets) {
    const std::optional<double> v = node.value<double>();
    if (!v || !valid_offset(*v))
      throw Error(Errc::parse, path + ": offsets_frames." + std::string(key.str()) + " is not a number of frames");
    s.cameras.emplace_back(key.str());
    s.offsets_frames.push_back(*v);
  }
  return s;
}

}  // namespace octocap::internal
