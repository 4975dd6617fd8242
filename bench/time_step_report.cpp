// Prints the tables of docs/time-step.md: how the step of a date alone (time_series.h)
// changes a day's insolation on open flat ground and the sun hours behind a wall,
// against the same day at a 1-minute step, at latitudes 0°, 45°, 65° on the March
// equinox and both solstices of 2026.
//
// Per frame the sun is solar_position's (apparent elevation e, azimuth A) and
//  * flat open ground: E = D(e)·twilight(e) + DNI(e)·sin e, ESRA at turbidity 3 (what
//    the uniform sky and the sun of lighting.h put on it);
//  * a long north–south wall east of the receiver, seen at σ = atan(a·cos ψ), ψ = A − 90°
//    (a = height / distance): the visible fraction of the disc above that line and the
//    ground (sun_disc.h), counted while sun_above_horizon. a is swept so that σ takes
//    24 values up to the day's highest sun: the wall's edge falls at every phase of
//    the step, and the worst case is reported.
// Sums by trapezoid_weights_hours. Usage: time_step_report
#include "shading/sky/atmosphere.h"
#include "shading/sky/sky_model.h"
#include "shading/sky/sun_disc.h"
#include "shading/sky/sun_position.h"
#include "shading/time_integral.h"
#include "shading/time_series.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace {

using namespace skylit;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kTurbidity = 3.0;
constexpr int kWalls = 24;
constexpr double kStepsMin[] = {5, 10, 15, 30, 60};
constexpr double kReferenceMin = 1.0;
constexpr double kMaxInsolationError = 0.5;  // %
constexpr double kMaxSunHoursError = 2.0;    // min

// Visible disc fraction with a wall of a = height/distance to the east.
double wall_fraction(double azimuth, double elevation, double a) {
  const double psi = std::remainder(azimuth - 90 * kDeg, 2 * kPi);
  sky::DiscLine lines[2] = {sky::horizon_line(elevation, 0.0, 0.0)};
  int n = 1;
  if (std::abs(psi) < kPi / 2) {
    const double c = std::cos(psi);
    lines[n++] = sky::horizon_line(elevation, std::atan(a * c), -a * std::sin(psi) / (1 + a * a * c * c));
  }
  return sky::disc_fraction_above_lines({lines, static_cast<std::size_t>(n)});
}

struct Day {
  double insolation_wh = 0;                 // Wh/m²
  std::vector<double> sun_hours;            // h, one per wall
  std::size_t frames = 0;
  double length_h = 0;
};

// without_disc_events: drop the frames at which the whole disc has risen / starts to
// set (the ablation of docs/time-step.md), keeping sunrise, sunset and the grid.
Day integrate(const std::string& date, const sky::Observer& place, double step_min, const std::vector<double>& walls,
              bool without_disc_events = false) {
  shading::TimeSeriesOptions o;
  o.day_step_seconds = step_min * 60.0;
  o.max_frames = 100000;
  shading::TimeSeries ts = shading::resolve_time_series(shading::parse_time_spec(date, o), place);
  if (without_disc_events && ts.instants.size() > 2)
    ts.instants.erase(std::remove_if(ts.instants.begin() + 1, ts.instants.end() - 1,
                                     [&](sky::UtcTime t) { return std::fmod(t.unix_seconds, o.day_step_seconds) != 0; }),
                      ts.instants.end() - 1);
  Day d;
  d.sun_hours.assign(walls.size(), 0.0);
  d.frames = ts.instants.size();
  if (ts.instants.empty()) return d;
  d.length_h = (ts.instants.back().unix_seconds - ts.instants.front().unix_seconds) / 3600.0;
  const std::vector<double> w = shading::trapezoid_weights_hours(ts.instants);
  for (std::size_t k = 0; k < w.size(); ++k) {
    const sky::SolarPosition p = sky::solar_position(ts.instants[k], place);
    const double az = p.azimuth_deg * kDeg, e = p.apparent_elevation_deg * kDeg;
    const sky::Sun s = sky::make_sun(sky::direction_from_azimuth_elevation(az, e), kTurbidity);
    const double e_flat = sky::esra_diffuse_horizontal(e, kTurbidity) * sky::twilight_factor(e) +
                          sky::luminance(s.dni) * std::max(std::sin(e), 0.0);
    d.insolation_wh += w[k] * e_flat;
    if (!shading::sun_above_horizon(s)) continue;
    for (std::size_t j = 0; j < walls.size(); ++j) d.sun_hours[j] += w[k] * wall_fraction(az, e, walls[j]);
  }
  return d;
}

