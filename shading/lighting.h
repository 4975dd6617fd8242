// Lighting of the `shadow`, `irradiance` and lit `shaded` products (DESIGN.md
// "Products"): a sky (radiance function of direction) plus the sun as a key light, and
// the resolution of what a user asks for (a time and place, or a sun azimuth and
// elevation; a sky name; a turbidity) into that.
//
// Energy budget (one clear-sky model family for sun and sky, atmosphere.h):
//  * sun   : ESRA clear-sky DNI for the sun's elevation and turbidity T (make_sun); 0
//            when its centre is below the horizon.
//  * uniform, cie:<type>: scaled so that the horizontal diffuse irradiance is the ESRA
//            clear-sky diffuse D(e, T) × twilight_factor(e); grey. CIE types 1–5 and
//            16 are overcast: they have no sun (the direct beam is hidden by cloud).
//  * preetham: the Perez/Preetham shape at the ESRA level (sky_preetham.h); colour.
//  * <file>: an equirectangular HDR map (sky_envmap.h), pixel values × sky_scale in
//            W m⁻² sr⁻¹; colour. The sun is added only when a time or sun angles are
//            given (a map has its own lighting; its sun should be clamped out).
// With a grey sky the sun is grey too (its broadband DNI), so `shaded` is one band.
//
// Tone map of `shaded` (a fixed exposure per sky model, so the images of a time series
// are comparable — noon is brighter than dusk, night is black):
//   code = curve(exposure · key · albedo · E_c / E_ref)
// (curve and key: products.h ToneCurve and shaded_key; sRGB with key kShadedKey by default)
// with E_c the irradiance of channel c on the surface (sky + sun) and E_ref the
// broadband irradiance of open flat ground under the same sky model and turbidity with
// the sun at the zenith (for a map: the map's own horizontal irradiance, plus the
// zenith sun if a sun is on). Every value is clamped at 0 first: order-n SH
// visibility can ring slightly negative, and radiance never is.
#pragma once

#include "shading/sky/atmosphere.h"
#include "shading/sky/sky_model.h"
#include "shading/sky/sun_position.h"

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace skylit::shading {

struct Lighting {
  std::shared_ptr<const sky::SkyModel> sky;  // null: no sky light
  // Toward the sun (always set: `shadow` needs it) and its DNI (W/m²; 0: no sun light).
  sky::Sun sun;
  bool colour = false;                // `shaded`: 3 bands R, G, B; false: one grey band
  double reference_irradiance = 1.0;  // E_ref of the tone map (W/m², broadband, > 0)
};

// Throws std::invalid_argument unless the sun direction is unit, its DNI ≥ 0 and
// E_ref > 0 (all finite).
void validate(const Lighting& lighting);

// Open flat ground at E_ref displays as linear kShadedKey (sRGB code 231): headroom for
// slopes facing a low sun, which get up to about E_ref.
inline constexpr double kShadedKey = 0.8;

// gdaldem's default light, and the default clear-sky turbidity.
inline constexpr double kDefaultSunAzimuthDeg = 315.0;
inline constexpr double kDefaultSunElevationDeg = 45.0;
inline constexpr double kDefaultTurbidity = 3.0;

struct SkySpec {
  enum class Kind { Uniform, Preetham, Cie, EnvMap };
  Kind kind = Kind::Uniform;
  int cie_type = 0;   // Cie: 1..16
  std::string path;   // EnvMap
};

// "uniform", "preetham", "cie:<1..16>", or a path to an image (anything with a '.' or
// '/'). Throws LightingError (option "sky") with a one-line message otherwise.
SkySpec parse_sky_spec(std::string_view text);
bool is_overcast(const SkySpec& spec);

struct LightingRequest {
  std::string time;                        // ISO 8601 with a zone; empty: none
  std::optional<double> latitude_deg;      // the place for `time` (else the DEM's centre)
  std::optional<double> longitude_deg;
  double height_m = 0.0;                   // observer height for the sun's position
  std::optional<double> sun_azimuth_deg;   // overrides: from north, clockwise
  std::optional<double> sun_elevation_deg; // above the horizontal, [−90, 90]
  std::string sky = "uniform";
  double turbidity = kDefaultTurbidity;
  bool sun = true;                         // false: sky light only
  double sky_scale = 1.0;                  // <file> skies: pixel value multiplier
  bool operator==(const LightingRequest&) const = default;
};

// Every check that needs neither the DEM nor the sky map: the time parses with an
// explicit zone, latitude/longitude/angles in range, sky name and CIE type, turbidity,
// scale. Throws LightingError (one line).
void validate(const LightingRequest& request);
// True when the sun's position must come from the time and a place.
bool needs_place(const LightingRequest& request);

// What parse_sky_spec, validate(LightingRequest) and resolve_lighting throw for a request
// that cannot work. option(): the LightingRequest member at fault ("time",
// "latitude_deg", "longitude_deg", "height_m", "sun_azimuth_deg", "sun_elevation_deg",
// "sky", "turbidity", "sky_scale"), or "place" when a time needs latitude_deg and
// longitude_deg. Messages name no command-line flag; a front end adds its own for option().
class LightingError : public std::invalid_argument {
 public:
  LightingError(std::string option, const std::string& message)
      : std::invalid_argument(message), option_(std::move(option)) {}
  const std::string& option() const { return option_; }

 private:
  std::string option_;
};

struct ResolvedLighting {
  Lighting lighting;
  double sun_azimuth_deg = 0.0;
  double sun_elevation_deg = 0.0;  // apparent (refracted) when from a time
  std::string summary;             // one line for the log
};

// `place` is used when the time needs one and the request gives no latitude/longitude
// (the DEM's centre). Without a time or angles the sun is gdaldem's (315°, 45°). Throws
// LightingError (bad request, no place for a time, a map that is not 2:1) or
// std::runtime_error (unreadable map), one line each.
ResolvedLighting resolve_lighting(const LightingRequest& request, const std::optional<sky::Observer>& place);

}  // namespace skylit::shading
