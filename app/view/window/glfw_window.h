// The viewer's window: GLFW with an OpenGL 4.5 core context (current on this thread;
// the GPU renderer adopts it), its key and mouse events turned into InputState.
#pragma once

#include <string>

#include "app/view/window/input.h"

struct GLFWwindow;

namespace skylit::app::view::window {

class GlfwWindow {
 public:
  // Throws std::runtime_error with one line: no display (pointing to `skylit render`),
  // or no OpenGL 4.5 core context.
  GlfwWindow(int width, int height, const std::string& title, bool vsync);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  // Polls events into input (keys the UI wants are not passed on: ui_wants_keys/mouse).
  void poll(InputState& input, bool ui_wants_keys, bool ui_wants_mouse);
  void swap();
  bool should_close() const;
  void framebuffer_size(int& width, int& height) const;
  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  InputState* input_ = nullptr;  // during poll()
  bool ui_keys_ = false, ui_mouse_ = false;
  bool looking_ = false;
  double last_x_ = 0.0, last_y_ = 0.0;

  static void on_key(GLFWwindow* w, int key, int scancode, int action, int mods);
  static void on_button(GLFWwindow* w, int button, int action, int mods);
  static void on_cursor(GLFWwindow* w, double x, double y);
  static void on_scroll(GLFWwindow* w, double dx, double dy);
};

}  // namespace skylit::app::view::window
