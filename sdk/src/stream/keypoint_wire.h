// One camera's 2D keypoints as a capture node sends them (the IDL's ViewKeypoints), and the checks a hub makes on
// what it receives.
#pragma once
#include <string>
#include <vector>

#include "core/layout.h"
#include "core/person2d.h"
#include "octocap_stream.h"

namespace octocap::internal {

struct RemoteView {
  std::string node, camera;
  uint64_t frame_number = 0;
  int64_t capture_time_us = 0;  // node's wall clock
  int64_t stream_time_us = 0;
  float processing_ms = 0;
  float nominal_fps = 0;
  LayoutId layout = LayoutId::coco17;
  int width = 0, height = 0;
  std::vector<Person2D> people;
};

// Owns what a written sample points into, so that a node writes without allocating once warmed up.
struct ViewKeypointsBuffers {
  std::vector<std::vector<octocap_wire_Keypoint2DSample>> keypoints;
  std::vector<octocap_wire_Person2DSample> people;
  octocap_wire_ViewKeypoints sample{};
};

// Throws Error(invalid_argument) for names beyond 31 bytes or more people or keypoints than the wire holds.
void fill_view_keypoints(const RemoteView& view, ViewKeypointsBuffers& out);
// Checks a received sample (version, known layout, its keypoint count, sizes, finite numbers); false with the reason.
bool read_view_keypoints(const octocap_wire_ViewKeypoints& in, RemoteView& out, std::string& why);

}  // namespace octocap::internal
