#include "rig/motion_writer.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "rig/bvh_export.h"

namespace octocap {
namespace {
const Eigen::Vector3d kMissing = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
}

MotionWriter::MotionWriter(std::string path, MotionFormat format, LayoutId layout_id, bool z_up, double rate_hz)
    : path_(std::move(path)), format_(format), layout_(layout_id), z_up_(z_up) {
  // Above 100 kHz no camera exists, below 1e-3 Hz (a frame every 17 minutes) a TRC reader divides into garbage.
  if (!std::isfinite(rate_hz) || !(rate_hz >= 1e-3) || rate_hz > 1e5)
    throw Error(Errc::invalid_argument, "rate_hz must be between 0.001 and 100000, is " + std::to_string(rate_hz));
  for (const char* n : layout(layout_id).keypoints) track_.markers.emplace_back(n);
  track_.rate_hz = rate_hz;
  track_.per_person = format == MotionFormat::csv_people;
}

void MotionWriter::add(const FrameResult& frame, size_t person) {
  if (frame.layout != layout_ && frame.keypoint_count() != 0)
    throw Error(Errc::invalid_argument, std::string("the frame's layout (") + layout(frame.layout).name + ") is not the writer's (" +
                                            layout(layout_).name + ")");
  if (person >= frame.person_count()) return add_empty();
  add_person(frame.people[person], frame.info.frame_index);
}

void MotionWriter::add_person(const PersonResult& person, int64_t frame_index) {
  if (track_.per_person) track_.rows.emplace_back(frame_index, person.id);
  MarkerFrame f;
  for (const PointResult& k : person.keypoints) f.push_back(k.valid ? k.position : kMissing);
  f.resize(track_.markers.size(), kMissing);
  track_.frames.push_back(std::move(f));
  poses_.push_back(person.bones);
}

void MotionWriter::add_keypoints(const std::vector<Eigen::Vector3d>& keypoints) {
  if (format_ == MotionFormat::bvh)
    throw Error(Errc::unsupported, "a BVH holds bone rotations: add frames (octocap_motion_writer_add)");
  if (format_ == MotionFormat::csv_people)
    throw Error(Errc::unsupported, "a per-person CSV needs each row's frame and person: add frames (octocap_motion_writer_add)");
  if (keypoints.size() != track_.markers.size())
    throw Error(Errc::invalid_argument, "got " + std::to_string(keypoints.size()) + " keypoints, the writer's layout has " +
                                            std::to_string(track_.markers.size()));
  MarkerFrame f;
  for (const Eigen::Vector3d& p : keypoints) f.push_back(p.allFinite() ? p : kMissing);
  track_.frames.push_back(std::move(f));
}

void MotionWriter::add_empty() {
  if (track_.per_person) return;  // a frame without the person is no row
  track_.frames.emplace_back(track_.markers.size(), kMissing);
  poses_.emplace_back();  // all bones invalid: the BVH keeps the previous pose
}

void MotionWriter::close() const {
  if (format_ == MotionFormat::trc)
    write_trc(path_, track_, z_up_);
  else if (format_ == MotionFormat::bvh)
    write_bvh(path_, poses_, track_.rate_hz);
  else
    write_csv(path_, track_);
}

}  // namespace octocap
