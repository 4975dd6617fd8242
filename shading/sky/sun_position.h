// Solar position by NREL's SPA (Reda & Andreas 2004, NREL/TP-560-34302),
// written from the paper: ±0.0003° given ΔT. UTC is taken as UT1 (|UT1−UTC|
// < 0.9 s, at most 0.004° of hour angle), which keeps the total well inside
// 0.01° for 1950–2100. Degrees at this interface, radians inside.
#pragma once

#include <optional>

#include "shading/sky/time_utc.h"

namespace skylit::sky {

struct Observer {
  double latitude_deg = 0.0;   // geodetic, north positive, [-90, 90]
  double longitude_deg = 0.0;  // east positive, [-180, 180]
  double height_m = 0.0;       // above sea level
};

// Only refraction depends on it; SPA's reference conditions by default.
struct Atmosphere {
  double pressure_mbar = 1010.0;
  double temperature_c = 10.0;
};

// ΔT = TT − UT in seconds: Espenak & Meeus (2006) polynomials, 1860–2150,
// their long-term parabola outside (a ~20 s step at 1860). Within ~1–5 s of
// observed 1950–2025; a 5 s error moves the sun by only 0.00006°.
double delta_t_seconds(double decimal_year);

// Geocentric apparent sun (SPA steps 3.1–3.9): the quantities the paper
// tabulates for its example, exposed for tests and the rise/set algorithm.
struct GeocentricSun {
  double heliocentric_longitude_deg;  // L, [0, 360)
  double heliocentric_latitude_deg;   // B
  double radius_au;                   // R, Earth–sun distance
  double nutation_longitude_deg;      // Δψ
  double nutation_obliquity_deg;      // Δε
  double obliquity_deg;               // ε, true obliquity of the ecliptic
  double apparent_longitude_deg;      // λ
  double sidereal_time_deg;           // ν, apparent sidereal time at Greenwich
  double right_ascension_deg;         // α, [0, 360)
  double declination_deg;             // δ
  double equation_of_time_min;        // E, apparent minus mean solar time
};

GeocentricSun geocentric_sun(double julian_day_ut, double delta_t_s);

struct SolarPosition {
  double azimuth_deg;             // from north, clockwise, [0, 360)
  double elevation_deg;           // topocentric, geometric (no refraction)
  double apparent_elevation_deg;  // with refraction for the given atmosphere
  double zenith_deg;              // 90 − apparent elevation (SPA's θ)
  double hour_angle_deg;          // topocentric local hour angle H', (-180, 180]
  double declination_deg;         // topocentric δ'
  GeocentricSun geocentric;
};

// delta_t_s defaults to delta_t_seconds(decimal_year(t)).
SolarPosition solar_position(UtcTime t, const Observer& observer, const Atmosphere& atmosphere = {},
                             std::optional<double> delta_t_s = std::nullopt);

// Sunrise, transit and sunset of one solar day: the local-mean-time day
// (UTC shifted by longitude/15 h) that contains `t`. Rise and set are when the
// sun's centre is at −0.8333° (34′ refraction + 16′ semi-diameter), by SPA's
// appendix A.2 iterated to convergence; empty when the sun stays up
// (always_up) or down (always_down) that day. Observer height is ignored
// here (no horizon dip), as in SPA and the almanacs.
struct SunEvents {
  std::optional<UtcTime> sunrise;
  UtcTime solar_noon;
  std::optional<UtcTime> sunset;
  bool always_up = false;
  bool always_down = false;
};

SunEvents sun_events(UtcTime t, const Observer& observer, std::optional<double> delta_t_s = std::nullopt);

}  // namespace skylit::sky
