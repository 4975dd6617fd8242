#include "app/view/window/glfw_window.h"

#include <GLFW/glfw3.h>

#include <stdexcept>

#include "gpu/loaded_objects.h"
#include <string_view>

namespace skylit::app::view::window {
namespace {

std::string last_glfw_error() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "no reason given";
}

// GLFW keys to InputState's names (key_bindings.h).
std::string_view key_name(int key) {
  static thread_local char letter[2] = {0, 0};
  if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) {
    letter[0] = static_cast<char>(key >= GLFW_KEY_A ? 'a' + (key - GLFW_KEY_A) : key);
    return letter;
  }
  switch (key) {
    case GLFW_KEY_SPACE: return "space";
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: return "equal";
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: return "minus";
    case GLFW_KEY_PERIOD: return "period";
    case GLFW_KEY_COMMA: return "comma";
    case GLFW_KEY_LEFT: return "left";
    case GLFW_KEY_RIGHT: return "right";
    case GLFW_KEY_HOME: return "home";
    case GLFW_KEY_END: return "end";
    case GLFW_KEY_F1: return "f1";
    case GLFW_KEY_F12: return "f12";
    case GLFW_KEY_ESCAPE: return "escape";
    case GLFW_KEY_LEFT_SHIFT: case GLFW_KEY_RIGHT_SHIFT: return "shift";
    default: return {};
  }
}

GlfwWindow* owner(GLFWwindow* w) { return static_cast<GlfwWindow*>(glfwGetWindowUserPointer(w)); }

}  // namespace

GlfwWindow::GlfwWindow(int width, int height, const std::string& title, bool vsync) {
  const gpu::LoadedObjects before;  // glfwTerminate would unload the GLX driver
  if (!glfwInit())
    throw std::runtime_error("no display for a window (" + last_glfw_error() +
                             "): `skylit render` draws the same frames without one");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = last_glfw_error();
    glfwTerminate();
    throw std::runtime_error("no OpenGL 4.5 core context for a window (" + why + ")");
  }
  glfwMakeContextCurrent(window_);
  before.keep_the_new_loaded();
  glfwSwapInterval(vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, on_key);
  glfwSetMouseButtonCallback(window_, on_button);
  glfwSetCursorPosCallback(window_, on_cursor);
  glfwSetScrollCallback(window_, on_scroll);
  glfwGetCursorPos(window_, &last_x_, &last_y_);
}

GlfwWindow::~GlfwWindow() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void GlfwWindow::poll(InputState& input, bool ui_wants_keys, bool ui_wants_mouse) {
  input_ = &input;
  ui_keys_ = ui_wants_keys;
  ui_mouse_ = ui_wants_mouse;
  glfwPollEvents();
  input_ = nullptr;
}

void GlfwWindow::swap() { glfwSwapBuffers(window_); }
bool GlfwWindow::should_close() const { return glfwWindowShouldClose(window_); }
void GlfwWindow::framebuffer_size(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }

void GlfwWindow::on_key(GLFWwindow* w, int key, int, int action, int) {
  GlfwWindow* self = owner(w);
  if (!self->input_) return;
  const std::string_view name = key_name(key);
  if (name.empty()) return;
  if (action == GLFW_PRESS && !self->ui_keys_) self->input_->press(std::string(name));
  if (action == GLFW_RELEASE) self->input_->release(std::string(name));
}

void GlfwWindow::on_button(GLFWwindow* w, int button, int action, int) {
  GlfwWindow* self = owner(w);
  if (!self->input_) return;
  if (button == GLFW_MOUSE_BUTTON_RIGHT) self->looking_ = action == GLFW_PRESS && !self->ui_mouse_;
  if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_PRESS && !self->ui_mouse_) {
    self->input_->brush_click = self->input_->brush_held = true;
    self->input_->cursor = {self->last_x_, self->last_y_};
  }
  if (button == GLFW_MOUSE_BUTTON_LEFT && action == GLFW_RELEASE) self->input_->brush_held = false;
}

void GlfwWindow::on_cursor(GLFWwindow* w, double x, double y) {
  GlfwWindow* self = owner(w);
  if (self->input_ && self->looking_) self->input_->look += glm::dvec2(x - self->last_x_, y - self->last_y_);
  self->last_x_ = x;
  self->last_y_ = y;
  if (self->input_) self->input_->cursor = {x, y};
}

void GlfwWindow::on_scroll(GLFWwindow* w, double, double dy) {
  GlfwWindow* self = owner(w);
  if (self->input_ && !self->ui_mouse_) self->input_->wheel += dy;
}

}  // namespace skylit::app::view::window
