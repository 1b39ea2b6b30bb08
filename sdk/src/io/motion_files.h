// 3D keypoint tracks on disk: TRC (OpenSim / Pose2Sim) and CSV.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace octocap::internal {

// One frame: a position per marker; NaN where the marker was not solved.
using MarkerFrame = std::vector<Eigen::Vector3d>;

struct MotionTrack {
  std::vector<std::string> markers;
  std::vector<MarkerFrame> frames;
  double rate_hz = 30.0;
  // A take of several people: each row is one person in one frame, (frame number, person id) per row.
  bool per_person = false;
  std::vector<std::pair<int64_t, uint32_t>> rows;
  // When each frame (row) happened, seconds from the take's start; empty: frame f at f / rate_hz.
  std::vector<double> times_s;
  double time_of(size_t f) const { return f < times_s.size() ? times_s[f] : static_cast<double>(f) / rate_hz; }
};

// TRC as OpenSim reads it (Y up, metres). When `z_up` the positions are turned (x, y, z) -> (y, z, x),
// Pose2Sim's zup2yup, so a Z-up lab world stands upright in OpenSim.
void write_trc(const std::string& path, const MotionTrack& track, bool z_up);
// `frame,time,NAME_x,NAME_y,NAME_z,...`, positions as given (the calibration's world), empty cells when missing,
// time in seconds from the take's start; `frame,time,person,NAME_x,...` for a per-person track (one row per person
// and frame).
void write_csv(const std::string& path, const MotionTrack& track);
// The same CSV written a row at a time and flushed with each, for a take whose process may die before it ends.
class CsvAppender {
 public:
  // Throws Error(io) when the file cannot be made.
  CsvAppender(std::string path, const std::vector<std::string>& markers, bool per_person);
  // `person` is written only for a per-person CSV.
  void append(int64_t frame, double time_s, int64_t person, const MarkerFrame& points);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool per_person_;
  std::ofstream out_;
};

// Reads what write_csv writes, and the CSVs of before 1.6 (no time column: frames at rate_hz, 30 unless given).
// A per-person CSV comes back per_person with its rows. Throws Error(io / parse) naming the file and line.
MotionTrack read_csv(const std::string& path, double rate_hz = 30);
// Reads a TRC (positions as stored in the file; mm files are converted to metres).
MotionTrack read_trc(const std::string& path);

// One coordinate cell of a motion file: a finite number within a million units (metres, or the file's mm), as a
// whole cell. Throws Error(parse) naming `where` otherwise: beyond that no capture volume exists, and the float
// conversions downstream would turn it into infinity.
double parse_coordinate(const std::string& cell, const std::string& where);

// A file's frame rate: finite, 0.001 .. 100000 Hz. Throws Error(parse) naming `where` otherwise.
double parse_rate(const std::string& cell, const std::string& where);

}  // namespace octocap::internal
