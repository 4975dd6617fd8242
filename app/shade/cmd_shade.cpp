// `skylit shade INPUT... -o OUTPUT`: the DEM hillshade/export tool. Reads DEMs
// (or the built-in synthetic scene), computes one product, and writes it
// georeferenced — atomically, so a failed run leaves no file. Lighting (time, place,
// sky, sun) is resolved before any computation, so its errors cost nothing.
#include "app/commands.h"
#include "app/common/progress.h"
#include "app/common/sign_checks.h"
#include "app/shade/blocked_shade.h"
#include "app/shade/color_relief_cmd.h"
#include "app/shade/hillshade_args.h"
#include "app/shade/max_error.h"
#include "app/shade/shade_output.h"
#include "app/shade/tinted_relief.h"
#include "app/shade/shade_series.h"
#include "app/shade/sphere_input.h"
#include "app/shade/tracked_aircraft.h"
#include "app/common/altitude_arg.h"
#include "app/common/lighting_args.h"
#include "shading/blocker_frame.h"
#include "gpu/renderer_factory.h"
#include "gpu/timer.h"

#include "shading/horizon/horizon_sweep.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/quality.h"
#include "shading/reference_pipeline.h"
#include "shading/summed_products.h"
#include "shading/time_series.h"
#include "terrain/dem_reader.h"
#include "terrain/geolocation.h"
#include "terrain/synthetic.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace skylit::app::shade {
namespace {

struct ShadeArgs {
  std::vector<std::string> inputs;
  std::string output;
  bool synthetic = false;
  std::uint64_t seed = 1;
  int size = 512;
  std::string product = "shaded";
  std::string format;
  std::vector<std::string> creation_options;
  double z_factor = 1.0;
  int band = 1;
  std::optional<double> nodata;
  std::optional<double> scale, xscale, yscale;
  shading::ProductOptions options;  // defaults come from the library
  std::string quality = "default";
  std::optional<double> max_error;  // --max-error E: the front picks the knobs
  std::string shading_mode = "table";
  std::string wedge = "linear";
  std::string levels{horizon::level_sampling_name(horizon::level_sampling(horizon::MarchOptions{}))};
  std::string horizon_max{horizon::horizon_max_name(horizon::MarchOptions{}.smooth_max)};
  std::string horizons{horizon::horizon_method_name(horizon::MarchOptions{}.method)};
  bool horizons_given = false;  // --horizons on the command line (the fallback note is for it)
  bool no_curvature = false;
  std::string backend = gpu::backend_names().front();
  unsigned threads = 0;
  bool quiet = false;
  bool overwrite = false;
  bool compute_edges = false;  // horizon products always compute edges; local ones follow gdaldem
  HillshadeArgs hillshade;
  std::string tint_blend = "multiply:0.75";
  ColorReliefArgs color;  // -p color-relief: --color, --alpha, --exact/--nearest-color-entry
  bool timings = false;
  LightingArgs light;  // --time, the sun, the sky, --no-sun, --tone
  std::size_t max_frames = shading::kDefaultMaxFrames;
  double sun_tolerance_deg = shading::kFrameSunTolerance * 180.0 / std::numbers::pi;  // --sun-tolerance
  std::string spheres;  // --spheres FILE.csv
  std::string track;    // --track FILE
  std::string aircraft = "glider";
  std::string altitude = "gnss";
  std::string block_size = "auto";  // --block-size N|auto
};

// `--timings`: where the wall time went, one stage a line (stderr). The GPU stages come
// from the renderer (shading/renderer.h FrameTimings says which clock each uses).
void print_timings(double read_ms, const shading::Renderer& renderer, double write_ms) {
  const shading::FrameTimings& t = renderer.last_timings();
  auto line = [](const char* stage, double ms) { std::fprintf(stderr, "skylit: time %-28s %9.1f ms\n", stage, ms); };
  line("read DEM", read_ms);
  if (renderer.on_gpu()) {
    line("OpenGL context", t.context_ms);
    line("compile kernels", t.compile_ms);
    line("upload heights", t.upload_ms);
    line("pyramid build", t.pyramid_ms);
    line("horizon sweep", t.sweep_ms);
    // Mesa llvmpipe runs compute outside its timer queries (they read ≈ 0): then only the
    // stages' sum is known, inside "compute".
    if (t.sun_ms + t.march_ms + t.products_ms > 1e-3 * t.frame_ms) {
      line("sun shadow (GPU timer)", t.sun_ms);
      line("march (GPU timer)", t.march_ms);
      line("surface products (GPU timer)", t.products_ms);
    } else {
      std::fprintf(stderr, "skylit: time %-28s %12s\n", "sun, march, products", "(no GPU timer on this driver)");
    }
  }
  line(renderer.on_gpu() ? "compute (all GPU stages)" : "compute (CPU reference)",
       t.frame_ms - t.compile_ms);
  line("write output", write_ms);
}

// --backend's value, checked before any work.
gpu::Backend parse_backend_arg(const std::string& name) {
  if (const auto backend = gpu::parse_backend(name)) return *backend;
  std::string known;
  for (const auto& b : gpu::backend_names()) known += (known.empty() ? "" : ", ") + b;
  throw std::invalid_argument("--backend '" + name + "' is not available; this build has: " + known);
}

std::unique_ptr<shading::Renderer> make_shade_renderer(gpu::Backend backend, bool quiet) {
  try {
    return gpu::make_renderer(backend, [quiet](const std::string& note) {
      if (!quiet) std::cerr << "skylit: note: " << note << "\n";
    });
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("--backend " + std::string(gpu::backend_name(backend)) + ": " + e.what());
  }
}

// How the DEM is read: -b, --nodata, the scales and z (1 for local products, which
// apply z inside their formula as gdaldem does).
terrain::DemReadOptions dem_read_options(const ShadeArgs& a, double z_factor) {
  terrain::DemReadOptions opt;
  opt.scale = a.scale;
  opt.xscale = a.xscale;
  opt.yscale = a.yscale;
  opt.z_factor = z_factor;
  opt.band = a.band;
  opt.nodata = a.nodata;
  return opt;
}

terrain::HeightField load_input(const ShadeArgs& a, double z_factor) {
  if (a.synthetic) {
    if (!a.inputs.empty()) throw std::invalid_argument("give either INPUT files or --synthetic, not both");
    terrain::SyntheticOptions opt;
    opt.width = opt.height = a.size;
    opt.seed = a.seed;
    return terrain::make_synthetic_terrain(opt);
  }
  if (a.inputs.empty()) throw std::invalid_argument("no INPUT DEM given (or use --synthetic for the built-in scene)");
  const terrain::DemReadOptions opt = dem_read_options(a, z_factor);
  auto result = a.inputs.size() == 1 ? terrain::read_dem(a.inputs.front(), opt) : terrain::read_dem(a.inputs, opt);
  if (!a.quiet)
    for (const auto& w : result.warnings) std::cerr << "skylit: warning: " << w << "\n";
  return std::move(result.field);
}

std::vector<std::string> level_sampling_names() {
  std::vector<std::string> names;
  for (horizon::LevelSampling l : horizon::all_level_samplings()) names.emplace_back(horizon::level_sampling_name(l));
  return names;
}

std::vector<std::string> horizon_method_names() {
  std::vector<std::string> names;
  for (horizon::HorizonMethod m : horizon::all_horizon_methods()) names.emplace_back(horizon::horizon_method_name(m));
  return names;
}

// Why `--horizons sweep` marches on this field ("" when it sweeps or was not asked
// for), with the conditions of shading::uses_sweep. The default sweep falls back quietly.
std::string sweep_fallback_note(const terrain::HeightField& field, const shading::ProductOptions& o, bool asked) {
  if (!asked || o.march.method != horizon::HorizonMethod::Sweep || shading::uses_sweep(field, o)) return "";
  if (o.exact) return "--horizons sweep with --exact: the exact march runs instead";
  return "--horizons sweep: " + horizon::sweep_inapplicable_reason(field, o.march) + "; the march runs instead";
}

// Upper bound of a multi-band series file held in memory before it is written.
constexpr std::size_t kMaxSeriesFileBytes = std::size_t{4} << 30;

// The frames of --time when it is a series (an interval, a list of several times, a
// date) or the product is a sum over time; nullopt for a single time or none.
std::optional<shading::TimeSpec> series_spec(const ShadeArgs& a, const std::optional<shading::SummedProduct>& summed) {
  if (a.light.request.time.empty()) {
    if (summed)
      throw std::invalid_argument("-p " + a.product + " sums over time: give --time as an interval "
                                  "(2026-06-21T04:00Z/2026-06-21T20:00Z/PT10M), a list of times or a date (2026-06-21)");
    return std::nullopt;
  }
  shading::TimeSeriesOptions o;
  o.max_frames = a.max_frames;
  shading::TimeSpec spec;
  try {
    spec = shading::parse_time_spec(a.light.request.time, o);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--time: " + std::string(e.what()) +
                                (std::string(e.what()).find("frames") != std::string::npos ? " (raise --max-frames)" : ""));
  }
  if (!spec.date && spec.instants.size() == 1) {
    if (summed) throw std::invalid_argument("-p " + a.product + " sums over time: one --time is no interval");
    return std::nullopt;
  }
  if (a.light.request.sun_azimuth_deg || a.light.request.sun_elevation_deg)
    throw std::invalid_argument("a --time series moves the sun: give no --sun-azimuth or --sun-elevation");
  return spec;
}

