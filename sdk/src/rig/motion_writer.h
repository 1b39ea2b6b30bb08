// A take written to disk frame by frame: TRC / CSV of the layout keypoints, or BVH of the bone animation.
// Nothing is written until close() (TRC's header needs the frame count); a failed take is simply dropped. A journal
// (journal_to) keeps a take whose process dies: every frame appended to a CSV as it is added, removed once the file
// is written or the take dropped.
// Time: every frame keeps its timestamp. The CSV says when each frame happened; TRC and BVH rows are 1 / rate apart,
// so a take whose frames are not (a live take's sets) is resampled to the rate: the one given, or with rate 0 the
// take's mean rate. Frames without increasing timestamps are taken to be 1 / rate apart.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/frame.h"
#include "core/layout.h"
#include "io/motion_files.h"

namespace octocap::internal {

enum class MotionFormat : int { trc = 0, csv = 1, bvh = 2, csv_people = 3 };

class MotionWriter {
 public:
  // Throws Error(invalid_argument) for a rate that is not 0 (the frames' timestamps say) or a positive, finite, sane
  // frame rate.
  MotionWriter(std::string path, MotionFormat format, LayoutId layout, bool z_up, double rate_hz);
  ~MotionWriter();
  MotionWriter(MotionWriter&&) = default;
  MotionWriter& operator=(MotionWriter&&) = default;
  // Before the first frame: each frame is also appended to `path`, a CSV of the layout keypoints with their times
  // (io/motion_files.h, flushed per frame), deleted by close() once the file is written, and by the destructor.
  // Throws Error(io) when it cannot be made, Error(invalid_argument) after the first frame.
  void journal_to(const std::string& path);
  // The person's keypoints (and bones); a frame without that person is an empty frame (csv_people: no row).
  // Throws when the frame's layout is not the writer's.
  void add(const FrameResult& frame, size_t person);
  // Layout keypoints given directly (NaN where missing); not for BVH.
  void add_keypoints(const std::vector<Eigen::Vector3d>& keypoints);
  // A frame without the person; at `timestamp_us`, or with no time (the take is then taken as evenly spaced).
  void add_empty();
  void add_empty(int64_t timestamp_us);
  void close() const;
  // The rate TRC and BVH are written at (the given one, else the frames' mean), and whether they are resampled to it.
  double output_rate() const;
  bool resampled() const;
  MotionFormat format() const { return format_; }
  size_t keypoint_count() const { return track_.markers.size(); }

 private:
  void add_person(const PersonResult& person, int64_t frame_index, int64_t timestamp_us);
  void journal_last(int64_t person_id);
  // Seconds from the first frame, when every frame has a timestamp and they increase; else empty.
  std::vector<double> times() const;

  std::string path_;
  MotionFormat format_;
  LayoutId layout_;
  bool z_up_;
  double rate_hz_;  // 0: the frames' mean
  MotionTrack track_;
  std::vector<SkeletonPose> poses_;  // BVH only (per frame, as track_.frames)
  std::vector<int64_t> stamps_us_;   // per frame (row); kNoTime where none was given
  std::unique_ptr<CsvAppender> journal_;
};

}  // namespace octocap::internal
