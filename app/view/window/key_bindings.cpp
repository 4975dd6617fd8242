#include "app/view/window/key_bindings.h"

#include <algorithm>
#include <array>

namespace skylit::app::view::window {
namespace {

constexpr std::array kBindings{
    KeyBinding{"space", Action::PlayPause, "play / pause"},
    KeyBinding{"equal", Action::Faster, "faster (0.25x to 256x)"},
    KeyBinding{"minus", Action::Slower, "slower"},
    KeyBinding{"r", Action::Reverse, "reverse"},
    KeyBinding{"l", Action::Loop, "loop on / off"},
    KeyBinding{"period", Action::StepFrameForward, "step one frame forward (pauses)"},
    KeyBinding{"comma", Action::StepFrameBack, "step one frame back"},
    KeyBinding{"right", Action::StepSecondForward, "one second forward (shift: ten)"},
    KeyBinding{"left", Action::StepSecondBack, "one second back (shift: ten)"},
    KeyBinding{"home", Action::ToStart, "to the start"},
    KeyBinding{"end", Action::ToEnd, "to the end"},
    KeyBinding{"1", Action::CameraFollow, "camera: follow the aircraft"},
    KeyBinding{"2", Action::CameraOrbit, "camera: orbit (right-drag turns, wheel zooms)"},
    KeyBinding{"3", Action::CameraFree, "camera: free (WASD, Q/E down/up, right-drag looks, wheel: speed)"},
    KeyBinding{"t", Action::NextTrack, "follow the next track"},
    KeyBinding{"b", Action::Brush, "terrain brush: off / raise / lower / smooth (left click or drag applies)"},
    KeyBinding{"h", Action::TogglePanel, "hide / show the panel"},
    KeyBinding{"f1", Action::Help, "these keys"},
    KeyBinding{"f12", Action::Screenshot, "screenshot (scale in the panel)"},
    KeyBinding{"escape", Action::Quit, "quit"},
};

}  // namespace

std::span<const KeyBinding> key_bindings() { return kBindings; }

std::optional<Action> action_for(std::string_view key) {
  for (const KeyBinding& b : kBindings)
    if (b.key == key) return b.action;
  return std::nullopt;
}

bool is_known_key(std::string_view key) {
  return action_for(key).has_value() || std::find(std::begin(kMoveKeys), std::end(kMoveKeys), key) != std::end(kMoveKeys);
}

}  // namespace skylit::app::view::window
