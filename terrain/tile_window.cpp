// Per-zoom height windows: the DEM's staged copy warped by GDAL's warper (the
// engine of gdalwarp) onto a zoom's EPSG:3857 pixel grid, through the node-grid
// transformer of terrain/zoom_transform.h.
#include "terrain/tile_window.h"

#include <gdalwarper.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "terrain/gdal_util.h"
#include "terrain/geolocation.h"
#include "terrain/zoom_transform.h"

namespace skylit::terrain {
namespace {

using detail::DatasetPtr;
using detail::GdalErrorCapture;

constexpr std::array<std::pair<Resampling, std::string_view>, 6> kResamplingNames{{
    {Resampling::Nearest, "near"},
    {Resampling::Bilinear, "bilinear"},
    {Resampling::Cubic, "cubic"},
    {Resampling::CubicSpline, "cubicspline"},
    {Resampling::Lanczos, "lanczos"},
    {Resampling::Average, "average"},
}};

// Kernel radius in source pixels at scale 1 (GDAL's warper kernels).
double kernel_radius(Resampling r) {
  switch (r) {
    case Resampling::Nearest: return 1.0;
    case Resampling::Bilinear: return 1.0;
    case Resampling::Cubic: return 2.0;
    case Resampling::CubicSpline: return 2.0;
    case Resampling::Lanczos: return 3.0;
    case Resampling::Average: return 1.0;
  }
  return 3.0;
}

GDALResampleAlg gdal_resampling(Resampling r) {
  switch (r) {
    case Resampling::Nearest: return GRA_NearestNeighbour;
    case Resampling::Bilinear: return GRA_Bilinear;
    case Resampling::Cubic: return GRA_Cubic;
    case Resampling::CubicSpline: return GRA_CubicSpline;
    case Resampling::Lanczos: return GRA_Lanczos;
    case Resampling::Average: return GRA_Average;
  }
  return GRA_Cubic;
}

std::string exact(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

double latitude_rad(double y) { return mercator_to_lon_lat(0.0, y).latitude_deg * std::numbers::pi / 180.0; }

}  // namespace

std::string_view resampling_name(Resampling r) {
  for (const auto& [value, name] : kResamplingNames)
    if (value == r) return name;
  return "cubic";
}

std::optional<Resampling> parse_resampling(std::string_view name) {
  for (const auto& [value, n] : kResamplingNames)
    if (n == name) return value;
  if (name == "nearest") return Resampling::Nearest;
  return std::nullopt;
}

Resampling default_resampling(int zoom, int native) { return zoom >= native ? Resampling::Cubic : Resampling::Average; }

PixelRect TileWindow::tile_rect(const TileId& t) const {
  if (!tiles.contains(t))
    throw std::out_of_range("tile " + std::to_string(t.z) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y) +
                            " is not in this window");
  return {halo + (t.x - tiles.x0) * tile_size, halo + (t.y - tiles.y0) * tile_size, tile_size, tile_size};
}

double TileWindow::max_dy_error() const {
  double e = 0.0;
  for (double d : dy_per_row) e = std::max(e, std::abs(d / field.dy - 1.0));
  return e;
}

std::vector<std::string> WarpSettings::arguments() const {
  return {"-t_srs", "EPSG:3857", "-r", std::string(resampling_name(resampling)), "-et", "0", "-ot", "Float32",
          "-dstnodata", "nan", "-wo", "XSCALE=" + exact(xscale), "-wo", "YSCALE=" + exact(yscale),
          "-wo", "SOURCE_EXTRA=" + std::to_string(source_extra)};
}

struct TileWindowSource::Impl {
  explicit Impl(StagedDem staged) : dem(std::move(staged)), to_dem(dem.outline()) {}
  void warp_into(GDALDataset& out, long long gx0, long long gy0, long long w, long long h, const WarpSettings& s,
                 int zoom, int tile_size) const;

