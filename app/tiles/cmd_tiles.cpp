// `skylit tiles DEM... -o OUT`: web-map tiles (XYZ/TMS folder, MBTiles, PMTiles) of a
// shading product or a DEM encoding, per zoom from windows with a halo (docs/tiles.md).
// Every check that can fail is made before the archive is opened, so a bad run leaves
// no output behind.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/common/lighting_args.h"
#include "app/common/progress.h"
#include "app/common/sign_checks.h"
#include "app/shade/hillshade_args.h"
#include "app/tiles/merge_cmd.h"
#include "app/tiles/run_fingerprint.h"
#include "app/tiles/tile_plan.h"
#include "app/tiles/tile_run.h"
#include "app/tiles/web_viewer.h"
#include "gpu/renderer_factory.h"
#include "shading/quality.h"
#include "terrain/dem_reader.h"
#include "tiles/metadata.h"

namespace skylit::app::tiles {
namespace {

namespace st = skylit::tiles;

// Deepest zoom the command renders: 2^24 tiles a side is ~2 cm pixels, beyond any DEM.
constexpr int kMaxCommandZoom = 24;

struct TilesArgs {
  std::vector<std::string> inputs;
  std::string output;
  std::string product = "shaded";
  std::string zoom;  // "A-B" or "Z"; empty: native − 5 … native
  std::string bounds;  // "W,S,E,N"; empty: the whole DEM
  int tile_size = 256;
  std::string resampling;
  std::string format = "png";
  bool tms = false;
  bool xyz = false;  // the default; accepted in gdal2tiles' spelling
  unsigned threads = 0;
  bool quiet = false, resume = false, overwrite = false;
  std::string shard = "1/1";
  std::optional<int> halo;
  std::optional<double> max_distance;
  std::string quality = "default";
  std::string name;
  std::string webviewer = "none";
  double dem_memory_mib = 512;
  std::uint64_t max_tiles = 1'000'000;  // about a day's work on 2 cores: a zoom range past what was meant
  LightingArgs light;
};

// -w leaflet: the page beside a .pmtiles file, or inside a tile folder (as gdal2tiles).
ViewerSpec viewer_spec(const TilesArgs& a, st::ArchiveKind kind, const st::TileMetadata& meta,
                       const terrain::LonLatBox& dem_box, std::string& folder) {
  namespace fs = std::filesystem;
  const fs::path out(a.output);
  ViewerSpec v;
  v.title = meta.name;
  v.kind = kind == st::ArchiveKind::PMTiles ? ViewerSpec::Kind::Pmtiles : ViewerSpec::Kind::Folder;
  v.url = kind == st::ArchiveKind::PMTiles ? out.filename().string() : ".";
  folder = kind == st::ArchiveKind::PMTiles ? (out.has_parent_path() ? out.parent_path().string() : ".") : a.output;
  v.tms = a.tms;
  v.format = std::string(st::format_name(meta.format));
  v.tile_size = a.tile_size;
  v.minzoom = meta.minzoom;
  v.maxzoom = meta.maxzoom;
  // The DEM's own box, whose east runs past 180° across the antimeridian: Leaflet frames
  // it there and asks for the tiles it wraps to.
  const auto e7 = st::at_e7_precision;
  v.bounds = {e7(dem_box.west), e7(dem_box.south), e7(dem_box.east), e7(dem_box.north)};
  v.attribution = "skylit";
  return v;
}

// --zoom as given; nothing when it was not (the DEM's native zoom then sets the range).
std::optional<terrain::ZoomRange> parse_zoom(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto bad = [&](const std::string& why) { return std::invalid_argument("--zoom '" + text + "': " + why); };
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 3 || s.find_first_not_of("0123456789") != std::string::npos)
      throw bad("not Z or A-B (e.g. 8-13)");
    return std::stoi(s);
  };
  const auto dash = text.find('-');
  terrain::ZoomRange r;
  r.min = number(text.substr(0, dash));
  r.max = dash == std::string::npos ? r.min : number(text.substr(dash + 1));
  if (r.max > kMaxCommandZoom) throw bad("zooms run 0…" + std::to_string(kMaxCommandZoom));
  if (r.min > r.max) throw bad("the first zoom is above the second");
  return r;
}

