// The exact EPSG:3857 → DEM transform and its node-grid approximation (see the header).
#include "terrain/zoom_transform.h"

#include <gdal_alg.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "terrain/dem_reader.h"

namespace skylit::terrain {

struct MercatorToDem::Impl {
  std::unique_ptr<OGRCoordinateTransformation> forward, inverse;
  std::array<double, 6> gt{}, inv_gt{};
  bool geographic = false;
  double centre_longitude = 0.0;  // degrees as the DEM stores them (geographic DEMs)
  double centre_x = 0.0;          // 3857 metres of the DEM's centre, on its side of the antimeridian
};

MercatorToDem::MercatorToDem(const HeightField& field) : impl_(std::make_unique<Impl>()) {
  const GeoReference& dem = field.georef;
  if (dem.crs_wkt.empty() || !dem.has_geotransform)
    throw DemError("the DEM has no CRS or geotransform, so EPSG:3857 pixels cannot be placed on it");
  OGRSpatialReference mercator, source;
  mercator.importFromEPSG(3857);
  if (source.importFromWkt(dem.crs_wkt.c_str()) != OGRERR_NONE) throw DemError("the DEM's CRS cannot be parsed");
  // x = easting or longitude, as the geotransform (and gdalwarp) order them.
  mercator.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  impl_->forward.reset(OGRCreateCoordinateTransformation(&mercator, &source));
  impl_->inverse.reset(OGRCreateCoordinateTransformation(&source, &mercator));
  if (!impl_->forward || !impl_->inverse) throw DemError("PROJ has no transformation from EPSG:3857 to the DEM's CRS");
  impl_->gt = dem.geotransform;
  if (!GDALInvGeoTransform(impl_->gt.data(), impl_->inv_gt.data()))
    throw DemError("the DEM's geotransform cannot be inverted");
  const auto& g = impl_->gt;
  impl_->geographic = dem.geographic;
  impl_->centre_longitude = g[0] + 0.5 * field.width * g[1] + 0.5 * field.height * g[2];
  const LonLatBox box = dem_lon_lat_bounds(field);
  impl_->centre_x = lon_lat_to_mercator(0.5 * (box.west + box.east), 0.0).x;
}

MercatorToDem::~MercatorToDem() = default;
MercatorToDem::MercatorToDem(MercatorToDem&&) noexcept = default;
MercatorToDem& MercatorToDem::operator=(MercatorToDem&&) noexcept = default;

void MercatorToDem::to_source(std::size_t n, double* x, double* y, int* ok) const {
  if (n == 0) return;
  if (!impl_->forward->Transform(n, x, y, nullptr, ok)) std::fill(ok, ok + n, 0);
  const auto& g = impl_->inv_gt;
  for (std::size_t k = 0; k < n; ++k) {
    // PROJ returns longitudes in −180…180°; a DEM in degrees may store them past 180°.
    if (impl_->geographic) x[k] += 360.0 * std::round((impl_->centre_longitude - x[k]) / 360.0);
    const double gx = x[k], gy = y[k];
    x[k] = g[0] + gx * g[1] + gy * g[2];
    y[k] = g[3] + gx * g[4] + gy * g[5];
  }
}

void MercatorToDem::to_mercator(std::size_t n, double* x, double* y, int* ok) const {
  if (n == 0) return;
  const auto& g = impl_->gt;
  for (std::size_t k = 0; k < n; ++k) {
    const double px = x[k], py = y[k];
    x[k] = g[0] + px * g[1] + py * g[2];
    y[k] = g[3] + px * g[4] + py * g[5];
  }
  if (!impl_->inverse->Transform(n, x, y, nullptr, ok)) std::fill(ok, ok + n, 0);
  const double world = 2.0 * kWebMercatorOriginShift;
  for (std::size_t k = 0; k < n; ++k) x[k] += world * std::round((impl_->centre_x - x[k]) / world);
}

Curvature MercatorToDem::curvature(const MercatorBox& box) const {
  constexpr int kSamples = 9;
  const double hx = (box.xmax - box.xmin) / 16.0, hy = (box.ymax - box.ymin) / 16.0;
  // Per sample: the centre and its four neighbours at ±h (5 points).
  std::vector<double> x, y;
  for (int j = 0; j < kSamples; ++j)
    for (int i = 0; i < kSamples; ++i) {
      const double cx = box.xmin + (box.xmax - box.xmin) * i / (kSamples - 1);
      const double cy = box.ymin + (box.ymax - box.ymin) * j / (kSamples - 1);
      for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, {-hx, 0.0}, {hx, 0.0}, {0.0, -hy}, {0.0, hy}}) {
        x.push_back(cx + dx);
        y.push_back(cy + dy);
      }
    }
  std::vector<int> ok(x.size());
  to_source(x.size(), x.data(), y.data(), ok.data());
  Curvature c;
  for (std::size_t s = 0; s < x.size(); s += 5) {
    if (!std::all_of(&ok[s], &ok[s] + 5, [](int v) { return v != 0; })) continue;
    for (const std::vector<double>* f : {&x, &y}) {
      const auto& v = *f;
      if (hx > 0) c.xx = std::max(c.xx, std::abs(v[s + 1] - 2 * v[s] + v[s + 2]) / (hx * hx));
      if (hy > 0) c.yy = std::max(c.yy, std::abs(v[s + 3] - 2 * v[s] + v[s + 4]) / (hy * hy));
    }
  }
  return c;
}

