#include "flight/track_sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace skylit::flight {
namespace {

constexpr double kStandardGravity = 9.80665;  // m/s², CGPM 1901

// Difference of headings (degrees) wrapped into (−180, 180].
double heading_difference(double to, double from) {
  double d = std::fmod(to - from, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

double compass(glm::dvec2 d) {
  const double h = glm::degrees(std::atan2(d.x, d.y));
  return h < 0.0 ? h + 360.0 : h;
}

}  // namespace

TrackSampler::TrackSampler(const Track& track, const Projection& project, const HeightOf& height, SamplerOptions options)
    : options_(options) {
  for (const Fix& f : track.fixes) {
    if (!f.valid) continue;
    const glm::dvec2 xy = project(f.lon_deg, f.lat_deg);
    const std::optional<double> z = height(f, xy.x, xy.y);
    if (!z) continue;
    fixes_.push_back({f.time_s, {xy.x, xy.y, *z}});
  }
  index_segments();
}

TrackSampler::TrackSampler(std::vector<PlacedFix> fixes, SamplerOptions options)
    : fixes_(std::move(fixes)), options_(options) {
  for (std::size_t k = 1; k < fixes_.size(); ++k)
    if (!(fixes_[k].time_s > fixes_[k - 1].time_s)) throw std::invalid_argument("placed fixes must have increasing times");
  index_segments();
}

void TrackSampler::index_segments() {
  if (!(options_.max_gap_s > 0.0) || !(options_.window_s > 0.0) || !(options_.still_speed_mps >= 0.0))
    throw std::invalid_argument("sampler: max gap and window must be positive, the still speed not negative");
  const std::size_t n = fixes_.size();
  segment_.assign(n, 0);
  segment_end_.assign(n, 0);
  for (std::size_t k = 1; k < n; ++k)
    segment_[k] = fixes_[k].time_s - fixes_[k - 1].time_s > options_.max_gap_s ? k : segment_[k - 1];
  for (std::size_t k = n; k-- > 0;) segment_end_[k] = (k + 1 < n && segment_[k + 1] == segment_[k]) ? segment_end_[k + 1] : k;
  moving_heading_.assign(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const Motion m = motion(segment_[k], fixes_[k].time_s);
    moving_heading_[k] = m.horizontal_speed >= options_.still_speed_mps ? compass(m.direction)
                         : k > 0                                       ? moving_heading_[k - 1]
                                                                       : 0.0;
  }
}

std::optional<std::size_t> TrackSampler::bracket(double t) const {
  if (fixes_.empty() || !std::isfinite(t)) return std::nullopt;
  const auto after = std::upper_bound(fixes_.begin(), fixes_.end(), t,
                                      [](double v, const PlacedFix& f) { return v < f.time_s; });
  if (after == fixes_.begin()) return std::nullopt;
  const std::size_t i = static_cast<std::size_t>(after - fixes_.begin()) - 1;
  if (t == fixes_[i].time_s) return i;
  if (after == fixes_.end() || segment_[i + 1] != segment_[i]) return std::nullopt;
  return i;
}

glm::dvec3 TrackSampler::interpolate(std::size_t i, double t) const {
  if (i + 1 >= fixes_.size() || t <= fixes_[i].time_s) return fixes_[i].position;
  const PlacedFix &a = fixes_[i], &b = fixes_[i + 1];
  const double u = std::clamp((t - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0);
  return a.position + u * (b.position - a.position);
}

TrackSampler::Motion TrackSampler::motion(std::size_t segment, double t) const {
  const std::size_t first = segment, last = segment_end_[segment];
  const double a = std::max(t - options_.window_s, fixes_[first].time_s);
  const double b = std::min(t + options_.window_s, fixes_[last].time_s);
  Motion m;
  if (!(b - a > 1e-9)) return m;
  // Index of the fix at or before a time, within the segment.
  auto floor_index = [&](double v) {
    const auto it = std::upper_bound(fixes_.begin() + first, fixes_.begin() + last + 1, v,
                                     [](double x, const PlacedFix& f) { return x < f.time_s; });
    return static_cast<std::size_t>(it - fixes_.begin()) - 1;
  };
  const std::size_t ia = floor_index(a), ib = floor_index(b);
  const glm::dvec3 pa = interpolate(ia, a), pb = interpolate(ib, b);
  double path = 0.0;
  glm::dvec3 previous = pa;
  for (std::size_t k = ia + 1; k <= ib; ++k) {
    path += glm::length(glm::dvec2(fixes_[k].position) - glm::dvec2(previous));
    previous = fixes_[k].position;
  }
  path += glm::length(glm::dvec2(pb) - glm::dvec2(previous));
  m.direction = glm::dvec2(pb) - glm::dvec2(pa);
  m.horizontal_speed = path / (b - a);
  m.vertical_speed = (pb.z - pa.z) / (b - a);
  return m;
}

double TrackSampler::heading_deg(std::size_t segment, double t, std::size_t at_fix) const {
  const Motion m = motion(segment, t);
  return m.horizontal_speed >= options_.still_speed_mps ? compass(m.direction) : moving_heading_[at_fix];
}

std::optional<glm::dvec3> TrackSampler::position_at(double time_s) const {
  const auto i = bracket(time_s);
  if (!i) return std::nullopt;
  return interpolate(*i, time_s);
}

std::optional<Pose> TrackSampler::pose_at(double time_s) const {
  const auto i = bracket(time_s);
  if (!i) return std::nullopt;
  Pose pose;
  pose.time_s = time_s;
  pose.position = interpolate(*i, time_s);
  const std::size_t segment = segment_[*i];
  const Motion m = motion(segment, time_s);
  if (m.horizontal_speed < options_.still_speed_mps) {
    pose.attitude.heading_deg = moving_heading_[*i];
    return pose;
  }
  pose.attitude.heading_deg = compass(m.direction);
  pose.attitude.pitch_deg = glm::degrees(std::atan2(m.vertical_speed, m.horizontal_speed));
  const double t0 = std::max(time_s - options_.window_s, fixes_[segment].time_s);
  const double t1 = std::min(time_s + options_.window_s, fixes_[segment_end_[segment]].time_s);
  if (t1 - t0 > 1e-9) {
    const auto i0 = bracket(t0), i1 = bracket(t1);
    const double turn_deg = heading_difference(heading_deg(segment, t1, i1.value_or(*i)), heading_deg(segment, t0, i0.value_or(*i)));
    const double omega = glm::radians(turn_deg) / (t1 - t0);
    pose.attitude.bank_deg = glm::degrees(std::atan(m.horizontal_speed * omega / kStandardGravity));
  }
  return pose;
}

}  // namespace skylit::flight
