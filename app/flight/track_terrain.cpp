#include "app/flight/track_terrain.h"

#include "app/shade/sphere_input.h"
#include "app/shade/tracked_aircraft.h"
#include "flight/lon_lat_projection.h"
#include "flight/sphere_set.h"
#include "shading/horizon/horizon_ray.h"
#include "shading/point_visibility.h"
#include "shading/sky/sun_position.h"
#include "terrain/dem_reader.h"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace skylit::app::flight {
namespace {

namespace fl = skylit::flight;
constexpr double kDeg = std::numbers::pi / 180.0;

terrain::HeightField read_placeable_dem(const std::string& path) {
  const terrain::DemInfo info = terrain::inspect_dem(path);
  if (info.georef.crs_wkt.empty() || !info.georef.has_geotransform)
    throw std::invalid_argument("--dem '" + path + "' has no CRS (or no geotransform): a track cannot be placed on it");
  terrain::DemReadResult r = terrain::read_dem(path);
  for (const std::string& w : r.warnings) std::fprintf(stderr, "skylit: warning: %s\n", w.c_str());
  return std::move(r.field);
}

// Whether some valid fix lies over the DEM (a fix PROJ cannot transform lies nowhere).
bool any_fix_over(const std::vector<fl::Track>& tracks, const terrain::HeightField& field) {
  const fl::LonLatToCrs project(field.georef.crs_wkt);
  for (const fl::Track& t : tracks)
    for (const fl::Fix& f : t.fixes) {
      if (!f.valid) continue;
      try {
        const glm::dvec2 xy = project(f.lon_deg, f.lat_deg);
        const glm::dvec2 p = shade::texel_of(field, xy.x, xy.y);
        if (horizon::on_grid(field, {p.x, p.y})) return true;
      } catch (const std::runtime_error&) {
      }
    }
  return false;
}

// The spheres' centroid, each weighted by its volume (r³).
glm::dvec3 centroid(const std::vector<fl::PlacedSphere>& spheres) {
  glm::dvec3 sum(0.0);
  double weight = 0.0;
  for (const fl::PlacedSphere& s : spheres) {
    const double w = s.radius * s.radius * s.radius;
    sum += w * s.centre, weight += w;
  }
  return sum / weight;
}

FixTerrain fix_terrain(const shading::PointVisibilityMarcher& marcher, const fl::Fix& fix, const fl::Pose& pose,
                       const fl::SphereSet& set) {
  const glm::dvec3 c = centroid(fl::place(set, pose));
  const sky::SolarPosition sun =
      sky::solar_position(sky::UtcTime{fix.time_s}, sky::Observer{fix.lat_deg, fix.lon_deg, pose.position.z});
  const shading::PointVisibility v =
      marcher.at(c, shading::SunAngles{sun.azimuth_deg * kDeg, sun.apparent_elevation_deg * kDeg});
  FixTerrain out;
  out.inside_dem = v.place != shading::PointPlace::Outside;
  out.below_ground = v.place == shading::PointPlace::BelowGround;
  out.ground_m = v.ground_m;
  if (v.ground_m) out.height_above_ground_m = c.z - *v.ground_m;
  out.height_m = pose.position.z;
  out.sun_azimuth_deg = sun.azimuth_deg;
  out.sun_elevation_deg = sun.apparent_elevation_deg;
  out.sun_horizon_deg = v.sun->horizon / kDeg;
  out.in_terrain_shadow = v.sun->in_shadow;
  out.sun_visible_fraction = v.sun->visible_fraction;
  out.sky_view = v.sky_view;
  out.sky_fraction = v.sky_fraction;
  return out;
}

}  // namespace

TrackTerrain::TrackTerrain(const std::vector<fl::Track>& tracks, const std::string& track_file,
                           const std::string& dem_path, const std::string& aircraft, const fl::AltitudeMode& altitude)
    : dem_(dem_path) {
  const terrain::HeightField field = read_placeable_dem(dem_path);
  if (!any_fix_over(tracks, field))
    throw std::invalid_argument("'" + track_file + "' lies entirely outside --dem '" + dem_path +
                                "': no valid fix is over it");
  const shade::TrackedAircraft placed(tracks, "'" + track_file + "'", aircraft, altitude, field);
  aircraft_ = placed.set().name;
  const shading::PointVisibilityMarcher marcher(field);
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    std::vector<std::optional<FixTerrain>>& row = fixes_.emplace_back(tracks[k].fixes.size());
    for (std::size_t i = 0; i < row.size(); ++i) {
      const fl::Fix& f = tracks[k].fixes[i];
      // Invalid fixes are never placed (track_report.h), though a pose may span them.
      const std::optional<fl::Pose> pose = f.valid ? placed.pose_at(k, f.time_s) : std::nullopt;
      if (pose) row[i] = fix_terrain(marcher, f, *pose, placed.set());
    }
  }
}

TrackTerrainSummary TrackTerrain::summary(std::size_t track) const {
  TrackTerrainSummary s;
  double sum = 0.0;
  for (const std::optional<FixTerrain>& f : fixes_[track]) {
    if (!f) continue;
    ++s.fixes;
    if (!f->inside_dem) continue;
    s.sky_view_min = s.over_dem == 0 ? f->sky_view : std::min(s.sky_view_min, f->sky_view);
    ++s.over_dem;
    s.in_shadow += f->in_terrain_shadow ? 1 : 0;
    sum += f->sky_view;
  }
  if (s.over_dem > 0) s.sky_view_mean = sum / static_cast<double>(s.over_dem);
  return s;
}

}  // namespace skylit::app::flight