double node_error_bound(const Curvature& c, double p, int spacing) {
  if (spacing <= 1) return 0.0;  // every point exact
  const double n = spacing;
  return n * n / 8.0 * (c.xx + c.yy) * p * p;
}

int node_spacing(const Curvature& c, double p) {
  int n = kMaxNodeSpacing;
  while (n > 1 && node_error_bound(c, p, n) > kNodeTolerancePx) n /= 2;
  return n;
}

namespace {
long long floor_div(long long a, long long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
}  // namespace

NodeGrid::NodeGrid(const MercatorToDem& exact, int zoom, int tile_size, int spacing, long long gx0, long long gy0,
                   long long gx1, long long gy1)
    : exact_(&exact), p_(pixel_size(zoom, tile_size)), spacing_(spacing) {
  if (spacing_ <= 1) return;  // exact per point: no nodes
  // One node beyond each side: a pixel centre at gx1 + 0.5 still has both its nodes cached.
  i0_ = floor_div(gx0, spacing) - 1;
  j0_ = floor_div(gy0, spacing) - 1;
  ni_ = floor_div(gx1, spacing) + 2 - i0_ + 1;
  nj_ = floor_div(gy1, spacing) + 2 - j0_ + 1;
  const std::size_t n = static_cast<std::size_t>(ni_) * nj_;
  std::vector<double> x(n), y(n);
  std::vector<int> ok(n);
  for (long long j = 0; j < nj_; ++j)
    for (long long i = 0; i < ni_; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * ni_ + i);
      x[k] = -kWebMercatorOriginShift + static_cast<double>((i0_ + i) * spacing_) * p_;
      y[k] = kWebMercatorOriginShift - static_cast<double>((j0_ + j) * spacing_) * p_;
    }
  exact.to_source(n, x.data(), y.data(), ok.data());
  nodes_.resize(n);
  for (std::size_t k = 0; k < n; ++k) nodes_[k] = {x[k], y[k], ok[k] != 0};
}

NodeGrid::Node NodeGrid::node(long long i, long long j) const {
  if (i >= i0_ && i < i0_ + ni_ && j >= j0_ && j < j0_ + nj_) return nodes_[static_cast<std::size_t>((j - j0_) * ni_ + (i - i0_))];
  // The same arithmetic as the cache, so the answer does not depend on the window.
  double x = -kWebMercatorOriginShift + static_cast<double>(i * spacing_) * p_;
  double y = kWebMercatorOriginShift - static_cast<double>(j * spacing_) * p_;
  int ok = 0;
  exact_->to_source(1, &x, &y, &ok);
  return {x, y, ok != 0};
}

