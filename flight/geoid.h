// Ellipsoidal (WGS 84) heights to heights above the EGM96 geoid (mean sea level), through
// PROJ: EPSG:4979 (WGS 84 3-D) → EPSG:4326+5773 (WGS 84 + EGM96 height), whose operation
// uses the grid egm96_15.gtx (Debian: proj-data). Only operations whose grids are
// present are accepted, so a missing grid is an error, never a silent zero correction
// (PROJ's "ballpark" fallback would leave heights unchanged).
#pragma once

#include <memory>

namespace skylit::flight {

class EllipsoidToGeoid {
 public:
  // Throws std::runtime_error naming the grid when PROJ cannot use it.
  EllipsoidToGeoid();
  ~EllipsoidToGeoid();
  EllipsoidToGeoid(const EllipsoidToGeoid&) = delete;
  EllipsoidToGeoid& operator=(const EllipsoidToGeoid&) = delete;

  // Height above the geoid H = h − N(lat, lon) for an ellipsoidal height h (metres).
  double msl_height(double lat_deg, double lon_deg, double ellipsoidal_m) const;
  // The geoid undulation N (metres, geoid above ellipsoid positive).
  double undulation(double lat_deg, double lon_deg) const { return -msl_height(lat_deg, lon_deg, 0.0); }

 private:
  struct Proj;
  std::unique_ptr<Proj> proj_;
};

}  // namespace skylit::flight
