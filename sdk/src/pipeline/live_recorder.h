// Records a live take into a folder that `octocap solve` reads again: the calibration, each camera's pictures, the
// 2D keypoints every frame set was solved from (OpenPose JSON) and the capture times. One writer thread behind a
// bounded queue: the live path never waits for the disk. When the writer falls behind, a set's pictures are left
// out (all cameras' together, counted), never its keypoints or times, so the picture folders stay in step.
//
//   DIR/calibration.toml
//   DIR/keypoints/NN_<camera>_json/<camera>_<set:012>_keypoints.json   octocap solve --keypoints DIR/keypoints
//   DIR/images/NN_<camera>/<set:06>.jpg                                 octocap solve --images DIR/images
//   DIR/timestamps.csv   set,time_us,pictures,<camera>_us,...  (capture times, host monotonic µs; empty: absent)
//
// NN is the camera's place in the calibration (01, 02, ...): the readers pair folders with cameras in sorted order.
// A camera absent from a set gets no keypoints (an empty "people") and a black picture: nobody seen, as live.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/person2d.h"

namespace octocap::internal {

struct RecordedSet {
  int64_t time_us = 0;                         // the set's time
  std::vector<int64_t> capture_us;             // per camera; 0: absent from the set
  std::vector<cv::Mat> pictures;               // per camera (BGR, shared); empty: absent or detected on a node
  std::vector<std::vector<Person2D>> people;   // per camera, calibration pixels
};

struct RecorderStats {
  uint64_t sets = 0;              // sets written (keypoints and times)
  uint64_t pictures_dropped = 0;  // sets whose pictures were left out (the writer was behind)
  uint64_t sets_dropped = 0;      // sets left out whole (the disk far behind: no set number is used for them)
};

class LiveRecorder {
 public:
  // Creates the folders and writes the calibration: Error(io) when the folder cannot be made or is not empty of an
  // earlier take (a recording is never mixed into another).
  // `pictures[c]`: camera c gives pixels (a camera detected on a capture node has keypoints only, no images folder).
  LiveRecorder(const std::string& directory, const Calibration& calib, const std::vector<bool>& pictures);
  ~LiveRecorder();  // close()
  LiveRecorder(const LiveRecorder&) = delete;
  LiveRecorder& operator=(const LiveRecorder&) = delete;

  // Queues one set; never blocks on the disk.
  void add(RecordedSet set);
  // Writes what is queued and stops the writer. Idempotent.
  void close();
  RecorderStats stats() const;
  // The first write error, if any (the recording then stops; the live capture goes on).
  std::string error() const;

 private:
  struct Job {
    uint64_t index;
    RecordedSet set;
    bool with_pictures;
  };
  void run();
  void write(const Job& job);

  std::string dir_;
  std::vector<std::string> names_, keypoint_dirs_, image_dirs_;
  std::vector<cv::Size> sizes_;  // each camera's last picture size (first: the calibration's), for absent ones
  std::ofstream times_;
  std::thread thread_;
  mutable std::mutex mutex_;  // guards what follows
  std::condition_variable wake_;
  std::deque<Job> queue_;
  uint64_t next_index_ = 0;
  size_t queued_with_pictures_ = 0;
  bool closing_ = false;
  RecorderStats stats_;
  std::string error_;
};

}  // namespace octocap::internal
