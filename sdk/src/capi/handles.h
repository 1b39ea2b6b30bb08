// What the opaque C handles hold.
#pragma once
#include <memory>
#include <string>

#include "core/camera.h"
#include "io/motion_files.h"
#include "io/openpose_json.h"
#include "octocap/octocap.h"
#include "pipeline/session.h"
#include "detect/detector.h"

struct octocap_calibration_t {
  octocap::Calibration cameras;
};

struct octocap_session_t {
  std::unique_ptr<octocap::Session> session;
  uint32_t definition_counter = 1;
};

struct octocap_detector_t {
  explicit octocap_detector_t(std::unique_ptr<octocap::Detector> d) : detector(std::move(d)) {}
  std::unique_ptr<octocap::Detector> detector;
  std::vector<std::vector<octocap::DetectedPerson>> people;  // last run, image pixels
};

struct octocap_recording_t {
  std::unique_ptr<octocap::OpenPoseRecording> recording;
};

struct octocap_motion_writer_t {
  std::string path;
  octocap_motion_format_t format = OCTOCAP_MOTION_TRC;
  bool z_up = false;
  octocap::MotionTrack track;
  std::vector<octocap::SkeletonPose> poses;  // BVH
};

namespace octocap::capi {

// Creates a handle and registers it; the pair of destroy() below unregisters and frees it.
template <class H, class... Args>
H* make_handle(Args&&... args) {
  H* h = new H{std::forward<Args>(args)...};
  Registry<H>::instance().add(h);
  return h;
}

template <class H>
void destroy_handle(H* h) {
  if (h && Registry<H>::instance().remove(h)) delete h;
}

}  // namespace octocap::capi
