// What the user (or a script) did since the last frame, in GLFW-independent terms: keys
// by name ("w", "space", "f12"), so a --script file and the window feed one path.
#pragma once

#include <glm/vec2.hpp>

#include <set>
#include <string>
#include <vector>

namespace skylit::app::view::window {

struct InputState {
  std::set<std::string> held;        // keys down now
  std::vector<std::string> pressed;  // keys that went down since the last frame, in order
  glm::dvec2 look{0.0};              // mouse-look delta, pixels (right button dragged)
  double wheel = 0.0;                // wheel steps
  bool brush_click = false;          // the left button went down over the terrain
  bool brush_held = false;           // and is still down (a brush stroke)
  glm::dvec2 cursor{0.0};            // window pixels, from the top left

  bool is_held(const std::string& key) const { return held.count(key) != 0; }
  void press(const std::string& key) {
    held.insert(key);
    pressed.push_back(key);
  }
  void release(const std::string& key) { held.erase(key); }
  // What lasts one frame only.
  void end_frame() {
    pressed.clear();
    look = glm::dvec2(0.0);
    wheel = 0.0;
    brush_click = false;
  }
};

}  // namespace skylit::app::view::window
