#include "shading/lighting.h"

#include "shading/sky/sky_cie.h"
#include "shading/sky/sky_envmap.h"
#include "shading/sky/sky_preetham.h"
#include "shading/sky/sky_sh.h"
#include "shading/sky/time_utc.h"

#include <glm/geometric.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace skylit::shading {
namespace {

constexpr double kDeg = sh::kPi / 180.0;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// `option`: the LightingRequest member at fault (LightingError::option).
void require(bool ok, const char* option, const std::string& message) {
  if (!ok) throw LightingError(option, message);
}

// Library messages (OIIO's) may span lines; the CLI prints one.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// The sky of a spec for a sun direction; analytic skies at the ESRA clear-sky level.
std::shared_ptr<const sky::SkyModel> build_sky(const SkySpec& spec, const glm::dvec3& sun_dir, double turbidity,
                                               double sky_scale) {
  const double e = sky::elevation_of(sun_dir);
  const double diffuse = sky::esra_diffuse_horizontal(e, turbidity) * sky::twilight_factor(e);
  switch (spec.kind) {
    case SkySpec::Kind::Uniform: return std::make_shared<sky::UniformSky>(sky::Rgb(diffuse / sh::kPi));
    case SkySpec::Kind::Preetham: return std::make_shared<sky::PreethamSky>(sun_dir, turbidity);
    case SkySpec::Kind::Cie:
      return std::make_shared<sky::CieSky>(sky::CieSky::from_diffuse_horizontal(spec.cie_type, sun_dir, sky::Rgb(diffuse)));
    case SkySpec::Kind::EnvMap: {
      sky::EnvMapOptions opt;
      opt.scale = sky_scale;
      try {
        return std::make_shared<sky::EnvMapSky>(sky::EnvMapSky::load(spec.path, opt));
      } catch (const std::invalid_argument& err) {
        throw LightingError("sky", "sky map " + spec.path + ": " + one_line(err.what()));
      } catch (const std::exception& err) {
        throw std::runtime_error("sky map " + spec.path + ": " + one_line(err.what()));
      }
    }
  }
  return nullptr;
}

}  // namespace

void validate(const Lighting& l) {
  const glm::dvec3& d = l.sun.direction;
  require(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z) && std::abs(glm::length(d) - 1.0) < 1e-9,
          "lighting: the sun direction must be a unit vector");
  for (int c = 0; c < 3; ++c)
    require(std::isfinite(l.sun.dni[c]) && l.sun.dni[c] >= 0.0, "lighting: the sun's DNI must be finite and ≥ 0");
  require(std::isfinite(l.reference_irradiance) && l.reference_irradiance > 0.0,
          "lighting: the reference irradiance must be > 0");
}

SkySpec parse_sky_spec(std::string_view text) {
  SkySpec s;
  if (text == "uniform") return s;
  if (text == "preetham") {
    s.kind = SkySpec::Kind::Preetham;
    return s;
  }
  if (text.starts_with("cie:")) {
    const std::string_view digits = text.substr(4);
    int type = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), type);
    require(ec == std::errc() && end == digits.data() + digits.size() && type >= 1 && type <= sky::kCieTraditionalOvercast,
            "sky", "sky " + std::string(text) + ": the CIE sky type must be an integer 1..16");
    s.kind = SkySpec::Kind::Cie;
    s.cie_type = type;
    return s;
  }
  require(text.find_first_of("./") != std::string_view::npos, "sky",
          "unknown sky '" + std::string(text) + "' (uniform, preetham, cie:<1..16>, or an .hdr/.exr file)");
  s.kind = SkySpec::Kind::EnvMap;
  s.path = std::string(text);
  return s;
}

// ISO 15469 types 1–5 are the overcast group; 16 is the traditional overcast sky.
bool is_overcast(const SkySpec& spec) {
  return spec.kind == SkySpec::Kind::Cie && (spec.cie_type <= 5 || spec.cie_type == sky::kCieTraditionalOvercast);
}