st::OpenMode open_mode(const TilesArgs& a) {
  if (a.resume && a.overwrite) throw std::invalid_argument("give --resume or --overwrite, not both");
  if (a.resume) return st::OpenMode::Resume;
  if (a.overwrite) return st::OpenMode::Overwrite;
  std::error_code ec;
  if (std::filesystem::exists(a.output, ec))
    throw std::invalid_argument("output '" + a.output + "' exists: pass --resume to complete it or --overwrite to replace it");
  return st::OpenMode::Create;
}

// The product or DEM encoding of -p, with what it needs from the light options.
void choose_product(const TilesArgs& a, TileJob& job) {
  if (a.product == "terrain-rgb") job.encoding = terrain::DemEncoding::TerrainRgb;
  else if (a.product == "terrarium") job.encoding = terrain::DemEncoding::Terrarium;
  else if (const auto p = shading::parse_product(a.product); p && *p != shading::Product::Horizon) job.product = p;
  else
    throw std::invalid_argument("unknown -p '" + a.product +
                                "' (shaded, hillshade, skyview, svf, shadow, irradiance, terrain-rgb, terrarium)");
}

// The DEM staged for the warper a strip at a time: in memory, or on disk above
// --dem-memory, so that the run's peak memory does not grow with the DEM.
terrain::StagedDem read_input(const TilesArgs& a) {
  if (a.inputs.empty()) throw std::invalid_argument("no DEM given");
  terrain::cap_gdal_cache_for_streaming();
  terrain::check_warpable(terrain::inspect_dem(a.inputs).georef);  // before the reader asks for a scale
  terrain::StagingOptions staging;
  staging.memory_limit_bytes = static_cast<std::size_t>(a.dem_memory_mib * 1024 * 1024);
  std::vector<std::string> warnings;
  ProgressBar bar("reading the DEM", a.quiet);
  terrain::StagedDem dem = terrain::StagedDem::read(a.inputs, {}, staging, warnings, [&bar](double f) { bar.update(f); });
  bar.finish();
  if (!a.quiet) {
    for (const auto& w : warnings) std::cerr << "skylit: warning: " << w << "\n";
    if (dem.on_disk())
      std::cerr << "skylit: note: the DEM (" << dem.outline().width << "x" << dem.outline().height
                << ") is staged in a temporary file, over --dem-memory " << a.dem_memory_mib << " MiB\n";
  }
  return dem;
}

