// An interactive GLFW window: orbit with the left mouse button, zoom with the wheel, space to pause, arrows to
// step, Esc to quit. Needs an X server (run under `xvfb-run -a` without a display).
#pragma once
#include <functional>
#include <string>

#include "gl_api.h"
#include "renderer.h"

struct WindowView {
  float yaw = 0, pitch = 0.25f, distance = 4.0f;
  bool playing = true;
  int frame = 0;
};

// Opens the window, calls `init` once the context is current, `draw` every refresh, `release` before the
// context goes; calls `draw(view, camera)` every refresh and advances frames at `rate_hz` while playing.
// `max_frames_shown` > 0 closes the window after that many frames (for tests). Throws std::runtime_error when no
// window or OpenGL 3.3 context can be made.
void run_window(const std::string& title, int width, int height, int frame_count, double rate_hz, int max_frames_shown,
                const std::function<void(const GlApi&)>& init, const std::function<void()>& release,
                const std::function<void(const WindowView&, int width, int height)>& draw);