// The place of a series' sun: --lat/--lon, else the DEM's centre.
std::optional<sky::Observer> series_place(const ShadeArgs& a, const terrain::HeightField& field) {
  if (a.light.request.latitude_deg && a.light.request.longitude_deg)
    return sky::Observer{*a.light.request.latitude_deg, *a.light.request.longitude_deg, a.light.request.height_m};
  auto place = dem_place(field);
  if (!place) throw std::invalid_argument("--time needs the DEM's location, but the DEM has no CRS: give --lat and --lon");
  return place;
}

// A frame's blockers at time t (UTC seconds): the static spheres and the aircraft flying then.
std::vector<blockers::Sphere> spheres_at(const std::vector<blockers::Sphere>& spheres,
                                         const std::optional<TrackedAircraft>& aircraft, double t) {
  std::vector<blockers::Sphere> all = spheres;
  if (aircraft) {
    const auto flying = aircraft->spheres_at(t);
    all.insert(all.end(), flying.begin(), flying.end());
  }
  return all;
}

int run_shade_series(const ShadeArgs& a, const shading::TimeSpec& times, shading::Product product,
                     const std::optional<shading::SummedProduct>& summed, const shading::LightingRequest& request,
                     const terrain::HeightField& field, const shading::ProductOptions& opt,
                     OutputSpec summed_out, const std::vector<blockers::Sphere>& spheres,
                     const std::optional<TrackedAircraft>& aircraft, shading::Renderer& renderer) {
  SeriesJob job;
  if (!spheres.empty() || aircraft)
    job.spheres_at = [&spheres, &aircraft](double t) { return spheres_at(spheres, aircraft, t); };
  job.product = product;
  job.summed = summed;
  job.request = request;
  job.place = series_place(a, field);
  job.quiet = a.quiet;
  job.timings = a.timings;
  const shading::TimeSeries series = shading::resolve_time_series(times, job.place);
  if (!series.note.empty() && !a.quiet) std::cerr << "skylit: note: " << series.note << "\n";
  if (series.instants.empty() && !summed)
    throw std::invalid_argument("--time " + a.light.request.time + ": no frames (" + series.note + ")");
  job.instants = series.instants;
  if (summed) {
    job.outputs.files.push_back(std::move(summed_out));
  } else {
    const std::size_t bands = shading::traits(product).rgb_when_colour ? 3 : 1;  // at most: colour
    job.outputs = resolve_frame_outputs(a.output, a.format, product, a.creation_options, a.overwrite,
                                        static_cast<int>(job.instants.size()), field.size() * bands * sizeof(float),
                                        kMaxSeriesFileBytes);
  }
  if (!a.quiet && !job.instants.empty())  // none: a polar night's sum, whose note said so
    std::cerr << "skylit: " << job.instants.size() << " times from " << sky::format_utc_time(job.instants.front())
              << " to " << sky::format_utc_time(job.instants.back()) << "\n";
  shading::ProductOptions frame_opt = opt;
  frame_opt.lighting = shading::Lighting{};  // lit: the renderer's check sees a lit product
  if (const auto why = renderer.lacks(product, frame_opt))
    throw std::invalid_argument("--backend " + a.backend + (opt.exact ? " with --exact: " : ": ") + *why +
                                "; use --backend reference (or auto)");
  renderer.set_field(field);
  renderer.set_options(opt);
  renderer.set_sun_heading_tolerance(a.sun_tolerance_deg * std::numbers::pi / 180.0);
  run_series(renderer, field, job);
  return 0;
}