void validate(const LightingRequest& r) {
  if (!r.time.empty()) {
    try {
      sky::parse_utc_time(r.time);
    } catch (const std::invalid_argument& err) {  // names the rule it broke
      throw LightingError("time", err.what());
    }
  }
  if (r.latitude_deg)
    require(std::isfinite(*r.latitude_deg) && std::abs(*r.latitude_deg) <= 90.0, "latitude_deg",
            "latitude " + number(*r.latitude_deg) + " outside -90..90 degrees");
  if (r.longitude_deg)
    require(std::isfinite(*r.longitude_deg) && std::abs(*r.longitude_deg) <= 180.0, "longitude_deg",
            "longitude " + number(*r.longitude_deg) + " outside -180..180 degrees");
  require(r.latitude_deg.has_value() == r.longitude_deg.has_value(), "place",
          "give both latitude and longitude, or neither");
  require(std::isfinite(r.height_m), "height_m", "observer height must be finite");
  if (r.sun_azimuth_deg)
    require(std::isfinite(*r.sun_azimuth_deg), "sun_azimuth_deg",
            "the sun's azimuth must be a finite number of degrees");
  if (r.sun_elevation_deg)
    require(std::isfinite(*r.sun_elevation_deg) && std::abs(*r.sun_elevation_deg) <= 90.0, "sun_elevation_deg",
            "sun elevation " + number(*r.sun_elevation_deg) + " outside -90..90 degrees");
  require(std::isfinite(r.turbidity) && r.turbidity >= sky::kMinTurbidity && r.turbidity <= sky::kMaxTurbidity,
          "turbidity",
          "turbidity " + number(r.turbidity) + " outside " + number(sky::kMinTurbidity) + ".." +
              number(sky::kMaxTurbidity));
  require(std::isfinite(r.sky_scale) && r.sky_scale > 0.0, "sky_scale", "the sky scale must be > 0");
  parse_sky_spec(r.sky);
}

bool needs_place(const LightingRequest& r) {
  return !r.time.empty() && !(r.sun_azimuth_deg && r.sun_elevation_deg);
}

ResolvedLighting resolve_lighting(const LightingRequest& r, const std::optional<sky::Observer>& place) {
  validate(r);
  const SkySpec spec = parse_sky_spec(r.sky);
  ResolvedLighting out;
  out.sun_azimuth_deg = kDefaultSunAzimuthDeg;
  out.sun_elevation_deg = kDefaultSunElevationDeg;
  std::string where = "gdaldem's default sun";
  if (needs_place(r)) {
    std::optional<sky::Observer> at = place;
    if (r.latitude_deg) at = sky::Observer{*r.latitude_deg, *r.longitude_deg, r.height_m};
    require(at.has_value(), "place",
            "a time needs the DEM's location, but the DEM has no CRS: give a latitude and longitude (degrees)");
    // Apparent (refracted) elevation: where the sun is seen, and what air mass uses.
    const sky::SolarPosition p = sky::solar_position(sky::parse_utc_time(r.time), *at);
    out.sun_azimuth_deg = p.azimuth_deg;
    out.sun_elevation_deg = p.apparent_elevation_deg;
    where = "sun at " + r.time + ", lat " + number(at->latitude_deg) + " lon " + number(at->longitude_deg);
  }
  if (r.sun_azimuth_deg) out.sun_azimuth_deg = *r.sun_azimuth_deg;
  if (r.sun_elevation_deg) out.sun_elevation_deg = *r.sun_elevation_deg;

  const glm::dvec3 sun_dir =
      sky::direction_from_azimuth_elevation(out.sun_azimuth_deg * kDeg, out.sun_elevation_deg * kDeg);
  Lighting& l = out.lighting;
  l.sky = build_sky(spec, sun_dir, r.turbidity, r.sky_scale);
  l.colour = spec.kind == SkySpec::Kind::Preetham || spec.kind == SkySpec::Kind::EnvMap;
  const bool sun_positioned = !r.time.empty() || r.sun_azimuth_deg || r.sun_elevation_deg;
  const bool sun_on = r.sun && !is_overcast(spec) && (spec.kind != SkySpec::Kind::EnvMap || sun_positioned);
  l.sun = sky::make_sun(sun_dir, r.turbidity);
  if (!sun_on) l.sun.dni = sky::Rgb(0.0);
  if (!l.colour) l.sun.dni = sky::Rgb(sky::luminance(l.sun.dni));

  const double zenith_sun = sun_on ? sky::broadband_dni(sh::kPi / 2, r.turbidity) : 0.0;
  const double flat_sky = spec.kind == SkySpec::Kind::EnvMap
                              ? sky::luminance(sky::horizontal_irradiance(*l.sky))
                              : sky::esra_diffuse_horizontal(sh::kPi / 2, r.turbidity);
  const double reference = zenith_sun + flat_sky;
  l.reference_irradiance = reference > 0.0 ? reference : 1.0;  // a black map: any exposure shows black
  validate(l);

  out.summary = where + ": azimuth " + number(out.sun_azimuth_deg) + "°, elevation " +
                number(out.sun_elevation_deg) + "°; sky " + r.sky + ", turbidity " + number(r.turbidity) +
                "; DNI " + number(sky::luminance(l.sun.dni)) + " W/m²";
  return out;
}

}  // namespace skylit::shading
