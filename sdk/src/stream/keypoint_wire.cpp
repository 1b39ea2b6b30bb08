#include "stream/keypoint_wire.h"

#include <cmath>
#include <cstring>

#include "core/error.h"

namespace octocap::internal {
namespace {

constexpr size_t kViewPeopleBound = 64, kPersonKeypointsBound = 160, kNameBytes = 31;

void copy_name(const std::string& from, char* to, const char* what) {
  if (from.empty() || from.size() > kNameBytes)
    throw Error(Errc::invalid_argument, std::string(what) + " '" + from + "': 1 to 31 bytes");
  std::memcpy(to, from.c_str(), from.size() + 1);
}

}  // namespace

void fill_view_keypoints(const RemoteView& v, ViewKeypointsBuffers& out) {
  if (v.people.size() > kViewPeopleBound) throw Error(Errc::invalid_argument, "more than 64 people in one view");
  octocap_wire_ViewKeypoints& s = out.sample;
  copy_name(v.node, s.node, "node name");
  copy_name(v.camera, s.camera, "camera name");
  s.version = octocap_wire_KEYPOINTS_VERSION;
  s.frame_number = v.frame_number;
  s.capture_time_us = v.capture_time_us;
  s.stream_time_us = v.stream_time_us;
  s.processing_ms = v.processing_ms;
  s.nominal_fps = v.nominal_fps;
  s.layout = static_cast<int32_t>(v.layout);
  s.width = static_cast<uint32_t>(v.width);
  s.height = static_cast<uint32_t>(v.height);
  out.keypoints.resize(v.people.size());
  out.people.resize(v.people.size());
  for (size_t p = 0; p < v.people.size(); ++p) {
    const Person2D& person = v.people[p];
    if (person.size() > kPersonKeypointsBound) throw Error(Errc::invalid_argument, "more than 160 keypoints per person");
    out.keypoints[p].resize(person.size());
    for (size_t k = 0; k < person.size(); ++k)
      out.keypoints[p][k] = {static_cast<float>(person[k].x), static_cast<float>(person[k].y),
                             static_cast<float>(person[k].confidence)};
    out.people[p].keypoints._buffer = out.keypoints[p].data();
    out.people[p].keypoints._length = out.people[p].keypoints._maximum = static_cast<uint32_t>(person.size());
    out.people[p].keypoints._release = false;
  }
  s.people._buffer = out.people.data();
  s.people._length = s.people._maximum = static_cast<uint32_t>(out.people.size());
  s.people._release = false;
}

bool read_view_keypoints(const octocap_wire_ViewKeypoints& in, RemoteView& out, std::string& why) {
  if (in.version != octocap_wire_KEYPOINTS_VERSION) {
    why = "keypoints version " + std::to_string(in.version) + ", this build reads " +
          std::to_string(octocap_wire_KEYPOINTS_VERSION);
    return false;
  }
  bool known = false;
  for (LayoutId l : all_layouts()) known = known || static_cast<int32_t>(l) == in.layout;
  if (!known || in.layout == static_cast<int32_t>(LayoutId::automatic)) {
    why = "unknown layout " + std::to_string(in.layout);
    return false;
  }
  out.layout = static_cast<LayoutId>(in.layout);
  const size_t count = layout(out.layout).keypoints.size();
  if (in.width == 0 || in.height == 0 || in.width > 100000 || in.height > 100000) {
    why = "picture size " + std::to_string(in.width) + "x" + std::to_string(in.height);
    return false;
  }
  if (!std::isfinite(in.processing_ms) || !std::isfinite(in.nominal_fps)) {
    why = "a time that is not a number";
    return false;
  }
  out.node.assign(in.node, strnlen(in.node, sizeof in.node));
  out.camera.assign(in.camera, strnlen(in.camera, sizeof in.camera));
  out.frame_number = in.frame_number;
  out.capture_time_us = in.capture_time_us;
  out.stream_time_us = in.stream_time_us;
  out.processing_ms = in.processing_ms;
  out.nominal_fps = in.nominal_fps;
  out.width = static_cast<int>(in.width);
  out.height = static_cast<int>(in.height);
  out.people.assign(in.people._length, Person2D{});
  for (uint32_t p = 0; p < in.people._length; ++p) {
    const auto& kps = in.people._buffer[p].keypoints;
    if (kps._length != count) {
      why = "a person with " + std::to_string(kps._length) + " keypoints, the layout has " + std::to_string(count);
      return false;
    }
    Person2D& person = out.people[p];
    person.resize(count);
    for (uint32_t k = 0; k < count; ++k) {
      const octocap_wire_Keypoint2DSample& s = kps._buffer[k];
      if (!std::isfinite(s.x) || !std::isfinite(s.y) || !std::isfinite(s.confidence) || s.confidence < 0 ||
          s.confidence > 1) {
        why = "a keypoint that is not a finite position with a confidence in [0, 1]";
        return false;
      }
      person[k] = {s.x, s.y, s.confidence};
    }
  }
  return true;
}

}  // namespace octocap::internal