// --block-size: a core side, or nothing for auto.
std::optional<int> parse_block_size(const std::string& text) {
  if (text == "auto") return std::nullopt;
  std::size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty()) throw std::invalid_argument("--block-size '" + text + "' is not a number of texels or auto");
  return n;
}

// The whole run in blocks where the DEM needs them (blocked_shade.h), else nothing.
std::optional<int> run_shade_in_blocks(const ShadeArgs& a, shading::Product product, const OutputSpec& out,
                                       const shading::LightingRequest& request, bool lit, bool series,
                                       const shading::ProductOptions& opt, shading::Renderer& renderer,
                                       const std::optional<TintArgs>& tint_args,
                                       const std::vector<blockers::Sphere>& crs_spheres) {
  const std::optional<int> requested = parse_block_size(a.block_size);
  if (a.synthetic) {
    if (requested)
      throw std::invalid_argument("--block-size reads a DEM file in windows: write the scene with `skylit scene` "
                                  "and shade that file");
    return std::nullopt;
  }
  if (a.inputs.empty()) return std::nullopt;  // load_input says what is missing
  const terrain::DemReadOptions read = dem_read_options(a, shading::traits(product).local ? 1.0 : a.z_factor);
  const terrain::DemInfo dem = terrain::inspect_dem(a.inputs);
  std::vector<std::string> warnings;  // the blocks' reads report them
  terrain::MetricSpacing spacing;
  try {
    spacing = terrain::metric_spacing(dem.georef, dem.height, read, warnings);
  } catch (const terrain::DemError&) {
    return std::nullopt;  // the whole DEM's read reports it, naming the file
  }
  const double smallest = std::min(spacing.dy, *std::min_element(spacing.dx_per_row.begin(), spacing.dx_per_row.end()));
  const std::optional<BlockPlan> plan = plan_blocks(dem, smallest, product, opt, requested, renderer);
  if (!plan) return std::nullopt;
  if (series) throw std::invalid_argument("a --time series of a DEM in blocks is not supported: shade one time per run");
  if (!a.track.empty()) throw std::invalid_argument("--track with a DEM in blocks is not supported: give the aircraft as --spheres");
  if (!a.quiet)
    for (const std::string& note : plan->notes) std::cerr << "skylit: note: " << note << "\n";
  BlockedShade job;
  job.inputs = a.inputs;
  job.read = read;
  job.product = product;
  job.options = opt;
  job.crs_spheres = crs_spheres;
  job.tint = tint_args;
  job.out = out;
  job.quiet = a.quiet;
  if (lit) {
    std::optional<sky::Observer> place;
    if (shading::needs_place(request)) {
      // The DEM's centre, as dem_place gives for a whole field.
      if (const auto at = terrain::grid_centre_lat_lon(dem.georef, dem.width, dem.height)) {
        terrain::DemReadOptions centre = read;
        centre.window = terrain::PixelRect{std::min(dem.width / 2, dem.width - 2), std::min(dem.height / 2, dem.height - 2), 2, 2};
        centre.allow_all_nodata = true;
        place = sky::Observer{at->latitude_deg, at->longitude_deg, terrain::read_dem(a.inputs, centre).field.heights[0]};
      }
    }
    const auto resolved = shading::resolve_lighting(request, place);
    job.lighting = resolved.lighting;
    if (!a.quiet) std::cerr << "skylit: " << resolved.summary << "\n";
  }
  run_blocked_shade(job, *plan, dem, renderer);
  if (!a.quiet) std::cerr << "skylit: computed on " << renderer.description() << "\nskylit: wrote " << out.path << " ("
                          << dem.width << "x" << dem.height << ")\n";
  return 0;
}