  StagedDem dem;                     // Float32, NaN at voids
  MercatorToDem to_dem;              // the exact transform, made once (PROJ set-up costs ms)
  Curvature curvature;               // of to_dem over the DEM's widened Mercator box
  std::string mercator_wkt;          // EPSG:3857 as WKT2, the windows' CRS
  double centre_latitude = 0.0;      // degrees
  double resolution_x = 0.0, resolution_y = 0.0;  // ground metres per DEM pixel
  int native_256 = 0, native_512 = 0;
};

void check_warpable(const GeoReference& georef) {
  if (georef.crs_wkt.empty())
    throw DemError("the DEM has no CRS, so it cannot be warped to web-map tiles (EPSG:3857); assign one first");
  if (!georef.has_geotransform)
    throw DemError("the DEM has no geotransform, so it cannot be warped to web-map tiles (EPSG:3857)");
}

namespace {
StagedDem checked(StagedDem dem) {
  check_warpable(dem.outline().georef);
  return dem;
}
}  // namespace

TileWindowSource::TileWindowSource(const HeightField& dem) : TileWindowSource(StagedDem::from_field(dem)) {}

TileWindowSource::TileWindowSource(StagedDem staged) : impl_(std::make_unique<Impl>(checked(std::move(staged)))) {
  const HeightField& dem = impl_->dem.outline();
  const std::optional<LatLon> centre = grid_centre_lat_lon(dem.georef, dem.width, dem.height);
  impl_->centre_latitude = centre->latitude_deg;  // present: CRS and geotransform checked above
  impl_->resolution_x = dem.dx(dem.height / 2);
  impl_->resolution_y = dem.dy;
  impl_->native_256 = terrain::native_zoom(dem, 256);
  impl_->native_512 = terrain::native_zoom(dem, 512);

  // The curvature over the DEM's box widened by its size on every side: windows reach
  // past the DEM by their halo and the rest of their edge tiles, and only pixels whose
  // kernel touches the DEM keep a height.
  const MercatorBox b = dem_mercator_bounds(dem);
  const double wx = b.xmax - b.xmin, wy = b.ymax - b.ymin;
  impl_->curvature = impl_->to_dem.curvature({b.xmin - wx, b.ymin - wy, b.xmax + wx, b.ymax + wy});
  OGRSpatialReference mercator;
  mercator.importFromEPSG(3857);
  char* wkt = nullptr;
  const char* wkt_opts[] = {"FORMAT=WKT2_2019", nullptr};
  if (mercator.exportToWkt(&wkt, wkt_opts) != OGRERR_NONE || !wkt) throw DemError("cannot write EPSG:3857 as WKT");
  impl_->mercator_wkt = wkt;
  CPLFree(wkt);
}

const StagedDem& TileWindowSource::dem() const { return impl_->dem; }

// GDAL's warper (the engine of gdalwarp) with the node-grid transformer instead of
// gdalwarp's exact one; the other settings are WarpSettings::arguments()'s.
void TileWindowSource::Impl::warp_into(GDALDataset& out, long long gx0, long long gy0, long long w, long long h,
                                       const WarpSettings& s, int zoom, int tile_size) const {
  const NodeGrid grid(to_dem, zoom, tile_size, s.node_spacing, gx0, gy0, gx0 + w, gy0 + h);
  WindowTransformArg arg{&grid, gx0, gy0};
  GdalErrorCapture capture;
  GDALWarpOptions* wo = GDALCreateWarpOptions();
  wo->hSrcDS = GDALDataset::ToHandle(&dem.dataset());
  wo->hDstDS = GDALDataset::ToHandle(&out);
  wo->nBandCount = 1;
  wo->panSrcBands = static_cast<int*>(CPLMalloc(sizeof(int)));
  wo->panDstBands = static_cast<int*>(CPLMalloc(sizeof(int)));
  wo->panSrcBands[0] = wo->panDstBands[0] = 1;
  wo->eResampleAlg = gdal_resampling(s.resampling);
  wo->eWorkingDataType = GDT_Float32;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  wo->padfDstNoDataReal = static_cast<double*>(CPLMalloc(sizeof(double)));
  wo->padfDstNoDataReal[0] = nan;
  if (dem.has_voids()) {
    wo->padfSrcNoDataReal = static_cast<double*>(CPLMalloc(sizeof(double)));
    wo->padfSrcNoDataReal[0] = nan;
  }
  wo->papszWarpOptions = CSLSetNameValue(wo->papszWarpOptions, "INIT_DEST", "NO_DATA");
  wo->papszWarpOptions = CSLSetNameValue(wo->papszWarpOptions, "XSCALE", exact(s.xscale).c_str());
  wo->papszWarpOptions = CSLSetNameValue(wo->papszWarpOptions, "YSCALE", exact(s.yscale).c_str());
  wo->papszWarpOptions =
      CSLSetNameValue(wo->papszWarpOptions, "SOURCE_EXTRA", std::to_string(s.source_extra).c_str());
  wo->pfnTransformer = window_transform;
  wo->pTransformerArg = &arg;
  GDALWarpOperation op;
  const bool ok = op.Initialize(wo) == CE_None &&
                  op.ChunkAndWarpImage(0, 0, static_cast<int>(w), static_cast<int>(h)) == CE_None;
  GDALDestroyWarpOptions(wo);  // frees the arrays and options, not our transformer
  if (!ok) throw DemError("cannot warp the DEM to zoom " + std::to_string(zoom) + ": " + capture.failure());
}

TileWindowSource::~TileWindowSource() = default;
TileWindowSource::TileWindowSource(TileWindowSource&&) noexcept = default;
TileWindowSource& TileWindowSource::operator=(TileWindowSource&&) noexcept = default;

int TileWindowSource::native_zoom(int tile_size) const {
  (void)pixel_size(0, tile_size);  // validates the tile size
  return tile_size == 512 ? impl_->native_512 : impl_->native_256;
}

WarpSettings TileWindowSource::warp_settings(int zoom, const TileWindowOptions& options) const {
  const double ground = ground_pixel_size(zoom, impl_->centre_latitude, options.tile_size);
  WarpSettings s;
  s.resampling = options.resampling.value_or(default_resampling(zoom, native_zoom(options.tile_size)));
  // One kernel scale per zoom, from the DEM's centre: windows then agree where they
  // overlap (GDAL's own estimate is per chunk). Upsampling keeps the kernel at scale 1.
  s.xscale = std::min(1.0, impl_->resolution_x / ground);
  s.yscale = std::min(1.0, impl_->resolution_y / ground);
  // The warper pads its source window by the kernel radius over its own scale
  // estimate; pad by ours, plus one, so the fixed kernel is never cut short.
  s.source_extra = static_cast<int>(std::ceil(kernel_radius(s.resampling) / std::min(s.xscale, s.yscale))) + 1;
  s.node_spacing = node_spacing(impl_->curvature, pixel_size(zoom, options.tile_size));
  s.node_error_bound_px = node_error_bound(impl_->curvature, pixel_size(zoom, options.tile_size), s.node_spacing);
  return s;
}

TileWindow TileWindowSource::window(const TileRange& tiles, const TileWindowOptions& options) const {
  const int n_side = tiles_per_side(tiles.z);
  const double p = pixel_size(tiles.z, options.tile_size);
  // Columns past the world's east edge (to 2^z·2 − 1) are the next copy of it, where a
  // DEM across the antimeridian continues (tiles_covering).
  if (tiles.empty() || tiles.x0 < 0 || tiles.y0 < 0 || tiles.x0 >= n_side || tiles.x1 >= 2 * n_side ||
      tiles.columns() > n_side || tiles.y1 >= n_side)
    throw std::invalid_argument("tile range " + std::to_string(tiles.x0) + "…" + std::to_string(tiles.x1) + " × " +
                   std::to_string(tiles.y0) + "…" + std::to_string(tiles.y1) + " is empty or outside zoom " +
                   std::to_string(tiles.z) + " (0…" + std::to_string(n_side - 1) + ")");
  if (options.halo < 0) throw std::invalid_argument("negative halo " + std::to_string(options.halo));
  const long long T = options.tile_size, H = options.halo;
  const long long w = tiles.columns() * T + 2 * H, h = tiles.rows() * T + 2 * H;
  constexpr long long kMaxPixels = 1LL << 28;
  if (w * h > kMaxPixels || w > std::numeric_limits<int>::max() || h > std::numeric_limits<int>::max())
    throw std::invalid_argument("tile window " + std::to_string(w) + " × " + std::to_string(h) + " pixels is too large (over " +
                   std::to_string(kMaxPixels) + ")");

  // Global pixel (gx, gy) of the zoom starts at x = −S + gx·p, y = S − gy·p.
  const long long gx0 = tiles.x0 * T - H, gy0 = tiles.y0 * T - H;
  const double s = kWebMercatorOriginShift;
  const double xmin = -s + static_cast<double>(gx0) * p;
  const double ymax = s - static_cast<double>(gy0) * p, ymin = s - static_cast<double>(gy0 + h) * p;

  const WarpSettings settings = warp_settings(tiles.z, options);
  GdalErrorCapture capture;
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  DatasetPtr out(mem ? mem->Create("", static_cast<int>(w), static_cast<int>(h), 1, GDT_Float32, nullptr) : nullptr);
  if (!out) throw DemError("cannot create the in-memory window: " + capture.failure());
  std::array<double, 6> out_gt{xmin, p, 0.0, ymax, 0.0, -p};
  out->SetGeoTransform(out_gt.data());
  out->SetProjection(impl_->mercator_wkt.c_str());
  out->GetRasterBand(1)->SetNoDataValue(std::numeric_limits<double>::quiet_NaN());
  impl_->warp_into(*out, gx0, gy0, w, h, settings, tiles.z, options.tile_size);
  TileWindow win;
  win.tiles = tiles;
  win.tile_size = options.tile_size;
  win.halo = options.halo;
  win.resampling = settings.resampling;
  HeightField& f = win.field;
  f.width = static_cast<int>(w);
  f.height = static_cast<int>(h);
  const std::size_t n = static_cast<std::size_t>(w) * h;
  f.heights.resize(n);
  if (out->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, f.width, f.height, f.heights.data(), f.width, f.height,
                                      GDT_Float32, 0, 0, nullptr) != CE_None)
    throw DemError("cannot read the warped window: " + capture.failure());
  f.valid.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    f.valid[k] = std::isnan(f.heights[k]) ? 0 : 1;
    win.valid_count += f.valid[k];
    if (!f.valid[k]) f.heights[k] = 0.0f;
  }
  if (win.valid_count > 0 && win.valid_count < n) fill_voids(f, options.fill);
  f.nodata = nodata_for_outputs(impl_->dem.outline().nodata, win.valid_count < n);

  f.georef.geotransform = out_gt;
  f.georef.crs_wkt = impl_->mercator_wkt;
  f.georef.geographic = false;
  f.georef.has_geotransform = true;

  // Ground spacing (see the header): row j's centre latitude φ_j gives p·cos φ_j both
  // ways; the single dy is the window's meridian arc on the sphere over its rows.
  f.dx_per_row.resize(f.height);
  for (int j = 0; j < f.height; ++j) {
    const double lat_deg = mercator_to_lon_lat(0.0, ymax - (j + 0.5) * p).latitude_deg;
    f.dx_per_row[j] = ground_pixel_size(tiles.z, lat_deg, options.tile_size);
  }
  win.dy_per_row = f.dx_per_row;
  f.dy = kWebMercatorRadius * (latitude_rad(ymax) - latitude_rad(ymin)) / f.height;
  f.revision = 0;
  f.last_dirty = f.bounds();
  return win;
}

}  // namespace skylit::terrain
