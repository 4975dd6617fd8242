// The viewer's keys: one table that the event handling, the --script checks and the F1
// help all read.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace skylit::app::view::window {

enum class Action {
  PlayPause, Faster, Slower, Reverse, Loop, StepFrameForward, StepFrameBack, StepSecondForward,
  StepSecondBack, ToStart, ToEnd, CameraFollow, CameraOrbit, CameraFree, NextTrack, Brush, TogglePanel,
  Help, Screenshot, Quit,
};

struct KeyBinding {
  std::string_view key;  // InputState's name
  Action action;
  std::string_view help;
};

std::span<const KeyBinding> key_bindings();
std::optional<Action> action_for(std::string_view key);

// Held keys that move the free camera (not actions): w a s d q e, and shift (faster).
inline constexpr std::string_view kMoveKeys[] = {"w", "a", "s", "d", "q", "e", "shift"};

// Every key name a script may use: the bindings' and the move keys.
bool is_known_key(std::string_view key);

}  // namespace skylit::app::view::window