int run_shade(const ShadeArgs& a) {
  if (a.product == "color-relief") {
    if (a.inputs.size() != 1) throw std::invalid_argument("-p color-relief takes one DEM");
    ColorReliefArgs c = a.color;
    c.input = a.inputs.front();
    c.output = a.output;
    c.overwrite = a.overwrite;
    return run_color_relief(c);
  }
  const auto summed = shading::parse_summed_product(a.product);
  const auto product = summed ? std::optional(shading::frame_product(*summed)) : shading::parse_product(a.product);
  if (!product)
    throw std::invalid_argument("unknown --product '" + a.product + "' (" + shading::product_names() +
                                ", insolation, sun-hours)");
  const std::optional<shading::TimeSpec> times = series_spec(a, summed);
  const shading::ProductTraits& kind = shading::traits(*product);
  if (times && !summed && !kind.lit)
    throw std::invalid_argument("a --time series needs a product lit by the sun: shadow, irradiance, shaded, "
                                "insolation or sun-hours (not " + a.product + ")");
  OutputSpec out;
  if (!times || summed) out = resolve_output(a.output, a.format, *product, a.creation_options, a.overwrite);
  const gpu::Backend backend = parse_backend_arg(a.backend);
  const bool lit = kind.needs_sun || (kind.lit && !sky_only_default(a.light));
  shading::LightingRequest request = a.light.request;
  request.sun = !a.light.no_sun;
  if (times) request.time.clear();  // each frame sets its own
  if (lit) shading::validate(request);  // before reading the DEM
  try {
    shading::validate_subsample(a.options);  // --subsample with --exact
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--subsample " + std::to_string(a.options.subsample) + ": " + e.what());
  }

  if (const double e = a.options.blockers.blocker.cull_error; !(e >= 0.0 && std::isfinite(e)))
    throw std::invalid_argument("--blocker-error must be a finite number ≥ 0");
  if (const double m = a.options.blockers.merge_sin; !(m >= 0.0 && m <= 0.5))
    throw std::invalid_argument("--blocker-merge must be in [0, 0.5]");
  std::vector<blockers::Sphere> crs_spheres;
  if (!a.spheres.empty()) {
    crs_spheres = read_spheres_csv(a.spheres);  // before the DEM: a bad file fails fast
    if (!kind.blocked && !a.quiet)
      std::cerr << "skylit: note: --spheres: " << a.product << " is the terrain's alone (spheres darken skyview, "
                << "shaded, shadow and irradiance)\n";
  }
  const bool tinted = !a.color.color_file.empty();
  TintArgs tint_args{a.color.color_file};
  if (tinted) {
    if (*product != shading::Product::Shaded || times)
      throw std::invalid_argument("--color tints -p shaded (one frame) or makes -p color-relief");
    parse_tint_blend(a.tint_blend, tint_args);
  }
  shading::ProductOptions opt = a.options;
  opt.march.curvature.enabled = !a.no_curvature;
  opt.threads = a.threads;
  opt.shaded.tone = tone_curve(a.light);
  if (kind.local)
    opt.hillshade = hillshade_options(a.hillshade, a.z_factor, a.light.request.sun_azimuth_deg, a.light.request.sun_elevation_deg,
                                      a.compute_edges);
  const auto renderer = make_shade_renderer(backend, a.quiet);
  if (const auto done = run_shade_in_blocks(a, *product, out, request, lit, times.has_value(), opt, *renderer,
                                            tinted ? std::optional(tint_args) : std::nullopt, crs_spheres))
    return *done;

  const auto read_start = std::chrono::steady_clock::now();
  // Local products apply z inside their formula, as gdaldem does: heights stay unscaled.
  const terrain::HeightField field = load_input(a, kind.local ? 1.0 : a.z_factor);
  const std::vector<blockers::Sphere> spheres = to_field_frame(field, crs_spheres);
  std::optional<TrackedAircraft> aircraft;
  if (!a.track.empty()) {
    if (a.light.request.time.empty())
      throw std::invalid_argument("--track needs --time: the time (or series) at which to place the aircraft");
    aircraft.emplace(a.track, a.aircraft, parse_altitude_arg(a.altitude), field);
    if (!a.quiet) std::cerr << "skylit: aircraft: " << aircraft->summary() << "\n";
    for (std::size_t k = 0; k < aircraft->tracks() && !a.quiet; ++k)
      if (!aircraft->over_field(k)) std::cerr << "skylit: note: --track: track " << k + 1 << " lies outside the DEM\n";
  }
  if (const int under = shading::BlockerFrame::below_ground(field, spheres); under > 0 && !a.quiet)
    std::cerr << "skylit: note: --spheres: " << under << " sphere(s) centred below the ground; they shade only what "
              << "they reach above it\n";
  const double read_ms = gpu::ms_since(read_start);

  if (const std::string note = sweep_fallback_note(field, opt, a.horizons_given); !note.empty() && !a.quiet)
    std::cerr << "skylit: note: " << note << "\n";
  if (times)
    return run_shade_series(a, *times, *product, summed, request, field, opt, std::move(out), spheres,
                            aircraft, *renderer);
  const std::vector<blockers::Sphere> frame_spheres =
      spheres_at(spheres, aircraft, aircraft ? sky::parse_utc_time(a.light.request.time).unix_seconds : 0.0);
  if (aircraft && frame_spheres.size() == spheres.size() && !a.quiet)
    std::cerr << "skylit: note: --track: no aircraft is flying at " << a.light.request.time << " (" << aircraft->summary()
              << ")\n";
  if (lit) {
    const auto resolved = shading::resolve_lighting(request, shading::needs_place(request) ? dem_place(field) : std::nullopt);
    opt.lighting = resolved.lighting;
    if (!a.quiet) std::cerr << "skylit: " << resolved.summary << "\n";
  }

  if (const auto why = renderer->lacks(*product, opt))
    throw std::invalid_argument("--backend " + a.backend + (opt.exact ? " with --exact: " : ": ") + *why +
                                "; use --backend reference (or auto)");
  renderer->set_field(field);
  renderer->set_options(opt);
  ProgressBar bar(std::string(shading::product_name(*product)), a.quiet);
  auto bands =
      renderer->frame(*product, {opt.lighting, frame_spheres, std::nullopt}, [&](double f) { bar.update(f); });
  if (tinted) bands = tint(bands, field, tint_args);
  bar.finish();
  if (!a.quiet) std::cerr << "skylit: computed on " << renderer->description() << "\n";
  const auto write_start = std::chrono::steady_clock::now();
  write_product(out, field, bands);
  if (a.timings) print_timings(read_ms, *renderer, gpu::ms_since(write_start));
  if (!a.quiet) std::cerr << "skylit: wrote " << out.path << " (" << bands.width << "x" << bands.height << ", "
                          << bands.bands << " band" << (bands.bands > 1 ? "s" : "") << ")\n";
  return 0;
}

}  // namespace