int run_tiles(const TilesArgs& a) {
  if (a.output.empty()) throw std::invalid_argument("no output given (-o OUT.mbtiles, OUT.pmtiles or a folder)");
  const st::ArchiveKind kind = st::archive_kind(a.output);  // "out.zip" fails here
  if (a.tms && kind != st::ArchiveKind::Folder)
    throw std::invalid_argument("--tms orders a folder's rows; MBTiles rows are TMS and PMTiles XYZ by their specs");
  if (a.webviewer == "leaflet" && kind == st::ArchiveKind::MBTiles)
    throw std::invalid_argument("-w leaflet: a web page cannot read MBTiles; write a .pmtiles file or a folder");
  if (a.format != "png" && a.format != "webp" && a.format != "jpeg" && a.format != "jpg")
    throw std::invalid_argument("--format " + a.format + ": png, webp or jpeg");
  const st::TileFormat format = st::parse_format(a.format);
  if (format == st::TileFormat::Jpeg && (a.product == "terrain-rgb" || a.product == "terrarium"))
    throw std::invalid_argument("-p " + a.product + " encodes heights in the colours: it needs a lossless format "
                                "(--format png or webp), not jpeg");
  st::ArchiveOptions archive_options;
  archive_options.format = format;
  archive_options.mode = open_mode(a);
  archive_options.scheme = a.tms ? st::Scheme::Tms : st::Scheme::Xyz;
  const Shard shard = parse_shard(a.shard);
  TileJob job;
  job.format = format;
  job.tile_size = a.tile_size;
  job.quiet = a.quiet;
  job.threads = a.threads;
  choose_product(a, job);
  if (!a.resampling.empty()) {
    job.resampling = terrain::parse_resampling(a.resampling);
    if (!job.resampling) throw std::invalid_argument("unknown -r '" + a.resampling + "' (near, bilinear, cubic, cubicspline, lanczos, average)");
  }
  shading::LightingRequest request = a.light.request;
  request.sun = !a.light.no_sun;
  bool lit = false;
  if (job.product) {
    shading::apply_quality(*shading::parse_quality(a.quality), job.options);
    job.options.threads = a.threads;
    job.options.shaded.tone = tone_curve(a.light);
    const shading::ProductTraits& t = shading::traits(*job.product);
    lit = t.needs_sun || (t.lit && !sky_only_default(a.light));
    if (lit) shading::validate(request);
    if (t.local)
      job.options.hillshade = shade::hillshade_options({}, 1.0, request.sun_azimuth_deg, request.sun_elevation_deg, true);
  }

  const std::optional<terrain::ZoomRange> given_zooms = parse_zoom(a.zoom);  // before the DEM is read
  const std::optional<terrain::LonLatBox> bounds =
      a.bounds.empty() ? std::nullopt : std::optional(parse_bounds(a.bounds));
  const terrain::TileWindowSource source(read_input(a));  // a DEM without a CRS fails here
  const terrain::HeightField& dem = source.dem().outline();
  const terrain::ZoomRange zooms = given_zooms ? *given_zooms : terrain::default_zoom_range(source.native_zoom(a.tile_size));
  const terrain::LonLatBox ll = terrain::dem_lon_lat_bounds(dem);
  const terrain::MercatorBox box = terrain::dem_mercator_bounds(dem);
  const double poleward = std::max(std::abs(ll.south), std::abs(ll.north));
  // What the tiles show: the DEM's box, or its part within --bounds. Plans and blocks are
  // the whole DEM's either way, so a tile has the same bytes with or without bounds.
  terrain::LonLatBox shown = ll;
  if (bounds) {
    const auto part = bounded_box(ll, *bounds);
    if (!part) {
      char text[160];
      std::snprintf(text, sizeof text, "the DEM (lon %.4f…%.4f, lat %.4f…%.4f) does not overlap --bounds %s",
                    ll.west, ll.east > 180.0 ? ll.east - 360.0 : ll.east, ll.south, ll.north, a.bounds.c_str());
      throw std::invalid_argument(text);
    }
    shown = *part;
  }
  std::vector<ZoomPlan> plans;
  std::vector<Block> all;
  for (int z = zooms.min; z <= zooms.max; ++z) {
    plans.push_back(plan_zoom(box, poleward, z, a.tile_size, {a.halo, a.max_distance}));
    const auto b = blocks(plans.back(), a.tile_size);
    all.insert(all.end(), b.begin(), b.end());
  }
  if (bounds) all = within(all, shown);
  std::uint64_t tile_count = 0;
  for (const Block& b : all) tile_count += static_cast<std::uint64_t>(b.wanted.count());
  if (tile_count > a.max_tiles)
    throw std::invalid_argument("zooms " + std::to_string(zooms.min) + "-" + std::to_string(zooms.max) + " cover the DEM with " +
                                std::to_string(tile_count) + " tiles, over --max-tiles " + std::to_string(a.max_tiles) +
                                " (its native zoom is " + std::to_string(source.native_zoom(a.tile_size)) +
                                "); raise --max-tiles to render them");
  const std::vector<Block> mine = shard_blocks(all, shard);
  if (source.dem().valid_count() == 0) throw std::invalid_argument("nothing to render: the DEM has no valid heights");
  if (mine.empty())
    throw std::invalid_argument("nothing to render: shard " + a.shard + " gets none of the " + std::to_string(all.size()) +
                                " window blocks; use fewer shards");
  if (lit) {
    const auto resolved = shading::resolve_lighting(request, shading::needs_place(request) ? dem_place(source.dem()) : std::nullopt);
    job.options.lighting = resolved.lighting;
    if (!a.quiet) std::cerr << "skylit: " << resolved.summary << "\n";
  }
  std::unique_ptr<shading::Renderer> renderer;
  if (job.product) {
    renderer = gpu::make_renderer(gpu::Backend::Auto, [&a](const std::string& note) {
      if (!a.quiet) std::cerr << "skylit: note: " << note << "\n";
    });
    if (const auto why = renderer->lacks(*job.product, job.options)) throw std::invalid_argument(*why);
  }
  const bool horizons = job.product && !shading::traits(*job.product).local;  // else no halo to report
  if (!a.quiet) {
    std::cerr << "skylit: zooms " << zooms.min << "-" << zooms.max << " (native " << source.native_zoom(a.tile_size)
              << "), " << mine.size() << " of " << all.size() << " window blocks (shard " << shard.index << "/"
              << shard.count << ")" << (horizons ? "; halo and horizon distance:" : "");
    for (const ZoomPlan& p : plans)
      if (horizons) std::cerr << " z" << p.z << " " << p.halo << " px " << std::lround(p.max_distance_m) << " m;";
    std::cerr << "\n";
  }

  st::TileMetadata meta;
  meta.name = a.name.empty() ? std::filesystem::path(a.inputs.front()).stem().string() + " " + a.product : a.name;
  meta.format = format;
  const auto e7 = st::at_e7_precision;
  // Across the antimeridian the archive's W,S,E,N box (which cannot wrap) spans every
  // longitude, as mapbox-gl clamps such bounds; the centre is the DEM's.
  const bool wraps = shown.east > 180.0;
  const double mid = 0.5 * (shown.west + shown.east), centre_lon = mid >= 180.0 ? mid - 360.0 : mid;
  meta.bounds = {wraps ? -180.0 : e7(shown.west), e7(shown.south), wraps ? 180.0 : e7(shown.east), e7(shown.north)};
  meta.center = {e7(centre_lon), e7(0.5 * (shown.south + shown.north)), zooms.min};
  meta.minzoom = zooms.min;
  meta.maxzoom = zooms.max;
  meta.description = "skylit tiles -p " + a.product;
  RunOptions run{a.inputs, a.product, a.quality, a.resampling, a.light.tone, request, zooms, a.tile_size,
                 format, a.tms, plans, bounds};
  meta.fingerprint = archive_options.fingerprint = run_fingerprint(run);
  st::validate(meta);

  LazyArchive archive(a.output, archive_options);
  const RunCounts n = render_blocks(source, plans, mine, job, renderer.get(), archive);
  if (!archive.opened())
    throw std::invalid_argument("nothing to render: the " + std::to_string(n.empty) + " tiles of shard " + a.shard +
                                " lie outside the DEM's valid pixels");
  archive.finish(meta);
  if (a.webviewer == "leaflet") {
    std::string folder;
    const ViewerSpec spec = viewer_spec(a, kind, meta, shown, folder);
    write_leaflet_viewer(folder, spec);
    if (!a.quiet) std::cerr << "skylit: wrote " << (std::filesystem::path(folder) / "index.html").string() << "\n";
  }
  if (!a.quiet)
    std::cerr << "skylit: wrote " << a.output << ": " << n.written << " tiles (" << n.skipped
              << " already complete, " << n.empty << " outside the DEM)"
              << (renderer ? ", computed on " + renderer->description() : std::string()) << "\n";
  return 0;
}

}  // namespace

