// What the opaque C handles hold: every handle struct is defined here, once.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "capi/boundary.h"
#include "capture/take_reader.h"
#include "core/camera.h"
#include "core/frame.h"
#include "detect/detector.h"
#include "io/openpose_json.h"
#include "octocap/octocap.h"
#include "pipeline/live_engine.h"
#ifdef OCTOCAP_HAVE_DDS
#include "pipeline/keypoint_node.h"
#endif
#include "pipeline/session.h"
#include "rig/motion_take.h"
#include "rig/motion_writer.h"
#ifdef OCTOCAP_HAVE_DDS
#include "stream/dds_subscriber.h"
#endif

struct octocap_calibration_t {
  octocap::internal::Calibration cameras;
};

struct octocap_session_t {
  std::unique_ptr<octocap::internal::Session> session;
};

// A frame is an immutable snapshot shared by every handle made from it (a session's frame is copied once per
// octocap_session_get_frame, never while a caller reads it).
struct octocap_frame_t {
  std::shared_ptr<const octocap::internal::FrameResult> frame;
};

struct octocap_detector_t {
  explicit octocap_detector_t(std::unique_ptr<octocap::internal::Detector> d) : detector(std::move(d)) {}
  std::unique_ptr<octocap::internal::Detector> detector;
  std::vector<std::vector<octocap::internal::DetectedPerson>> people;  // last run, image pixels
};

struct octocap_recording_t {
  std::unique_ptr<octocap::internal::OpenPoseRecording> recording;
};

struct octocap_motion_writer_t {
  std::unique_ptr<octocap::internal::MotionWriter> writer;
};

struct octocap_motion_t {
  octocap::internal::MotionTake take;
};

struct octocap_live_t {
  std::unique_ptr<octocap::internal::LiveEngine> engine;
};

struct octocap_take_reader_t {
  std::unique_ptr<octocap::internal::TakeReader> reader;
};

struct octocap_node_t {
#ifdef OCTOCAP_HAVE_DDS
  std::unique_ptr<octocap::internal::KeypointNode> node;
#endif
};

struct octocap_subscriber_t {
#ifdef OCTOCAP_HAVE_DDS
  std::unique_ptr<octocap::internal::DdsSubscriber> subscriber;
#endif
};

namespace octocap::internal::capi {

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

// A new frame handle over a snapshot.
octocap_frame_t* make_frame(std::shared_ptr<const FrameResult> frame);

}  // namespace octocap::internal::capi
