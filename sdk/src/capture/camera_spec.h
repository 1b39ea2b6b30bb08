// What a camera argument names: a V4L2 device (/dev/videoN or an index), a network camera (rtsp://, http://), a
// video file or a folder of pictures played as a camera, or a remote camera: dds://NODE/CAMERA, whose 2D keypoints a
// capture node detects and publishes (stream/remote_feed.h).
#pragma once
#include <string>

namespace octocap::internal {

enum class SourceKind : int { device = 0, network = 1, video_file = 2, picture_folder = 3, remote = 4 };

struct CameraSpec {
  std::string text;       // as given, for messages
  SourceKind kind = SourceKind::video_file;
  int device_index = -1;  // device: N of /dev/videoN
  std::string location;   // network: the URL; file / folder: the path
  std::string node, camera;  // remote: the node's and its camera's names
  // Live sources run on their own clock and come back after a drop; files and folders are played at their own
  // rate and end.
  bool live() const { return kind == SourceKind::device || kind == SourceKind::network || kind == SourceKind::remote; }
};

// A name in dds://NODE/CAMERA (a capture node's, or one of its cameras'): 1 to 31 bytes, no '/'.
bool valid_remote_name(const std::string& name);

// Throws Error(invalid_argument) for an empty spec or an unknown URL scheme, Error(io) for a file, folder or device
// that does not exist; the message names the spec.
CameraSpec parse_camera_spec(const std::string& text);

struct SourceOptions {
  int open_timeout_ms = 5000;
  int read_timeout_ms = 3000;
  double picture_rate_hz = 30;  // picture folders have no rate of their own
};

}  // namespace octocap::internal
