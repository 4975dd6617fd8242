#include "shading/sky/sun_disc.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace skylit::sky {
namespace {

constexpr double kPi = std::numbers::pi;

struct P2 {
  double x, y;
};
double cross(P2 a, P2 b) { return a.x * b.y - a.y * b.x; }
double dot(P2 a, P2 b) { return a.x * b.x + a.y * b.y; }

// Convex polygon with a fixed capacity: a square plus one vertex per clip.
constexpr int kMaxVertices = 4 + kMaxDiscLines + 4;
struct Polygon {
  std::array<P2, kMaxVertices> v;
  int n = 0;
};

// The square [−2, 2]² (counter-clockwise), which contains the unit disc.
Polygon bounding_square() {
  Polygon p;
  p.v[0] = {-2, -2}, p.v[1] = {2, -2}, p.v[2] = {2, 2}, p.v[3] = {-2, 2};
  p.n = 4;
  return p;
}

// Sutherland–Hodgman against {nx·x + ny·y + offset ≥ 0}; keeps counter-clockwise order.
void clip(Polygon& poly, const DiscLine& l) {
  if (poly.n == 0) return;
  Polygon out;
  auto side = [&](P2 p) { return l.nx * p.x + l.ny * p.y + l.offset; };
  for (int k = 0; k < poly.n; ++k) {
    const P2 a = poly.v[k], b = poly.v[(k + 1) % poly.n];
    const double sa = side(a), sb = side(b);
    if (sa >= 0) out.v[out.n++] = a;
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      out.v[out.n++] = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
    }
  }
  poly = out;
}

// Signed area of the unit disc ∩ triangle (0, a, b): straight pieces inside the
// circle contribute their triangle, pieces outside the circular sector they subtend.
double disc_triangle_area(P2 a, P2 b) {
  auto sector = [](P2 p, P2 q) { return 0.5 * std::atan2(cross(p, q), dot(p, q)); };
  const P2 d{b.x - a.x, b.y - a.y};
  const double qa = dot(d, d);
  if (qa == 0.0) return 0.0;
  const double qb = dot(a, d), qc = dot(a, a) - 1.0;
  const double disc = qb * qb - qa * qc;
  if (disc <= 0.0) return sector(a, b);
  const double sq = std::sqrt(disc);
  const double t1 = (-qb - sq) / qa, t2 = (-qb + sq) / qa;
  if (t2 <= 0.0 || t1 >= 1.0) return sector(a, b);
  const double u1 = std::max(t1, 0.0), u2 = std::min(t2, 1.0);
  const P2 p1{a.x + u1 * d.x, a.y + u1 * d.y}, p2{a.x + u2 * d.x, a.y + u2 * d.y};
  return sector(a, p1) + 0.5 * cross(p1, p2) + sector(p2, b);
}

// Area of the unit disc ∩ a counter-clockwise convex polygon.
double disc_polygon_area(const Polygon& poly) {
  double area = 0.0;
  for (int k = 0; k < poly.n; ++k) area += disc_triangle_area(poly.v[k], poly.v[(k + 1) % poly.n]);
  return std::max(area, 0.0);
}

// The line y = y0 + s·(x − x0) with its upper side visible.
DiscLine above(double x0, double y0, double s) {
  const double len = std::sqrt(1.0 + s * s);
  return {-s / len, 1.0 / len, (s * x0 - y0) / len};
}

// ∫ over an azimuth interval of length len of (sin e1 − sin clamp(σ0 + k·t, e0, e1)) dt, exact.
double rect_slab(double len, double sigma0, double k, double e0, double e1) {
  if (len <= 0.0) return 0.0;
  // Break points where the horizon crosses the light's bottom or top edge.
  std::array<double, 4> cut{0.0, len, len, len};
  int n = 1;
  if (k != 0.0)
    for (double e : {e0, e1}) {
      const double t = (e - sigma0) / k;
      if (t > 0.0 && t < len) cut[n++] = t;
    }
  if (n == 3 && cut[1] > cut[2]) std::swap(cut[1], cut[2]);
  cut[n++] = len;
  double sum = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double w = cut[i + 1] - cut[i];
    if (w <= 0.0) continue;
    const double mid = sigma0 + k * 0.5 * (cut[i] + cut[i + 1]);
    if (mid <= e0) {
      sum += w * (std::sin(e1) - std::sin(e0));
    } else if (mid < e1) {
      // ∫ sin(σ) dA over the piece = w·sin(σ_mid)·sinc(k·w/2), stable as k → 0.
      const double h = 0.5 * k * w;
      const double sinc = std::abs(h) < 1e-8 ? 1.0 - h * h / 6.0 : std::sin(h) / h;
      sum += w * (std::sin(e1) - std::sin(mid) * sinc);
    }
  }
  return sum;
}

double rect_norm(const RectLight& l) {
  return (l.azimuth_max - l.azimuth_min) * (std::sin(l.elevation_max) - std::sin(l.elevation_min));
}

}  // namespace

double disc_fraction_above_line(double u) {
  const double c = std::clamp(u, -1.0, 1.0);
  // The blocked part is the circular segment beyond distance u from the centre.
  return 1.0 - (std::acos(c) - c * std::sqrt(1.0 - c * c)) / kPi;
}

double disc_fraction_above_lines(std::span<const DiscLine> lines) {
  if (lines.size() > static_cast<std::size_t>(kMaxDiscLines))
    throw std::invalid_argument("disc_fraction_above_lines: too many lines");
  Polygon poly = bounding_square();
  for (const DiscLine& l : lines) clip(poly, l);
  return std::clamp(disc_polygon_area(poly) / kPi, 0.0, 1.0);
}

