#include "io/bvh.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace octocap::internal {
namespace {

class Tokens {
 public:
  Tokens(std::istream& in, std::string path) : in_(in), path_(std::move(path)) {}
  std::string next() {
    std::string t;
    if (!(in_ >> t)) fail("unexpected end of file");
    return t;
  }
  double number() {
    const std::string t = next();
    try {
      size_t used = 0;
      const double v = std::stod(t, &used);
      if (used != t.size() || !std::isfinite(v)) throw std::invalid_argument(t);
      return v;
    } catch (const std::exception&) {
      fail("expected a number, found '" + t + "'");
    }
  }
  void expect(const std::string& word) {
    const std::string t = next();
    if (t != word) fail("expected '" + word + "', found '" + t + "'");
  }
  [[noreturn]] void fail(const std::string& what) { throw Error(Errc::parse, path_ + ": " + what); }

 private:
  std::istream& in_;
  std::string path_;
};

int channel_code(const std::string& c, Tokens& tok) {
  static const char* names[] = {"Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};
  for (int i = 0; i < 6; ++i)
    if (c == names[i]) return i;
  tok.fail("unknown channel '" + c + "'");
}

// Real skeletons are a few dozen joints, a dozen deep; the caps turn a hostile file into a parse error, not a
// stack overflow or an allocation of gigabytes.
constexpr int kMaxDepth = 256;
constexpr size_t kMaxJoints = 10000;
constexpr double kMaxFrames = 1e7;  // 23 hours at 120 Hz

void parse_joint(Tokens& tok, BvhMotion& m, int parent, const std::string& name, int& channel_count, int depth) {
  if (depth > kMaxDepth) tok.fail("joints nested deeper than " + std::to_string(kMaxDepth));
  if (m.joints.size() >= kMaxJoints) tok.fail("more than " + std::to_string(kMaxJoints) + " joints");
  BvhJoint j;
  j.name = name;
  j.parent = parent;
  tok.expect("{");
  tok.expect("OFFSET");
  for (int k = 0; k < 3; ++k) j.offset[k] = tok.number();
  tok.expect("CHANNELS");
  const double n = tok.number();
  if (n < 0 || n > 6 || n != std::floor(n)) tok.fail("CHANNELS count must be 0..6");
  j.first_channel = channel_count;
  for (int c = 0; c < static_cast<int>(n); ++c) j.channels.push_back(channel_code(tok.next(), tok));
  channel_count += static_cast<int>(n);
  const int index = static_cast<int>(m.joints.size());
  m.joints.push_back(j);
  for (;;) {
    const std::string t = tok.next();
    if (t == "}") return;
    if (t == "JOINT") {
      const std::string child = tok.next();
      parse_joint(tok, m, index, child, channel_count, depth + 1);
    } else if (t == "End") {
      tok.expect("Site");
      tok.expect("{");
      tok.expect("OFFSET");
      BvhJoint e;
      e.name = name + "_end";
      e.parent = index;
      e.end_site = true;
      for (int k = 0; k < 3; ++k) e.offset[k] = tok.number();
      tok.expect("}");
      m.joints.push_back(e);
    } else {
      tok.fail("unexpected '" + t + "' in joint " + name);
    }
  }
}

}  // namespace

int BvhMotion::find(const std::string& name) const {
  for (size_t i = 0; i < joints.size(); ++i)
    if (joints[i].name == name) return static_cast<int>(i);
  return -1;
}

void BvhMotion::pose(size_t frame, std::vector<Eigen::Vector3d>& positions,
                     std::vector<Eigen::Matrix3d>& rotations) const {
  const std::vector<double>& row = frames.at(frame);
  positions.resize(joints.size());
  rotations.resize(joints.size());
  for (size_t i = 0; i < joints.size(); ++i) {
    const BvhJoint& j = joints[i];
    Eigen::Vector3d translation = j.offset;
    Eigen::Matrix3d local = Eigen::Matrix3d::Identity();
    for (size_t c = 0; c < j.channels.size(); ++c) {
      const double v = row[j.first_channel + c];
      const int code = j.channels[c];
      if (code < 3) {
        translation[code] = v;  // root position channels replace the offset
      } else {
        local = local * Eigen::AngleAxisd(v * M_PI / 180.0, Eigen::Vector3d::Unit(code - 3)).toRotationMatrix();
      }
    }
    if (j.parent < 0) {
      positions[i] = translation;
      rotations[i] = local;
    } else {
      positions[i] = positions[j.parent] + rotations[j.parent] * translation;
      rotations[i] = rotations[j.parent] * local;
    }
  }
}

BvhMotion read_bvh(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(Errc::io, path + ": cannot open BVH file");
  Tokens tok(in, path);
  BvhMotion m;
  tok.expect("HIERARCHY");
  tok.expect("ROOT");
  int channels = 0;
  const std::string root = tok.next();
  parse_joint(tok, m, -1, root, channels, 0);
  tok.expect("MOTION");
  tok.expect("Frames:");
  const double n = tok.number();
  if (n < 1 || n > kMaxFrames || n != std::floor(n))
    tok.fail("Frames: must be a whole number from 1 to " + std::to_string(static_cast<long>(kMaxFrames)));
  tok.expect("Frame");
  tok.expect("Time:");
  m.frame_time = tok.number();
  if (!(m.frame_time > 0)) tok.fail("Frame Time must be > 0");
  // Grown as the data is read, so a header that claims more frames than the file holds fails at its end instead
  // of allocating them first.
  const size_t count = static_cast<size_t>(n);
  m.frames.reserve(std::min<size_t>(count, 4096));
  for (size_t f = 0; f < count; ++f) {
    std::vector<double> row(static_cast<size_t>(channels));
    for (auto& v : row) v = tok.number();
    m.frames.push_back(std::move(row));
  }
  return m;
}

}  // namespace octocap::internal
