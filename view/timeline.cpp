#include "view/timeline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace skylit::view {

Timeline::Timeline(double start_s, double end_s) : start_(start_s), end_(end_s), t_(start_s) {
  if (!std::isfinite(start_s) || !std::isfinite(end_s) || end_s < start_s)
    throw std::invalid_argument("timeline: the end is before the start or not finite");
}

void Timeline::advance(double wall_dt_s) {
  if (!playing_ || !(wall_dt_s > 0.0)) return;
  const double span = end_ - start_;
  double t = t_ + (reversed_ ? -1.0 : 1.0) * speed() * wall_dt_s;
  if (t >= start_ && t <= end_) {
    t_ = t;
    return;
  }
  if (loop_ && span > 0.0) {  // wrap into [start, end)
    t_ = start_ + std::fmod(std::fmod(t - start_, span) + span, span);
    return;
  }
  t_ = std::clamp(t, start_, end_);
  playing_ = false;
}

void Timeline::set_playing(bool playing) {
  // Playing on from a stopped end restarts at the other end.
  if (playing && !loop_) {
    if (!reversed_ && t_ >= end_) t_ = start_;
    if (reversed_ && t_ <= start_) t_ = end_;
  }
  playing_ = playing;
}

void Timeline::faster() { set_speed_index(speed_index_ + 1); }
void Timeline::slower() { set_speed_index(speed_index_ - 1); }
void Timeline::set_speed_index(int index) {
  speed_index_ = std::clamp(index, 0, static_cast<int>(kPlaybackSpeeds.size()) - 1);
}

void Timeline::scrub(double t_s) {
  if (std::isfinite(t_s)) t_ = std::clamp(t_s, start_, end_);
}

void Timeline::step_frames(int n, double frame_s) { step_seconds(n * frame_s); }

void Timeline::step_seconds(double seconds) {
  playing_ = false;
  scrub(t_ + seconds);
}

}  // namespace skylit::view
