#include "window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <stdexcept>

namespace {

void* glfw_proc(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

struct Input {
  WindowView view;
  int frame_count = 1;
  bool dragging = false;
  double last_x = 0, last_y = 0;
};

}  // namespace

void run_window(const std::string& title, int width, int height, int frame_count, double rate_hz, int max_frames_shown,
                const std::function<void(const GlApi&)>& init, const std::function<void()>& release,
                const std::function<void(const WindowView&, int, int)>& draw) {
  if (!glfwInit()) throw std::runtime_error("GLFW could not start (no display? run under xvfb-run -a)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("GLFW could not open a window with an OpenGL 3.3 core context");
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  Input input;
  input.frame_count = std::max(1, frame_count);
  glfwSetWindowUserPointer(window, &input);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) glfwSetWindowShouldClose(w, GLFW_TRUE);
    if (key == GLFW_KEY_SPACE) in->view.playing = !in->view.playing;
    if (key == GLFW_KEY_RIGHT) in->view.frame = (in->view.frame + 1) % in->frame_count;
    if (key == GLFW_KEY_LEFT) in->view.frame = (in->view.frame + in->frame_count - 1) % in->frame_count;
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
    if (button == GLFW_MOUSE_BUTTON_LEFT) in->dragging = action == GLFW_PRESS;
    glfwGetCursorPos(w, &in->last_x, &in->last_y);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
    if (in->dragging) {
      in->view.yaw -= static_cast<float>(x - in->last_x) * 0.01f;
      in->view.pitch = std::clamp(in->view.pitch + static_cast<float>(y - in->last_y) * 0.01f, -1.4f, 1.4f);
    }
    in->last_x = x, in->last_y = y;
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    auto* in = static_cast<Input*>(glfwGetWindowUserPointer(w));
    in->view.distance = std::clamp(in->view.distance * (dy > 0 ? 0.9f : 1.1f), 0.5f, 30.0f);
  });
  GlApi gl{};
  try {
    load_gl(gl, glfw_proc);
    init(gl);
    double next = glfwGetTime();
    int shown = 0;
    while (!glfwWindowShouldClose(window) && (max_frames_shown <= 0 || shown < max_frames_shown)) {
      int w = 0, h = 0;
      glfwGetFramebufferSize(window, &w, &h);
      draw(input.view, w, h);
      glfwSwapBuffers(window);
      glfwPollEvents();
      ++shown;
      if (input.view.playing && glfwGetTime() >= next) {
        input.view.frame = (input.view.frame + 1) % input.frame_count;
        next += 1.0 / rate_hz;
      }
    }
  } catch (...) {
    release();
    glfwDestroyWindow(window);
    glfwTerminate();
    throw;
  }
  release();  // GL objects go while their context is still current
  glfwDestroyWindow(window);
  glfwTerminate();
}