void add_shade_command(CLI::App& root, Action& run) {
  auto args = std::make_shared<ShadeArgs>();
  auto* cmd = root.add_subcommand(
      "shade", "Shade a DEM: horizon, svf, skyview, shaded relief, sun shadow or irradiance, georeferenced");
  cmd->add_option("INPUT", args->inputs, "DEM raster(s) or a directory of tiles (mosaicked)");
  cmd->add_option("-o,--output", args->output, "Output raster (.tif, .png)")->required();
  cmd->add_flag("--synthetic", args->synthetic, "Use the built-in synthetic mountain scene instead of INPUT");
  cmd->add_option("--seed", args->seed, "Seed of the synthetic scene")->capture_default_str();
  cmd->add_option("--size", args->size, "Width and height of the synthetic scene (pixels)")
      ->check(CLI::Range(2, 16384))->capture_default_str();
  cmd->add_option("-p,--product", args->product,
                  "horizon | svf | skyview | shaded | shadow | irradiance | hillshade (gdaldem hillshade, bit-exact) | insolation (Wh/m^2 over --time) | "
                  "sun-hours (hours of direct sun over --time)")
      ->capture_default_str();
  cmd->add_option("--of,-f", args->format, "Output format: GTiff, COG, PNG (default: from the extension)");
  cmd->add_option("-b,--band", args->band, "Input band (gdaldem -b)")->check(app::positive_number())->capture_default_str();
  cmd->add_option("--nodata", args->nodata, "Input nodata value, overriding the DEM's (gdaldem has none)");
  cmd->add_option("--co", args->creation_options, "Creation option NAME=VALUE (repeatable)");
  cmd->add_option("-z,--zfactor", args->z_factor, "Vertical exaggeration")->check(app::positive_number())->capture_default_str();
  cmd->add_option("-s,--scale", args->scale, "Metres per horizontal map unit (as gdaldem -s)")->check(app::positive_number());
  cmd->add_option("--xscale", args->xscale, "Metres per map unit east-west")->check(app::positive_number());
  cmd->add_option("--yscale", args->yscale, "Metres per map unit north-south")->check(app::positive_number());
  cmd->add_option("--quality", args->quality,
                  "Preset from the measured speed/error front: fast | default | high "
                  "(docs/quality-presets.md); explicit --azimuths/--kv/--level-offset/--levels/--horizon-max/--horizons/"
                  "--near-steps/--sweep-lines/--sh-order/--nlp-order win")
      ->check(CLI::IsMember({"fast", "default", "high"}))
      ->capture_default_str();
  cmd->add_option("--max-error", args->max_error,
                  "Cheapest setting on the measured speed/error front (data/quality/front.csv) whose RMSE is at "
                  "most E: svf and skyview in fractions of the sky, shaded in 8-bit code values (uniform sky); "
                  "explicit quality knobs win (docs/quality-presets.md)");
  cmd->add_option("--shading-mode", args->shading_mode,
                  "How visibility meets the sky: table (sky x BRDF table, the accurate default) | triple "
                  "(SH triple product) | log-brdf (the seed's log-SH BRDF; errs by tens of %, docs/numerics.md)")
      ->check(CLI::IsMember({"table", "triple", "log-brdf"}))
      ->capture_default_str();
  cmd->add_option("--wedge", args->wedge,
                  "Wedge interpolation of the horizon slices over azimuth: linear | bspline (shaded, irradiance)")
      ->check(CLI::IsMember({"linear", "bspline"}))
      ->capture_default_str();
  cmd->add_option("--subsample", args->options.subsample,
                  "Find horizons at every Nth texel each way and interpolate them; normals and shading stay per texel: 1 | 2 | 4")
      ->check(CLI::IsMember({1, 2, 4}))
      ->capture_default_str();
  cmd->add_option("--azimuths", args->options.march.azimuths, "Number of horizon azimuths W")->check(CLI::Range(1, 1024))->capture_default_str();
  cmd->add_flag("--exact", args->options.exact, "Brute-force ground truth: dense half-texel marching, dense sky integral");
  cmd->add_flag("--no-curvature", args->no_curvature, "Disable the Earth-curvature correction");
  cmd->add_option("--max-distance", args->options.march.max_distance_m, "Maximum marching distance in metres (0: the DEM extent)")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_option("--levels", args->levels,
                  "How march steps read the height pyramid: bspline (cubic B-spline, NS09) | bilinear (4 samples "
                  "instead of 16) | none (no pyramid: level-0 heights, bilinear); docs/accuracy.md")
      ->check(CLI::IsMember(level_sampling_names()))
      ->capture_default_str();
  cmd->add_option("--horizon-max", args->horizon_max,
                  "Maximum of the blocking angles along a ray: smooth (B-spline through them, NS09) | plain")
      ->check(CLI::IsMember({std::string(horizon::horizon_max_name(true)), std::string(horizon::horizon_max_name(false))}))
      ->capture_default_str();
  cmd->add_option("--horizons", args->horizons,
                  "How horizons are found: march (rays per texel over the height pyramid) | sweep (sweep lines "
                  "with convex hulls: near-exact horizons in O(N^2) per azimuth, within --max-distance if given; needs "
                  "rows of spacings within 2x (not near a pole) and a --max-distance beyond the near steps; elsewhere "
                  "the march runs, with a note when sweep was asked for)")
      ->check(CLI::IsMember(horizon_method_names()))
      ->capture_default_str();
  cmd->add_option("--sweep-lines", args->options.march.sweep_lines,
                  "Sweep lines per texel across each azimuth (--horizons sweep): a texel's far field comes from "
                  "a line at most 1/(2N) texel beside its own ray")
      ->check(CLI::Range(1, 64))->capture_default_str();
  cmd->add_option("--near-steps", args->options.march.sweep_near_steps,
                  "Half-texel steps K each texel takes along its own ray before the sweep line's far field "
                  "(--horizons sweep; K >= twice the DEM's side is the exact march)")
      ->check(CLI::Range(0, 1 << 16))->capture_default_str();
  cmd->add_option("--kv", args->options.march.k_v, "Pyramid levels per halving of resolution")->check(CLI::Range(1, 16))->capture_default_str();
  cmd->add_option("--level-offset", args->options.march.level_offset, "Pyramid level offset o_v")->capture_default_str();
  cmd->add_option("--sh-order", args->options.shaded.sh_order, "SH order n of the visibility (shaded)")->check(CLI::Range(2, 8))->capture_default_str();
  cmd->add_option("--nlp-order", args->options.shaded.nlp_order, "NLP order N >= n of the slices (shaded)")->check(CLI::Range(2, 16))->capture_default_str();
  cmd->add_option("--exposure", args->options.shaded.exposure, "Linear exposure before the tone curve (shaded)")->check(app::positive_number())->capture_default_str();
  add_lighting_options(*cmd, args->light,
                  "Sun position for this ISO 8601 time with a zone, e.g. 2026-06-21T09:30:00Z or "
                  "2026-06-21T09:30:00-07:00 (place: the DEM's centre, or --lat/--lon); a series: an interval "
                  "START/END/STEP (2026-06-21T04:00Z/2026-06-21T20:00Z/PT15M), a comma-separated list, or a date "
                  "(2026-06-21: that local day, sunrise to sunset); frames go to one file each when OUTPUT has a "
                  "%d (frames/shadow_%04d.png), else to one GeoTIFF band each");
  cmd->add_option("--spheres", args->spheres,
                  "Sphere blockers (aircraft) as CSV x,y,z,radius in the DEM's CRS (z, radius in metres): they darken "
                  "skyview, shaded, shadow and irradiance");
  cmd->add_option("--blocker-error", args->options.blockers.blocker.cull_error,
                  "The most the spheres culled as too small or far may change a texel's sky visibility, together "
                  "(0 culls none by size; 1e-4 for skyview changes under a quarter of an 8-bit code)")
      ->capture_default_str();
  cmd->add_option("--blocker-merge", args->options.blockers.merge_sin,
                  "The sine of the angle under which a texel takes an aircraft part as one cap (0: every sphere "
                  "alone; larger is faster and less exact, docs/accuracy.md)")
      ->capture_default_str();
  cmd->add_option("--track", args->track,
                  "A flight track (IGC, GPX, KML gx:Track, CSV): its aircraft as sphere blockers at --time");
  cmd->add_option("--aircraft", args->aircraft, "The sphere set of --track's aircraft: a shipped name (glider, "
                  "light-single, airliner, helicopter, balloon) or a set.json")->capture_default_str();
  cmd->add_option("--track-altitude", args->altitude,
                  "--track's altitude (skylit track --altitude): gnss | pressure | agl-offset=M (--altitude is the sun's, as in gdaldem)")
      ->capture_default_str();
  cmd->add_option("--max-frames", args->max_frames, "Most frames a --time series may have")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 24))
      ->capture_default_str();
  cmd->add_option("--sun-tolerance", args->sun_tolerance_deg,
                  "A --time series keeps the sun's swept horizon while its heading moves less than this many "
                  "degrees (a replay's frames seconds apart; docs/accuracy.md \"Frame reuse\"); 0 sweeps every frame, "
                  "as a single time does")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  cmd->add_option("--backend", args->backend,
                  "Compute backend: auto (GPU where an OpenGL 4.5 context exists and the GPU has the product, "
                  "else reference) | gpu | reference (CPU, double precision)")
      ->capture_default_str();
  cmd->add_option("--block-size", args->block_size,
                  "Shade the DEM in blocks of N x N texels, each read with a halo of the horizon search distance "
                  "(--max-distance, 5 km by default when blocked), so memory is bounded by the block: N | auto "
                  "(blocks where the DEM is over the GPU's limits or 4096^2 texels; docs/large-dems.md)")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")
      ->check(app::non_negative_number())->capture_default_str();
  cmd->add_flag("--compute-edges", args->compute_edges,
                "-p hillshade: shade the border and nodata-adjacent pixels too (gdaldem -compute_edges); the horizon "
                "products always compute edges");
  add_hillshade_options(*cmd, args->hillshade);
  cmd->add_flag("-q,--quiet", args->quiet, "No progress bar or warnings");
  cmd->add_flag("--timings", args->timings, "Print the wall time of each stage (read, GPU set-up, pyramid, march, ..., write) to stderr");
  cmd->add_flag("--overwrite", args->overwrite, "Replace OUTPUT if it exists");
  cmd->add_option("--color", args->color.color_file, "Colour table (gdaldem color-relief syntax, .cpt) for -p color-relief");
  cmd->add_option("--tint-blend", args->tint_blend,
                  "-p shaded --color: multiply[:W] (colour × relief at weight W, as a GIS layer's opacity) | soft-light[:W] (W3C)")
      ->capture_default_str();
  cmd->add_flag("--alpha", args->color.alpha, "-p color-relief: add an alpha band (gdaldem -alpha)");
  cmd->add_flag_callback("--exact-color-entry", [args] { args->color.selection = relief::ColorSelection::ExactEntry; },
                         "-p color-relief: only exact table entries, else transparent black");
  cmd->add_flag_callback("--nearest-color-entry", [args] { args->color.selection = relief::ColorSelection::NearestEntry; },
                         "-p color-relief: the nearest table entry, no interpolation");
  cmd->callback([&run, args, cmd] {
    // The preset sets the quality knobs the user did not give explicitly.
    shading::ProductOptions preset = args->options;
    shading::apply_quality(*shading::parse_quality(args->quality), preset);
    std::string max_error_note;
    if (args->max_error) {
      try {
        max_error_note = apply_max_error(*args->max_error, args->product, *cmd, preset);
      } catch (const std::invalid_argument& e) {
        run = [why = std::string(e.what())]() -> int { throw std::invalid_argument(why); };
        return;
      }
      if (!cmd->count("--subsample")) args->options.subsample = preset.subsample;
      if (!cmd->count("--wedge")) args->wedge = preset.shaded.wedge == sh::WedgeInterpolation::BSpline ? "bspline" : "linear";
    }
    auto& o = args->options;
    if (!cmd->count("--azimuths")) o.march.azimuths = preset.march.azimuths;
    if (!cmd->count("--kv")) o.march.k_v = preset.march.k_v;
    if (!cmd->count("--level-offset")) o.march.level_offset = preset.march.level_offset;
    horizon::set_level_sampling(o.march, cmd->count("--levels") ? *horizon::parse_level_sampling(args->levels)
                                                                 : horizon::level_sampling(preset.march));
    o.march.smooth_max =
        cmd->count("--horizon-max") ? args->horizon_max == horizon::horizon_max_name(true) : preset.march.smooth_max;
    args->horizons_given = cmd->count("--horizons") > 0;
    o.march.method = args->horizons_given ? *horizon::parse_horizon_method(args->horizons) : preset.march.method;
    if (!cmd->count("--near-steps")) o.march.sweep_near_steps = preset.march.sweep_near_steps;
    if (!cmd->count("--sweep-lines")) o.march.sweep_lines = preset.march.sweep_lines;
    if (!cmd->count("--sh-order")) o.shaded.sh_order = preset.shaded.sh_order;
    if (!cmd->count("--nlp-order")) o.shaded.nlp_order = preset.shaded.nlp_order;
    args->options.shaded.mode = *shading::parse_shading_mode(args->shading_mode);
    args->options.shaded.wedge =
        args->wedge == "bspline" ? sh::WedgeInterpolation::BSpline : sh::WedgeInterpolation::Linear;
    run = [args, max_error_note] {
      if (!max_error_note.empty() && !args->quiet) std::cerr << "skylit: " << max_error_note << "\n";
      return run_shade(*args);
    };
  });
}

}  // namespace skylit::app::shade