double disc_fraction_above_polyline(std::span<const double> x, std::span<const double> y, const DiscLine* extra) {
  const std::size_t n = x.size();
  if (n < 2 || y.size() != n || n > static_cast<std::size_t>(kMaxPolylinePoints))
    throw std::invalid_argument("disc_fraction_above_polyline: need 2…65 points, x and y of equal size");
  if (!(x.front() <= -1.0 && x.back() >= 1.0))
    throw std::invalid_argument("disc_fraction_above_polyline: samples must span [-1, 1]");
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double x0 = x[k], x1 = x[k + 1];
    if (!(x1 > x0)) {
      if (x1 < x0) throw std::invalid_argument("disc_fraction_above_polyline: x must ascend");
      continue;
    }
    if (x1 <= -1.0 || x0 >= 1.0) continue;  // strip misses the disc
    Polygon poly = bounding_square();
    clip(poly, {1.0, 0.0, -x0});  // x ≥ x0
    clip(poly, {-1.0, 0.0, x1});  // x ≤ x1
    clip(poly, above(x0, y[k], (y[k + 1] - y[k]) / (x1 - x0)));
    if (extra) clip(poly, *extra);
    area += disc_polygon_area(poly);
  }
  return std::clamp(area / kPi, 0.0, 1.0);
}

double disc_azimuth_scale(double sun_elevation, double radius) {
  return std::max(std::cos(sun_elevation), std::sin(radius));
}

DiscLine horizon_line(double sun_elevation, double sigma, double slope, double radius) {
  const double m = slope / disc_azimuth_scale(sun_elevation, radius);
  return above(0.0, (sigma - sun_elevation) / radius, m);
}

DiscLine tangent_plane_line(const glm::dvec3& n, double sun_azimuth, double sun_elevation, double radius) {
  const double sa = std::sin(sun_azimuth), ca = std::cos(sun_azimuth);
  const double se = std::sin(sun_elevation), ce = std::cos(sun_elevation);
  // Orthonormal frame at the sun: s, ∂s/∂A / cos e (x), ∂s/∂e (y), in (east, north, up).
  const double ns = n.x * ce * sa + n.y * ce * ca + n.z * se;
  const double nx = n.x * ca - n.y * sa;
  const double ny = -n.x * se * sa - n.y * se * ca + n.z * ce;
  const double len = std::hypot(nx, ny);
  // Great circle at angular distance asin(n·s) from the sun; at its pole no line crosses.
  const double dist = std::asin(std::clamp(ns, -1.0, 1.0)) / radius;
  if (len < 1e-300) return {0.0, 1.0, ns > 0 ? 2.0 : -2.0};
  return {nx / len, ny / len, dist};
}

double sun_disc_fraction(double sun_elevation, double sigma, double slope, double radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("sun_disc_fraction: radius must be > 0");
  return disc_fraction_above_line(horizon_line(sun_elevation, sigma, slope, radius).offset);
}

void validate(const RectLight& l) {
  constexpr double kHalfPi = kPi / 2;
  if (!(l.azimuth_max > l.azimuth_min) || l.azimuth_max - l.azimuth_min > 2 * kPi + 1e-12)
    throw std::invalid_argument("rect light: need azimuth_min < azimuth_max, width ≤ 2π");
  if (!(l.elevation_max > l.elevation_min) || l.elevation_min < -kHalfPi - 1e-12 || l.elevation_max > kHalfPi + 1e-12)
    throw std::invalid_argument("rect light: need −π/2 ≤ elevation_min < elevation_max ≤ π/2");
}

double rect_light_fraction(const RectLight& l, double sigma_centre, double slope) {
  validate(l);
  const double centre = 0.5 * (l.azimuth_min + l.azimuth_max);
  const double sigma0 = sigma_centre + slope * (l.azimuth_min - centre);
  const double v = rect_slab(l.azimuth_max - l.azimuth_min, sigma0, slope, l.elevation_min,
                             l.elevation_max);
  return std::clamp(v / rect_norm(l), 0.0, 1.0);
}

double rect_light_fraction(const RectLight& l, std::span<const double> az, std::span<const double> sigma) {
  validate(l);
  const std::size_t n = az.size();
  if (n < 1 || sigma.size() != n) throw std::invalid_argument("rect light: need ≥ 1 sample, matching sizes");
  for (std::size_t k = 1; k < n; ++k)
    if (az[k] < az[k - 1]) throw std::invalid_argument("rect light: sample azimuths must ascend");
  // Piecewise-linear σ(A), constant beyond the end samples: the piece holding
  // azimuth `mid`, evaluated at `a` (so jumps at repeated azimuths are kept).
  auto horizon = [&](double mid, double a) {
    if (mid <= az[0]) return sigma[0];
    if (mid >= az[n - 1]) return sigma[n - 1];
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(az.begin(), az.end(), mid) - az.begin()) - 1;
    return sigma[k] + (sigma[k + 1] - sigma[k]) * (a - az[k]) / (az[k + 1] - az[k]);
  };
  double sum = 0.0, a = l.azimuth_min;
  std::size_t k = static_cast<std::size_t>(std::upper_bound(az.begin(), az.end(), a) - az.begin());
  while (a < l.azimuth_max) {
    // Next break: the next sample azimuth inside the light, or its edge.
    const double b = k < n ? std::min(az[k], l.azimuth_max) : l.azimuth_max;
    if (b > a) {
      const double mid = 0.5 * (a + b), s0 = horizon(mid, a), s1 = horizon(mid, b);
      sum += rect_slab(b - a, s0, (s1 - s0) / (b - a), l.elevation_min, l.elevation_max);
    }
    a = b;
    ++k;
  }
  return std::clamp(sum / rect_norm(l), 0.0, 1.0);
}

}  // namespace skylit::sky
