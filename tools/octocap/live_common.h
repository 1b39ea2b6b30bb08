// What the live commands (octocap live, octocap detect --live) share: Ctrl-C handling, warnings on stderr, camera
// state names.
#pragma once
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "octocap/octocap.h"

namespace live_common {

inline std::atomic<bool>& interrupted() {
  static std::atomic<bool> flag{false};
  return flag;
}

extern "C" inline void on_interrupt(int) { interrupted() = true; }

// Ctrl-C and SIGTERM end the run cleanly (files closed, the table printed).
inline void catch_interrupts() {
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
}

inline void log_to_stderr(octocap_log_level_t level, const char* message, void*) {
  static const char* names[] = {"debug", "info", "warning", "error"};
  std::fprintf(stderr, "\noctocap %s: %s\n", names[level], message);
}

// Camera specs with ${NAME} replaced by the environment's NAME: a password given as
// --camera 'rtsp://admin:${CAM1_PASSWORD}@host/x' never shows in `ps` (single quotes keep the shell from expanding
// it first). An unset NAME is an error naming it, never an empty password sent to the camera.
inline std::vector<std::string> expand_camera_secrets(std::vector<std::string> cameras) {
  for (size_t c = 0; c < cameras.size(); ++c) {
    std::string& spec = cameras[c];
    for (size_t at = spec.find("${"); at != std::string::npos; at = spec.find("${", at)) {
      const size_t close = spec.find('}', at + 2);
      if (close == std::string::npos) break;
      const std::string name = spec.substr(at + 2, close - at - 2);
      const char* value = std::getenv(name.c_str());
      if (name.empty() || !value)
        throw std::runtime_error("camera " + std::to_string(c + 1) + " (" + octocap_redact_credentials(spec.c_str()) +
                                 ") names ${" + name + "}, which the environment does not set");
      spec.replace(at, close + 1 - at, value);
      at += std::string(value).size();
    }
  }
  return cameras;
}

inline const char* state_name(octocap_camera_state_t s) {
  static const char* names[] = {"stopped", "connecting", "streaming", "reconnecting", "ended", "failed"};
  return s >= 0 && s <= 5 ? names[s] : "?";
}

// The status line's end: each camera's name and rate, and whether it is reconnecting (octocap::Live or ::Node).
template <class Capture>
void print_camera_rates(const Capture& capture, uint32_t cameras) {
  for (uint32_t c = 0; c < cameras; ++c) {
    const octocap_camera_status_t cam = capture.camera(c);
    std::fprintf(stderr, " %s %.0f fps%s", cam.name, cam.fps,
                 cam.state == OCTOCAP_CAMERA_RECONNECTING ? " (reconnecting)" : "");
  }
  std::fprintf(stderr, "   ");
}

}  // namespace live_common