double max_abs_diff_min(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t j = 0; j < a.size(); ++j) m = std::max(m, std::abs(a[j] - b[j]) * 60.0);
  return m;
}

}  // namespace

int main() {
  const double latitudes[] = {0, 45, 65};
  const char* dates[] = {"2026-03-20", "2026-06-21", "2026-12-21"};
  std::printf("Reference: the same day at a %.0f-minute step. Insolation: relative error (%%); "
              "sun hours: largest error over %d walls (min); frames in brackets.\n\n",
              kReferenceMin, kWalls);
  std::printf("| latitude | date | day (h) | insolation (Wh/m²) | 1 min vs 10 s |");
  for (double s : kStepsMin) std::printf(" %g min |", s);
  std::printf("\n| --- | --- | --- | --- | --- |");
  for (std::size_t i = 0; i < std::size(kStepsMin); ++i) std::printf(" --- |");
  std::printf("\n");
  std::vector<double> worst_e(std::size(kStepsMin), 0.0), worst_h(std::size(kStepsMin), 0.0);
  std::vector<double> ablated_e(std::size(kStepsMin), 0.0), ablated_h(std::size(kStepsMin), 0.0);
  for (double lat : latitudes)
    for (const char* date : dates) {
      const sky::Observer place{lat, 0.0, 0.0};
      // Walls whose top is seen at σ_j = j/(kWalls+1) of the noon elevation.
      const sky::SunEvents ev = sky::sun_events(sky::parse_utc_time(std::string(date) + "T12:00Z"), place);
      const double noon = sky::solar_position(ev.solar_noon, place).apparent_elevation_deg * kDeg;
      std::vector<double> walls;
      for (int j = 1; j <= kWalls && noon > 0; ++j) walls.push_back(std::tan(noon * j / (kWalls + 1)));
      const Day ref = integrate(date, place, kReferenceMin, walls);
      const Day fine = integrate(date, place, 10.0 / 60.0, walls);
      std::printf("| %g° | %s | %.2f | %.1f [%zu] | %.3f %%, %.2f min |", lat, date, ref.length_h, ref.insolation_wh,
                  ref.frames, 100 * std::abs(ref.insolation_wh - fine.insolation_wh) / fine.insolation_wh,
                  max_abs_diff_min(ref.sun_hours, fine.sun_hours));
      for (std::size_t i = 0; i < std::size(kStepsMin); ++i) {
        const Day d = integrate(date, place, kStepsMin[i], walls);
        const double ee = ref.insolation_wh > 0 ? 100 * std::abs(d.insolation_wh - ref.insolation_wh) / ref.insolation_wh : 0;
        const double eh = max_abs_diff_min(d.sun_hours, ref.sun_hours);
        worst_e[i] = std::max(worst_e[i], ee);
        worst_h[i] = std::max(worst_h[i], eh);
        std::printf(" %.3f %%, %.2f min [%zu] |", ee, eh, d.frames);
        const Day a = integrate(date, place, kStepsMin[i], walls, true);
        if (ref.insolation_wh > 0)
          ablated_e[i] = std::max(ablated_e[i], 100 * std::abs(a.insolation_wh - ref.insolation_wh) / ref.insolation_wh);
        ablated_h[i] = std::max(ablated_h[i], max_abs_diff_min(a.sun_hours, ref.sun_hours));
      }
      std::printf("\n");
    }
  std::printf("| worst | | | | |");
  double chosen = kReferenceMin;
  bool passing = true;  // the largest step below which every step passes
  for (std::size_t i = 0; i < std::size(kStepsMin); ++i) {
    std::printf(" %.3f %%, %.2f min |", worst_e[i], worst_h[i]);
    passing = passing && worst_e[i] <= kMaxInsolationError && worst_h[i] <= kMaxSunHoursError;
    if (passing) chosen = kStepsMin[i];
  }
  std::printf("\n| worst without the disc events | | | | |");
  for (std::size_t i = 0; i < std::size(kStepsMin); ++i) std::printf(" %.3f %%, %.2f min |", ablated_e[i], ablated_h[i]);
  std::printf("\n\nLargest step within %.1f %% (insolation) and %.0f min (sun hours) everywhere: %g min\n",
              kMaxInsolationError, kMaxSunHoursError, chosen);
}
