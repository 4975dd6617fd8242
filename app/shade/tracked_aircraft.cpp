#include "app/shade/tracked_aircraft.h"

#include "app/shade/sphere_input.h"
#include "flight/aircraft_catalog.h"
#include "flight/lon_lat_projection.h"
#include "flight/track_reader.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/sky/time_utc.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace skylit::app::shade {
namespace {

// The DEM's height (bilinear) at CRS (x, y); NaN off the grid.
double ground_at(const terrain::HeightField& field, double x, double y) {
  const glm::dvec2 t = texel_of(field, x, y);
  const horizon::GridPoint p{t.x, t.y};
  return horizon::on_grid(field, p) ? horizon::bilinear_height(field, p) : std::numeric_limits<double>::quiet_NaN();
}

// The DEM must place the track (CRS, geotransform), then the set is loaded: checked in
// this order before any track is read.
skylit::flight::SphereSet checked_set(const terrain::HeightField& field, const std::string& aircraft) {
  if (field.georef.crs_wkt.empty() || !field.georef.has_geotransform)
    throw std::invalid_argument("--track needs a DEM with a CRS and a geotransform, to place the track on it");
  try {
    return skylit::flight::load_aircraft(aircraft);
  } catch (const std::exception& e) {
    throw std::invalid_argument(std::string("--aircraft: ") + e.what());
  }
}

}  // namespace

TrackedAircraft::TrackedAircraft(const std::string& track_path, const std::string& aircraft,
                                 const skylit::flight::AltitudeMode& altitude, const terrain::HeightField& field)
    : field_(field), set_(checked_set(field, aircraft)) {
  place(skylit::flight::read_track_file(track_path), "--track '" + track_path + "'", altitude);
}

TrackedAircraft::TrackedAircraft(const std::vector<std::string>& track_paths, const std::string& aircraft,
                                 const skylit::flight::AltitudeMode& altitude, const terrain::HeightField& field)
    : field_(field), set_(checked_set(field, aircraft)) {
  std::vector<skylit::flight::Track> tracks;
  std::string source = "--track";
  for (const std::string& path : track_paths) {
    const std::vector<skylit::flight::Track> read = skylit::flight::read_track_file(path);
    tracks.insert(tracks.end(), read.begin(), read.end());
    source += " '" + path + "'";
  }
  place(tracks, source, altitude);
}

TrackedAircraft::TrackedAircraft(const std::vector<skylit::flight::Track>& tracks, const std::string& source,
                                 const std::string& aircraft, const skylit::flight::AltitudeMode& altitude,
                                 const terrain::HeightField& field)
    : field_(field), set_(checked_set(field, aircraft)) {
  place(tracks, source, altitude);
}

void TrackedAircraft::place(const std::vector<skylit::flight::Track>& tracks, const std::string& source,
                            const skylit::flight::AltitudeMode& altitude) {
  const terrain::HeightField& field = field_;
  auto project = std::make_shared<skylit::flight::LonLatToCrs>(field.georef.crs_wkt);
  auto resolver = std::make_shared<skylit::flight::AltitudeResolver>(
      altitude, [&field](double x, double y) { return ground_at(field, x, y); });
  start_ = std::numeric_limits<double>::infinity();
  end_ = -start_;
  for (const skylit::flight::Track& t : tracks) {
    skylit::flight::TrackSampler s(
        t, [project](double lon, double lat) { return (*project)(lon, lat); },
        [resolver](const skylit::flight::Fix& f, double x, double y) { return resolver->height(f, x, y); });
    samplers_.emplace_back();
    if (s.fixes().size() < 2) continue;
    start_ = std::min(start_, s.fixes().front().time_s);
    end_ = std::max(end_, s.fixes().back().time_s);
    samplers_.back() = std::move(s);
    ++placed_;
  }
  if (placed_ == 0) throw std::invalid_argument(source + ": no track has two valid fixes with a usable altitude");
}

glm::dvec3 TrackedAircraft::to_field(const glm::dvec3& crs) const {
  return to_field_frame(field_, {{crs, 1.0}}).front().centre;
}

std::optional<skylit::flight::Pose> TrackedAircraft::pose_at(std::size_t k, double unix_seconds) const {
  std::optional<skylit::flight::Pose> pose = samplers_[k] ? samplers_[k]->pose_at(unix_seconds) : std::nullopt;
  if (pose) pose->position = to_field(pose->position);
  return pose;
}

bool TrackedAircraft::over_field(std::size_t k) const {
  const double w = (field_.width - 1) * field_.mean_dx(), h = (field_.height - 1) * field_.dy;
  for (int s = 0; s <= 64; ++s)
    if (const auto p = pose_at(k, start_ + (end_ - start_) * s / 64.0))
      if (p->position.x >= 0 && p->position.x <= w && p->position.y <= 0 && p->position.y >= -h) return true;
  return false;
}

std::vector<blockers::Sphere> TrackedAircraft::spheres_at(double unix_seconds) const {
  std::vector<blockers::Sphere> out;
  for (std::size_t k = 0; k < samplers_.size(); ++k) {
    // The reference point in the field frame, then the set placed around it in metres.
    const std::optional<skylit::flight::Pose> pose = pose_at(k, unix_seconds);
    if (!pose) continue;
    for (const skylit::flight::PlacedSphere& p : skylit::flight::place(set_, *pose)) out.push_back({p.centre, p.radius});
  }
  return out;
}

std::string TrackedAircraft::summary() const {
  return set_.name + " (" + std::to_string(set_.spheres.size()) + " spheres) on " + std::to_string(placed_) +
         " track" + (placed_ == 1 ? "" : "s") + ", " + sky::format_utc_time({start_}) + " to " +
         sky::format_utc_time({end_});
}

}  // namespace skylit::app::shade
