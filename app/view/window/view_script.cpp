#include "app/view/window/view_script.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/view/window/key_bindings.h"
#include "shading/sky/time_utc.h"

namespace skylit::app::view::window {
namespace {

using Verb = ScriptEvent::Verb;

[[noreturn]] void fail(const std::string& name, int line, const std::string& what) {
  throw std::invalid_argument(name + ":" + std::to_string(line) + ": " + what);
}

std::string key_arg(std::istringstream& in, const std::string& name, int line) {
  std::string key;
  if (!(in >> key)) fail(name, line, "a key name is missing");
  if (!is_known_key(key)) fail(name, line, "unknown key '" + key + "' (F1 in the viewer lists the keys)");
  return key;
}

}  // namespace

ViewScript ViewScript::parse(const std::string& text, const std::string& name) {
  ViewScript s;
  std::istringstream lines(text);
  std::string raw;
  for (int line = 1; std::getline(lines, raw); ++line) {
    if (const auto hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
    std::istringstream in(raw);
    std::string first;
    if (!(in >> first)) continue;
    ScriptEvent e{};
    e.line = line;
    std::size_t used = 0;
    try {
      e.frame = std::stoi(first, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != first.size() || e.frame < 0) fail(name, line, "'" + first + "' is not a frame number >= 0");
    std::string verb;
    if (!(in >> verb)) fail(name, line, "a verb is missing after the frame");
    if (verb == "press") {
      e.verb = Verb::Press;
      e.key = key_arg(in, name, line);
    } else if (verb == "hold") {
      e.verb = Verb::Hold;
      e.key = key_arg(in, name, line);
      if (!(in >> e.frames) || e.frames < 1) fail(name, line, "hold needs a number of frames >= 1");
    } else if (verb == "look") {
      e.verb = Verb::Look;
      if (!(in >> e.dx >> e.dy)) fail(name, line, "look needs DX DY in pixels");
    } else if (verb == "wheel") {
      e.verb = Verb::Wheel;
      if (!(in >> e.dx)) fail(name, line, "wheel needs a number of steps");
    } else if (verb == "click") {
      e.verb = Verb::Click;
      if (!(in >> e.dx >> e.dy)) fail(name, line, "click needs X Y in window pixels");
    } else if (verb == "drag") {
      e.verb = Verb::Drag;
      if (!(in >> e.dx >> e.dy >> e.to_x >> e.to_y >> e.frames) || e.frames < 1)
        fail(name, line, "drag needs X0 Y0 X1 Y1 in window pixels and a number of frames >= 1");
    } else if (verb == "scrub") {
      e.verb = Verb::Scrub;
      std::string t;
      if (!(in >> t)) fail(name, line, "scrub needs a time");
      try {
        e.unix_seconds = sky::parse_utc_time(t).unix_seconds;
      } catch (const std::invalid_argument& x) {
        fail(name, line, "scrub '" + t + "': " + x.what());
      }
    } else if (verb == "screenshot") {
      e.verb = Verb::Screenshot;
      if (!(in >> e.path)) fail(name, line, "screenshot needs a file name");
    } else if (verb == "windowshot") {
      e.verb = Verb::WindowShot;
      if (!(in >> e.path)) fail(name, line, "windowshot needs a file name");
    } else if (verb == "pose") {
      e.verb = Verb::Pose;
      if (!(in >> e.eye.x >> e.eye.y >> e.eye.z >> e.heading_deg >> e.pitch_deg))
        fail(name, line, "pose needs X Y Z HEADING PITCH");
      if (!(std::abs(e.pitch_deg) <= 89.0)) fail(name, line, "pose: the pitch must be within ±89 degrees");
    } else if (verb == "quit") {
      e.verb = Verb::Quit;
    } else {
      fail(name, line, "unknown verb '" + verb + "' (press, hold, look, wheel, click, drag, scrub, screenshot, windowshot, pose, quit)");
    }
    std::string extra;
    if (in >> extra) fail(name, line, "unexpected '" + extra + "'");
    s.events_.push_back(e);
  }
  return s;
}

ViewScript ViewScript::read(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::invalid_argument("--script '" + path + "' cannot be read");
  std::ostringstream text;
  text << f.rdbuf();
  return parse(text.str(), path);
}

void ViewScript::feed(int frame, InputState& input) const {
  for (const ScriptEvent& e : events_) {
    if (e.verb == Verb::Hold && e.frame + e.frames == frame) input.release(e.key);
    if (e.verb == Verb::Drag && frame > e.frame && frame <= e.frame + e.frames + 1) {
      const double t = std::min(1.0, static_cast<double>(frame - e.frame) / e.frames);
      input.cursor = {e.dx + t * (e.to_x - e.dx), e.dy + t * (e.to_y - e.dy)};
      input.brush_held = frame <= e.frame + e.frames;
    }
    if (e.frame != frame) continue;
    switch (e.verb) {
      case Verb::Press:
        input.press(e.key);
        input.release(e.key);
        break;
      case Verb::Hold:
        input.press(e.key);
        break;
      case Verb::Look:
        input.look += glm::dvec2(e.dx, e.dy);
        break;
      case Verb::Wheel:
        input.wheel += e.dx;
        break;
      case Verb::Click:
        input.brush_click = true;
        input.cursor = {e.dx, e.dy};
        break;
      case Verb::Drag:
        input.brush_click = input.brush_held = true;
        input.cursor = {e.dx, e.dy};
        break;
      default:
        break;
    }
  }
}

std::vector<ScriptEvent> ViewScript::commands_at(int frame) const {
  std::vector<ScriptEvent> out;
  for (const ScriptEvent& e : events_)
    if (e.frame == frame && (e.verb == Verb::Scrub || e.verb == Verb::Screenshot || e.verb == Verb::WindowShot ||
                                 e.verb == Verb::Pose || e.verb == Verb::Quit))
      out.push_back(e);
  return out;
}

int ViewScript::last_frame() const {
  int last = -1;
  for (const ScriptEvent& e : events_) last = std::max(last, e.frame + (e.verb == Verb::Hold ? e.frames : e.verb == Verb::Drag ? e.frames + 1 : 0));
  return last;
}

}  // namespace skylit::app::view::window