void add_tiles_command(CLI::App& root, Action& run) {
  auto a = std::make_shared<TilesArgs>();
  auto* cmd = root.add_subcommand("tiles", "Web-map tiles (XYZ/TMS folder, MBTiles, PMTiles) of a shading product "
                                           "or Terrain-RGB/Terrarium heights (docs/tiles.md)");
  cmd->add_option("DEM", a->inputs, "DEM raster(s) with a CRS (several are mosaicked)");
  cmd->add_option("-o,--output", a->output, "OUT.mbtiles, OUT.pmtiles, or a folder OUT/{z}/{x}/{y}.png");
  cmd->add_option("-p,--product", a->product,
                  "shaded | hillshade | skyview | svf | shadow | irradiance | terrain-rgb | terrarium")
      ->capture_default_str();
  cmd->add_option("-z,--zoom", a->zoom, "Zoom Z or range A-B, 0..24 (default: native-5 .. native)");
  cmd->add_option("--bounds", a->bounds,
                  "Only the tiles over this WGS 84 box W,S,E,N in degrees (W > E: across the antimeridian); "
                  "they equal the whole run's tiles byte for byte");
  cmd->add_option("--tile-size,--tilesize", a->tile_size, "Tile side in pixels")
      ->check(CLI::IsMember({256, 512}))->capture_default_str();
  cmd->add_option("-r,--resampling", a->resampling,
                  "DEM resampling onto each zoom: near | bilinear | cubic | cubicspline | lanczos | average "
                  "(default: cubic at and above the native zoom, average below)");
  cmd->add_option("--format", a->format,
                  "Tile image format: png | webp (lossless, with alpha) | jpeg (quality 90, no alpha: outside the "
                  "DEM white; for opaque base maps)")
      ->capture_default_str();
  auto* tms = cmd->add_flag("--tms", a->tms, "Folder rows in TMS order (y from the south) instead of XYZ");
  cmd->add_flag("--xyz", a->xyz, "Folder rows in XYZ order (y from the north): the default, as gdal2tiles --xyz")->excludes(tms);
  cmd->add_option("--halo", a->halo, "Window halo in pixels (default: from --max-distance, docs/tiles.md)");
  cmd->add_option("--max-distance", a->max_distance,
                  "Horizon search distance in ground metres (default 5000, or what --halo holds)")
      ->check(app::positive_number());
  cmd->add_option("--shard", a->shard, "Render shard i of N (1-based, i/N): a cost-balanced share of the window blocks")
      ->capture_default_str();
  cmd->add_option("--quality", a->quality, "Preset: fast | default | high (docs/quality-presets.md)")
      ->check(CLI::IsMember({"fast", "default", "high"}))->capture_default_str();
  add_lighting_options(*cmd, a->light,
                       "Sun position for this ISO 8601 time with a zone, e.g. 2026-06-21T09:30:00Z (place: the "
                       "DEM's centre, or --lat/--lon); one time, not a series");
  cmd->add_option("--name", a->name, "Archive name in its metadata (default: the DEM's file name and the product)");
  cmd->add_option("--threads", a->threads, "Worker threads of the CPU renderer and the tile encoder (0: all cores)")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_option("-w,--webviewer", a->webviewer,
                  "leaflet: an index.html showing the tiles on a Leaflet map (beside a .pmtiles file, inside a "
                  "folder; Leaflet and pmtiles.js inlined) | none")
      ->check(CLI::IsMember({"none", "leaflet"}))->capture_default_str();
  cmd->add_option("--dem-memory", a->dem_memory_mib,
                  "Largest DEM copy held in memory, MiB; a larger DEM is staged in a temporary GeoTIFF in $TMPDIR "
                  "(4 B a pixel, deleted once open) and read a block at a time")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_option("--max-tiles", a->max_tiles,
                  "Most tiles the pyramid may cover (all shards together): a zoom range past it is refused")
      ->capture_default_str();
  cmd->add_flag("-e,--resume", a->resume, "Complete an interrupted run: keep its finished tiles");
  cmd->add_flag("--overwrite", a->overwrite, "Replace OUT if it exists");
  cmd->add_flag("-q,--quiet", a->quiet, "No progress or notes");
  CLI::App* merge = add_merge_subcommand(*cmd, run);
  cmd->callback([&run, a, merge] {
    if (merge->parsed()) return;  // `skylit tiles merge …` set its own action
    run = [a] { return run_tiles(*a); };
  });
}

}  // namespace skylit::app::tiles
