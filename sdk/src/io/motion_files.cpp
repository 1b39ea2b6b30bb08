#include "io/motion_files.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/error.h"

namespace octocap {
namespace {

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream s(line);
  while (std::getline(s, cell, '\t')) out.push_back(cell);
  if (!line.empty() && line.back() == '\t') out.emplace_back();
  return out;
}

std::ofstream open_out(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw Error(Errc::io, path + ": cannot open for writing");
  out << std::setprecision(9);
  return out;
}

}  // namespace

void write_trc(const std::string& path, const MotionTrack& track, bool z_up) {
  std::ofstream out = open_out(path);
  const size_t n = track.markers.size();
  const std::string file = std::filesystem::path(path).filename().string();
  out << "PathFileType\t4\t(X/Y/Z)\t" << file << "\n";
  out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
  out << track.rate_hz << "\t" << track.rate_hz << "\t" << track.frames.size() << "\t" << n << "\tm\t"
      << track.rate_hz << "\t0\t" << track.frames.size() << "\n";
  out << "Frame#\tTime";
  for (const auto& m : track.markers) out << "\t" << m << "\t\t";
  out << "\n\t";
  for (size_t i = 0; i < n; ++i) out << "\tX" << i + 1 << "\tY" << i + 1 << "\tZ" << i + 1;
  out << "\n\n";
  for (size_t f = 0; f < track.frames.size(); ++f) {
    out << f + 1 << "\t" << static_cast<double>(f + 1) / track.rate_hz;
    for (const auto& p0 : track.frames[f]) {
      if (!p0.allFinite()) {
        out << "\t\t\t";
        continue;
      }
      const Eigen::Vector3d p = z_up ? zup_to_yup(p0) : p0;
      out << "\t" << p.x() << "\t" << p.y() << "\t" << p.z();
    }
    out << "\n";
  }
  if (!out) throw Error(Errc::io, path + ": write failed");
}

void write_csv(const std::string& path, const MotionTrack& track) {
  std::ofstream out = open_out(path);
  out << (track.per_person ? "frame,person" : "frame");
  for (const auto& m : track.markers) out << "," << m << "_x," << m << "_y," << m << "_z";
  out << "\n";
  for (size_t f = 0; f < track.frames.size(); ++f) {
    if (track.per_person)
      out << track.rows.at(f).first << "," << track.rows.at(f).second;
    else
      out << f;
    for (const auto& p : track.frames[f]) {
      if (p.allFinite())
        out << "," << p.x() << "," << p.y() << "," << p.z();
      else
        out << ",,,";
    }
    out << "\n";
  }
  if (!out) throw Error(Errc::io, path + ": write failed");
}

double parse_coordinate(const std::string& cell, const std::string& where) {
  const char* begin = cell.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(v))
    throw Error(Errc::parse, where + ": '" + cell + "' is not a number");
  if (std::abs(v) > 1e6) throw Error(Errc::parse, where + ": coordinate " + cell + " is out of range (|v| > 1e6)");
  return v;
}

double parse_rate(const std::string& cell, const std::string& where) {
  const char* begin = cell.c_str();
  char* end = nullptr;
  const double v = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(v) || v < 1e-3 || v > 1e5)
    throw Error(Errc::parse, where + ": '" + cell + "' is not a frame rate (0.001 to 100000 Hz)");
  return v;
}

MotionTrack read_trc(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, path + ": cannot open TRC file");
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  if (lines.size() < 5) throw Error(Errc::parse, path + ": too short for a TRC header (5 lines)");
  const auto keys = split_tabs(lines[1]);
  const auto vals = split_tabs(lines[2]);
  MotionTrack t;
  double scale = 1.0;
  for (size_t i = 0; i < keys.size() && i < vals.size(); ++i) {
    if (keys[i] == "DataRate") t.rate_hz = parse_rate(vals[i], path + ": DataRate");
    if (keys[i] == "Units" && vals[i] == "mm") scale = 0.001;
  }
  const auto names = split_tabs(lines[3]);
  for (size_t i = 2; i < names.size(); i += 3)
    if (!names[i].empty()) t.markers.push_back(names[i]);
  if (t.markers.empty()) throw Error(Errc::parse, path + ": line 4 names no marker");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (size_t li = 5; li < lines.size(); ++li) {
    if (lines[li].find_first_not_of(" \t") == std::string::npos) continue;
    const auto cells = split_tabs(lines[li]);
    MarkerFrame frame(t.markers.size(), Eigen::Vector3d::Constant(nan));
    for (size_t m = 0; m < t.markers.size(); ++m) {
      const size_t c = 2 + 3 * m;
      if (c + 2 >= cells.size() || cells[c].empty()) continue;
      const std::string where = path + ":" + std::to_string(li + 1);
      frame[m] = Eigen::Vector3d(parse_coordinate(cells[c], where), parse_coordinate(cells[c + 1], where),
                                 parse_coordinate(cells[c + 2], where)) * scale;
    }
    t.frames.push_back(std::move(frame));
  }
  return t;
}

}  // namespace octocap
