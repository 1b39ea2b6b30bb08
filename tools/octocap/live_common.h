// What the live commands (octocap live, octocap detect --live) share: Ctrl-C handling, warnings on stderr, camera
// state names.
#pragma once
#include <atomic>
#include <csignal>
#include <cstdio>

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
