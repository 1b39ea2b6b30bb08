#include "io/motion_files.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/axes.h"
#include "core/error.h"
#include "core/take_timing.h"

namespace octocap::internal {
namespace {

// A line's cells between `sep`s; a trailing separator ends with an empty cell, a trailing CR is no part of it.
std::vector<std::string> split_cells(std::string line, char sep) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> out;
  std::string cell;
  std::istringstream s(line);
  while (std::getline(s, cell, sep)) out.push_back(cell);
  if (!line.empty() && line.back() == sep) out.emplace_back();
  return out;
}

std::vector<std::string> split_tabs(const std::string& line) { return split_cells(line, '\t'); }

// A whole non-negative integer cell (a frame number, a person id) within `max`.
int64_t parse_count(const std::string& cell, const std::string& where, int64_t max) {
  const char* begin = cell.c_str();
  char* end = nullptr;
  const long long v = std::strtoll(begin, &end, 10);
  if (end == begin || *end != '\0' || v < 0 || v > max) throw Error(Errc::parse, where + ": '" + cell + "' is not a whole number 0.." + std::to_string(max));
  return v;
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
    out << f + 1 << "\t" << track.time_of(f);
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

namespace {

void write_csv_header(std::ostream& out, const std::vector<std::string>& markers, bool per_person) {
  out << (per_person ? "frame,time,person" : "frame,time");
  for (const auto& m : markers) out << "," << m << "_x," << m << "_y," << m << "_z";
  out << "\n";
}

// person < 0: a one-person CSV's row (no person column).
void write_csv_row(std::ostream& out, int64_t frame, double time_s, int64_t person, const MarkerFrame& points) {
  out << frame << "," << time_s;
  if (person >= 0) out << "," << person;
  for (const auto& p : points) {
    if (p.allFinite())
      out << "," << p.x() << "," << p.y() << "," << p.z();
    else
      out << ",,,";
  }
  out << "\n";
}

}  // namespace

void write_csv(const std::string& path, const MotionTrack& track) {
  std::ofstream out = open_out(path);
  write_csv_header(out, track.markers, track.per_person);
  for (size_t f = 0; f < track.frames.size(); ++f) {
    if (track.per_person)
      write_csv_row(out, track.rows.at(f).first, track.time_of(f), track.rows.at(f).second, track.frames[f]);
    else
      write_csv_row(out, static_cast<int64_t>(f), track.time_of(f), -1, track.frames[f]);
  }
  if (!out) throw Error(Errc::io, path + ": write failed");
}

CsvAppender::CsvAppender(std::string path, const std::vector<std::string>& markers, bool per_person)
    : path_(std::move(path)), per_person_(per_person) {
  out_ = open_out(path_);
  write_csv_header(out_, markers, per_person);
  out_.flush();
  if (!out_) throw Error(Errc::io, path_ + ": write failed");
}

void CsvAppender::append(int64_t frame, double time_s, int64_t person, const MarkerFrame& points) {
  write_csv_row(out_, frame, time_s, per_person_ ? person : -1, points);
  out_.flush();  // on disk before the next frame: a process killed now loses only the frame being added
  if (!out_) throw Error(Errc::io, path_ + ": write failed");
}

MotionTrack read_csv(const std::string& path, double rate_hz) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, "cannot open " + path);
  std::string line;
  if (!std::getline(in, line)) throw Error(Errc::parse, path + ": empty");
  const std::vector<std::string> header = split_cells(line, ',');
  MotionTrack t;
  t.rate_hz = rate_hz;
  // frame[,time][,person],NAME_x,NAME_y,NAME_z,...
  size_t first = 1;
  const bool timed = header.size() > first && header[first] == "time";
  first += timed;
  t.per_person = header.size() > first && header[first] == "person";
  first += t.per_person;
  if (header.empty() || header[0] != "frame" || header.size() < first + 3 || (header.size() - first) % 3 != 0)
    throw Error(Errc::parse, path + ": not a `frame[,time][,person],NAME_x,NAME_y,NAME_z,...` CSV");
  for (size_t i = first; i < header.size(); i += 3) {
    const std::string& h = header[i];
    if (h.size() < 3 || h.compare(h.size() - 2, 2, "_x") != 0) throw Error(Errc::parse, path + ": column " + h + " is not NAME_x");
    t.markers.push_back(h.substr(0, h.size() - 2));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    std::vector<std::string> cells = split_cells(line, ',');
    if (cells.empty() || (cells.size() == 1 && cells[0].empty())) continue;
    const std::string where = path + ":" + std::to_string(line_no);
    if (cells.size() > header.size()) throw Error(Errc::parse, where + ": more cells than the header names");
    cells.resize(header.size());
    const int64_t frame = parse_count(cells[0], where + ": frame", int64_t{1} << 40);
    if (timed) {
      const char* begin = cells[1].c_str();
      char* end = nullptr;
      const double s = std::strtod(begin, &end);
      if (end == begin || *end != '\0' || !std::isfinite(s) || std::abs(s) > 1e9)
        throw Error(Errc::parse, where + ": '" + cells[1] + "' is not a time in seconds");
      t.times_s.push_back(s);
    }
    if (t.per_person) t.rows.emplace_back(frame, static_cast<uint32_t>(parse_count(cells[first - 1], where + ": person", 0xffffffffLL)));
    MarkerFrame f(t.markers.size(), Eigen::Vector3d::Constant(nan));
    for (size_t m = 0; m < t.markers.size(); ++m) {
      const std::string* c = &cells[first + 3 * m];
      if (c[0].empty() || c[1].empty() || c[2].empty()) continue;
      f[m] = {parse_coordinate(c[0], where), parse_coordinate(c[1], where), parse_coordinate(c[2], where)};
    }
    t.frames.push_back(std::move(f));
  }
  return t;
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
  std::vector<double> times;  // the Time column, kept when it says when each frame happened
  for (size_t li = 5; li < lines.size(); ++li) {
    if (lines[li].find_first_not_of(" \t") == std::string::npos) continue;
    const auto cells = split_tabs(lines[li]);
    MarkerFrame frame(t.markers.size(), Eigen::Vector3d::Constant(nan));
    if (cells.size() > 1) {
      char* end = nullptr;
      const double s = std::strtod(cells[1].c_str(), &end);
      times.push_back(end != cells[1].c_str() && *end == '\0' ? s : nan);
    } else {
      times.push_back(nan);
    }
    for (size_t m = 0; m < t.markers.size(); ++m) {
      const size_t c = 2 + 3 * m;
      if (c + 2 >= cells.size() || cells[c].empty()) continue;
      const std::string where = path + ":" + std::to_string(li + 1);
      frame[m] = Eigen::Vector3d(parse_coordinate(cells[c], where), parse_coordinate(cells[c + 1], where),
                                 parse_coordinate(cells[c + 2], where)) * scale;
    }
    t.frames.push_back(std::move(frame));
  }
  if (times_increase(times)) {
    for (double& s : times) s -= times.front();
    t.times_s = std::move(times);
  }
  return t;
}

}  // namespace octocap::internal
