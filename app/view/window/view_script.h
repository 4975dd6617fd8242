// `skylit-view --script FILE`: a timeline of input events by frame number, so a window
// under Xvfb replays the same frames every run (the viewer then steps a fixed 1/fps of
// wall time per frame). One event per line, '#' starts a comment:
//   FRAME press KEY           the key goes down and up (its action, once)
//   FRAME hold KEY FRAMES     the key is held for FRAMES frames (w a s d q e shift)
//   FRAME look DX DY          a mouse-look drag of DX, DY pixels (right button)
//   FRAME wheel STEPS         wheel steps (+: closer, or faster in free mode)
//   FRAME click X Y           a left click at window pixel (X, Y) from the top left
//                             (the terrain brush, when one is chosen: key b)
//   FRAME drag X0 Y0 X1 Y1 FRAMES   the left button down at (X0, Y0), moved evenly to
//                             (X1, Y1) over FRAMES frames, released after the last
//   FRAME scrub TIME          the clock jumps to TIME (ISO 8601 with a zone)
//   FRAME screenshot FILE     saves the frame (PNG) at the panel's screenshot scale
//   FRAME windowshot FILE     saves the window as shown, with the panel (PNG)
//   FRAME pose X Y Z HEADING PITCH   the free camera's eye (field frame, metres) and
//                             view (degrees clockwise from north; degrees up, |.| <= 89)
//   FRAME quit                ends the run after this frame
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "app/view/window/input.h"

namespace skylit::app::view::window {

struct ScriptEvent {
  enum class Verb { Press, Hold, Look, Wheel, Click, Drag, Scrub, Screenshot, WindowShot, Pose, Quit } verb;
  int frame = 0;
  std::string key;          // press, hold
  int frames = 0;           // hold, drag
  double dx = 0, dy = 0;    // look, click, drag's start; dx: wheel steps
  double to_x = 0, to_y = 0;  // drag's end
  double unix_seconds = 0;  // scrub
  std::string path;         // screenshot, windowshot
  glm::dvec3 eye{0.0};      // pose
  double heading_deg = 0, pitch_deg = 0;
  int line = 0;
};

class ViewScript {
 public:
  ViewScript() = default;
  // Throws std::invalid_argument: "FILE:LINE: …" for the first bad line.
  static ViewScript parse(const std::string& text, const std::string& name);
  static ViewScript read(const std::string& path);

  // Feeds frame `frame`'s key and mouse events into `input` (holds end on their frame).
  void feed(int frame, InputState& input) const;
  // The events at `frame` that the viewer carries out itself (scrub, screenshots, pose, quit).
  std::vector<ScriptEvent> commands_at(int frame) const;
  int last_frame() const;  // of any event or hold's end; −1 when empty

 private:
  std::vector<ScriptEvent> events_;
};

}  // namespace skylit::app::view::window
