#include "rig/motion_writer.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.h"
#include "core/take_timing.h"
#include "rig/bvh_export.h"

namespace octocap::internal {
namespace {
const Eigen::Vector3d kMissing = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
constexpr int64_t kNoTime = std::numeric_limits<int64_t>::min();
constexpr double kFallbackRate = 30;  // rate 0 and no usable timestamps: what TRC writers have always assumed

MarkerFrame blend(const MarkerFrame& a, const MarkerFrame& b, double w) {
  MarkerFrame out(a.size());
  for (size_t m = 0; m < a.size(); ++m) out[m] = (1 - w) * a[m] + w * b[m];  // NaN in either stays NaN
  return out;
}

SkeletonPose blend(const SkeletonPose& a, const SkeletonPose& b, double w) {
  SkeletonPose out;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!a[i].valid || !b[i].valid) continue;  // invalid: the BVH holds the previous rotation
    out[i].local = a[i].local.slerp(w, b[i].local);
    out[i].global = a[i].global.slerp(w, b[i].global);
    out[i].head = (1 - w) * a[i].head + w * b[i].head;
    out[i].length = (1 - w) * a[i].length + w * b[i].length;
    out[i].valid = true;
  }
  return out;
}

}  // namespace

MotionWriter::MotionWriter(std::string path, MotionFormat format, LayoutId layout_id, bool z_up, double rate_hz)
    : path_(std::move(path)), format_(format), layout_(layout_id), z_up_(z_up), rate_hz_(rate_hz) {
  // Above 100 kHz no camera exists, below 1e-3 Hz (a frame every 17 minutes) a TRC reader divides into garbage.
  if (!std::isfinite(rate_hz) || (rate_hz != 0 && (!(rate_hz >= 1e-3) || rate_hz > 1e5)))
    throw Error(Errc::invalid_argument, "rate_hz must be 0 (the frames' timestamps) or between 0.001 and 100000, is " +
                                            std::to_string(rate_hz));
  for (const char* n : layout(layout_id).keypoints) track_.markers.emplace_back(n);
  track_.rate_hz = rate_hz > 0 ? rate_hz : kFallbackRate;
  track_.per_person = format == MotionFormat::csv_people;
}

MotionWriter::~MotionWriter() {
  if (!journal_) return;
  std::error_code ec;
  std::filesystem::remove(journal_->path(), ec);  // written or dropped: the journal has served
}

void MotionWriter::journal_to(const std::string& path) {
  if (!track_.frames.empty()) throw Error(Errc::invalid_argument, "a journal starts before the first frame");
  journal_ = std::make_unique<CsvAppender>(path, track_.markers, track_.per_person);
}

void MotionWriter::journal_last(int64_t person_id) {
  if (!journal_) return;
  const size_t row = track_.frames.size() - 1;
  const int64_t first = stamps_us_.front(), stamp = stamps_us_.back();
  // Seconds from the first frame, as the CSV will say; frames without a time at the nominal rate.
  const double t = stamp != kNoTime && first != kNoTime ? static_cast<double>(stamp - first) * 1e-6
                                                        : static_cast<double>(row) / track_.rate_hz;
  const int64_t frame = track_.per_person ? track_.rows.back().first : static_cast<int64_t>(row);
  journal_->append(frame, t, person_id, track_.frames.back());
}

std::vector<double> MotionWriter::times() const {
  std::vector<double> t;
  if (stamps_us_.empty() || std::find(stamps_us_.begin(), stamps_us_.end(), kNoTime) != stamps_us_.end()) return t;
  for (int64_t s : stamps_us_) t.push_back(static_cast<double>(s - stamps_us_.front()) * 1e-6);
  // Several people share a frame's time in a per-person CSV: there the times need only not go back.
  if (track_.per_person) return std::is_sorted(t.begin(), t.end()) ? t : std::vector<double>{};
  return times_increase(t) ? t : std::vector<double>{};
}

double MotionWriter::output_rate() const {
  if (rate_hz_ > 0) return rate_hz_;
  const double measured = track_.per_person ? 0 : mean_rate(times());
  return measured >= 1e-3 && measured <= 1e5 ? measured : kFallbackRate;
}

bool MotionWriter::resampled() const {
  if (track_.per_person) return false;
  const std::vector<double> t = times();
  return t.size() >= 2 && !evenly_spaced(t, output_rate());
}

void MotionWriter::add(const FrameResult& frame, size_t person) {
  if (frame.layout != layout_ && frame.keypoint_count() != 0)
    throw Error(Errc::invalid_argument, std::string("the frame's layout (") + layout(frame.layout).name + ") is not the writer's (" +
                                            layout(layout_).name + ")");
  if (person >= frame.person_count()) return add_empty(frame.info.timestamp_us);
  add_person(frame.people[person], frame.info.frame_index, frame.info.timestamp_us);
}

void MotionWriter::add_person(const PersonResult& person, int64_t frame_index, int64_t timestamp_us) {
  if (track_.per_person) track_.rows.emplace_back(frame_index, person.id);
  stamps_us_.push_back(timestamp_us);
  MarkerFrame f;
  for (const PointResult& k : person.keypoints) f.push_back(k.valid ? k.position : kMissing);
  f.resize(track_.markers.size(), kMissing);
  track_.frames.push_back(std::move(f));
  if (format_ == MotionFormat::bvh) poses_.push_back(person.bones);  // 1.7 KB a frame: only a BVH needs them
  journal_last(person.id);
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
  stamps_us_.push_back(kNoTime);
  journal_last(-1);
}

void MotionWriter::add_empty() { add_empty(kNoTime); }

void MotionWriter::add_empty(int64_t timestamp_us) {
  if (track_.per_person) return;  // a frame without the person is no row
  track_.frames.emplace_back(track_.markers.size(), kMissing);
  if (format_ == MotionFormat::bvh) poses_.emplace_back();  // all bones invalid: the BVH keeps the previous pose
  stamps_us_.push_back(timestamp_us);
  journal_last(-1);
}

void MotionWriter::close() const {
  MotionTrack track = track_;
  std::vector<SkeletonPose> poses = poses_;
  track.rate_hz = output_rate();
  track.times_s = times();
  if (format_ != MotionFormat::csv && format_ != MotionFormat::csv_people && resampled()) {
    // Row k of a TRC or BVH is at k / rate: frames that came unevenly are interpolated onto that grid.
    const std::vector<Resampled> plan = resample_plan(track.times_s, track.rate_hz, max_interpolated_gap_s(track.rate_hz));
    track.frames.clear();
    poses.clear();
    for (const Resampled& r : plan) {
      if (r.gap) {
        track.frames.emplace_back(track.markers.size(), kMissing);
        poses.emplace_back();
        continue;
      }
      track.frames.push_back(blend(track_.frames[r.before], track_.frames[r.after], r.weight));
      if (format_ == MotionFormat::bvh) poses.push_back(blend(poses_[r.before], poses_[r.after], r.weight));
    }
    track.times_s.clear();  // k / rate
  }
  if (format_ == MotionFormat::trc)
    write_trc(path_, track, z_up_);
  else if (format_ == MotionFormat::bvh)
    write_bvh(path_, poses, track.rate_hz);
  else
    write_csv(path_, track);
  if (journal_) {
    std::error_code ec;
    std::filesystem::remove(journal_->path(), ec);
  }
}

}  // namespace octocap::internal