NodeGrid::Cell NodeGrid::cell(long long i, long long j) const {
  Cell c{i, j, node(i, j), node(i + 1, j), node(i, j + 1), node(i + 1, j + 1), false};
  c.ok = c.a.ok && c.b.ok && c.c.ok && c.d.ok;
  return c;
}

// One formula for source() and sources(), so both give the same bits.
void NodeGrid::locate(double gx, double gy, long long& i, long long& j, double& fx, double& fy) const {
  // Division by a power of two and the subtraction are exact: fx, fy are the same
  // bits in every window.
  const double tx = gx / spacing_, ty = gy / spacing_;
  const double fi = std::floor(tx), fj = std::floor(ty);
  fx = tx - fi;
  fy = ty - fj;
  i = static_cast<long long>(fi);
  j = static_cast<long long>(fj);
}

void NodeGrid::interpolate(const Cell& c, double fx, double fy, double& sx, double& sy) {
  sx = (1 - fy) * ((1 - fx) * c.a.x + fx * c.b.x) + fy * ((1 - fx) * c.c.x + fx * c.d.x);
  sy = (1 - fy) * ((1 - fx) * c.a.y + fx * c.b.y) + fy * ((1 - fx) * c.c.y + fx * c.d.y);
}

bool NodeGrid::source(double gx, double gy, double& sx, double& sy) const {
  // Spacing 1: the curvature is too high for interpolation between pixels (low zooms of
  // fine DEMs, whose windows are small), so every point is exact.
  if (spacing_ <= 1) return exact_source(gx, gy, sx, sy);
  long long i = 0, j = 0;
  double fx = 0, fy = 0;
  locate(gx, gy, i, j, fx, fy);
  const Cell c = cell(i, j);
  if (c.ok) interpolate(c, fx, fy, sx, sy);
  return c.ok;
}

void NodeGrid::sources(std::size_t n, double* x, double* y, int* ok, double offset_x, double offset_y) const {
  std::optional<Cell> c;  // the warper asks row by row: consecutive points share a cell
  for (std::size_t k = 0; k < n; ++k) {
    const double gx = offset_x + x[k], gy = offset_y + y[k];
    if (spacing_ <= 1) {
      ok[k] = exact_source(gx, gy, x[k], y[k]);
      continue;
    }
    long long i = 0, j = 0;
    double fx = 0, fy = 0;
    locate(gx, gy, i, j, fx, fy);
    if (!c || c->i != i || c->j != j) c = cell(i, j);
    ok[k] = c->ok;
    if (c->ok) interpolate(*c, fx, fy, x[k], y[k]);
  }
}

bool NodeGrid::exact_source(double gx, double gy, double& sx, double& sy) const {
  sx = -kWebMercatorOriginShift + gx * p_;
  sy = kWebMercatorOriginShift - gy * p_;
  int ok = 0;
  exact_->to_source(1, &sx, &sy, &ok);
  return ok != 0;
}

bool NodeGrid::global_pixel(double sx, double sy, double& gx, double& gy) const {
  int ok = 0;
  exact_->to_mercator(1, &sx, &sy, &ok);
  gx = (sx + kWebMercatorOriginShift) / p_;
  gy = (kWebMercatorOriginShift - sy) / p_;
  return ok != 0;
}

int window_transform(void* arg, int dst_to_src, int n, double* x, double* y, double* /*z*/, int* ok) {
  const auto& w = *static_cast<const WindowTransformArg*>(arg);
  if (dst_to_src) {  // the warper's pixels → the DEM: the approximation
    w.grid->sources(static_cast<std::size_t>(n), x, y, ok, static_cast<double>(w.gx0), static_cast<double>(w.gy0));
    return TRUE;
  }
  for (int k = 0; k < n; ++k) {  // the DEM → the window's pixels, exact (not on the per-pixel path)
    double gx = 0, gy = 0;
    ok[k] = w.grid->global_pixel(x[k], y[k], gx, gy) ? TRUE : FALSE;
    if (!ok[k]) continue;
    x[k] = gx - static_cast<double>(w.gx0);
    y[k] = gy - static_cast<double>(w.gy0);
  }
  return TRUE;  // per-point failures are in ok[]; the call itself succeeded
}

}  // namespace skylit::terrain
