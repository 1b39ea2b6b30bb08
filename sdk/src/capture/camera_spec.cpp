#include "capture/camera_spec.h"

#include <cctype>
#include <filesystem>

#include "core/error.h"

namespace octocap::internal {
namespace fs = std::filesystem;

namespace {

bool all_digits(const std::string& s) {
  if (s.empty() || s.size() > 4) return false;
  for (unsigned char c : s)
    if (!std::isdigit(c)) return false;
  return true;
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

bool valid_remote_name(const std::string& name) {
  return !name.empty() && name.size() <= 31 && name.find('/') == std::string::npos;
}

CameraSpec parse_camera_spec(const std::string& text) {
  CameraSpec spec;
  spec.text = text;
  if (text.empty()) throw Error(Errc::invalid_argument, "a camera spec is empty");
  if (all_digits(text) || (starts_with(text, "/dev/video") && all_digits(text.substr(10)))) {
    spec.kind = SourceKind::device;
    spec.device_index = std::stoi(all_digits(text) ? text : text.substr(10));
    spec.location = "/dev/video" + std::to_string(spec.device_index);
    std::error_code ec;
    if (!fs::exists(spec.location, ec))
      throw Error(Errc::io, "camera '" + text + "': no device " + spec.location);
    return spec;
  }
  const size_t scheme = text.find("://");
  if (scheme != std::string::npos) {
    const std::string s = text.substr(0, scheme);
    if (s == "dds") {
      const std::string rest = text.substr(scheme + 3);
      const size_t slash = rest.find('/');
      spec.kind = SourceKind::remote;
      spec.node = rest.substr(0, slash);
      spec.camera = slash == std::string::npos ? "" : rest.substr(slash + 1);
      if (!valid_remote_name(spec.node) || !valid_remote_name(spec.camera))
        throw Error(Errc::invalid_argument, "camera '" + text + "': a remote camera is dds://NODE/CAMERA (names of 1 to "
                                                "31 bytes, as the node publishes them)");
      spec.location = text;
      return spec;
    }
    if (s != "rtsp" && s != "rtsps" && s != "http" && s != "https")
      throw Error(Errc::invalid_argument, "camera '" + text + "': unknown scheme '" + s +
                                              "://' (rtsp://, rtsps://, http://, https:// are cameras, dds:// a capture node's)");
    spec.kind = SourceKind::network;
    spec.location = text;
    return spec;
  }
  std::error_code ec;
  if (fs::is_directory(text, ec)) {
    spec.kind = SourceKind::picture_folder;
  } else if (fs::is_regular_file(text, ec)) {
    spec.kind = SourceKind::video_file;
  } else {
    throw Error(Errc::io, "camera '" + text + "': no such device, video file or picture folder");
  }
  spec.location = text;
  return spec;
}

}  // namespace octocap::internal
