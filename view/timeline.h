// The viewer's playback clock over a span of track time (UTC seconds): play and pause,
// speeds 0.25× to 256×, reverse, loop, scrubbing and stepping. Pure logic, advanced by
// the wall (or scripted) time between frames, so the sun, the sky and the aircraft all
// read one clock.
#pragma once

#include <array>

namespace skylit::view {

// Track seconds per wall second.
inline constexpr std::array<double, 11> kPlaybackSpeeds{0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0};

class Timeline {
 public:
  // Throws std::invalid_argument unless start <= end, both finite. Starts paused at start,
  // at 1×, forward, looping.
  Timeline(double start_s, double end_s);

  // Moves the clock by wall_dt_s × speed (backwards when reversed) while playing. At an
  // end it wraps to the other end when looping, else it stops there and pauses.
  void advance(double wall_dt_s);

  void set_playing(bool playing);
  void toggle_playing() { set_playing(!playing_); }
  void faster();  // the next speed of kPlaybackSpeeds (stays at the fastest)
  void slower();
  void set_speed_index(int index);  // clamped to kPlaybackSpeeds
  void toggle_reverse() { reversed_ = !reversed_; }
  void set_loop(bool loop) { loop_ = loop; }
  // Jumps to t, clamped to the span (keeps playing or paused).
  void scrub(double t_s);
  // Pauses and steps by n frames of frame_s (n < 0: back), or by seconds; clamped.
  void step_frames(int n, double frame_s);
  void step_seconds(double seconds);

  double time() const { return t_; }
  double start() const { return start_; }
  double end() const { return end_; }
  bool playing() const { return playing_; }
  bool reversed() const { return reversed_; }
  bool looping() const { return loop_; }
  double speed() const { return kPlaybackSpeeds[static_cast<std::size_t>(speed_index_)]; }
  int speed_index() const { return speed_index_; }

 private:
  double start_, end_, t_;
  bool playing_ = false, reversed_ = false, loop_ = true;
  int speed_index_ = 2;  // 1×
};

}  // namespace skylit::view
