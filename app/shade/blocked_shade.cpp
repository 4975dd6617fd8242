#include "app/shade/blocked_shade.h"

#include "app/common/progress.h"
#include "app/shade/sphere_input.h"
#include "shading/horizon/halo.h"
#include "terrain/block_raster_writer.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <set>
#include <stdexcept>

namespace skylit::app::shade {
namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "×" + std::to_string(h); }

std::string metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f m", m);
  return text;
}

// `bands` (the read window's) cut to the block's core.
std::vector<float> core_of(const shading::ProductBands& bands, const terrain::RasterBlock& block) {
  const int ox = block.core.x0 - block.read.x0, oy = block.core.y0 - block.read.y0;
  std::vector<float> out(static_cast<std::size_t>(block.core.width) * block.core.height * bands.bands);
  std::size_t k = 0;
  for (int b = 0; b < bands.bands; ++b)
    for (int j = 0; j < block.core.height; ++j) {
      const float* row = &bands.data[(static_cast<std::size_t>(b) * bands.height + oy + j) * bands.width + ox];
      k = std::copy(row, row + block.core.width, out.begin() + static_cast<std::ptrdiff_t>(k)) - out.begin();
    }
  return out;
}

}  // namespace

std::optional<BlockPlan> plan_blocks(const terrain::DemInfo& dem, double smallest_spacing_m,
                                     shading::Product product, const shading::ProductOptions& options,
                                     std::optional<int> requested, shading::Renderer& renderer) {
  const bool local = shading::traits(product).local;
  const long long texels = static_cast<long long>(dem.width) * dem.height;
  const bool over_gpu = !local && !renderer.fits_field(dem.width, dem.height, product, options);
  if (!requested && !over_gpu && texels <= kMaxWholeFieldTexels) return std::nullopt;
  if (requested && *requested < kMinBlockCore)
    throw std::invalid_argument("--block-size " + std::to_string(*requested) + " is under " +
                                std::to_string(kMinBlockCore) + " texels");

  BlockPlan plan;
  if (!requested)
    plan.notes.push_back("the DEM (" + size_text(dem.width, dem.height) + ") is over " +
                         (over_gpu ? std::string("the largest GPU frame on this driver")
                                   : "one frame's memory budget (" + std::to_string(kMaxWholeFieldTexels) + " texels)") +
                         ": shading it in blocks (--block-size)");
  std::optional<int> gpu_side;
  int side = kBlockBudgetSide;
  if (local) {
    plan.halo = 1;  // the 3×3 window
  } else {
    // The side the GPU takes for a bounded search.
    shading::ProductOptions bounded = options;
    bounded.march.max_distance_m = options.march.max_distance_m > 0.0 ? options.march.max_distance_m
                                                                      : horizon::kDefaultBoundedDistanceM;
    gpu_side = shading::max_square_side(renderer, product, bounded);
    if (gpu_side) side = std::min(side, *gpu_side);
    plan.max_distance_m = options.march.max_distance_m;
    if (plan.max_distance_m <= 0.0) {
      // The default, shortened where a block could not hold its halo with a core twice as wide.
      const double fit = (side / 4 - horizon::kKernelMarginTexels) * smallest_spacing_m;
      plan.max_distance_m = std::max(smallest_spacing_m, std::min(horizon::kDefaultBoundedDistanceM, fit));
      plan.notes.push_back("horizons are searched to " + metres(plan.max_distance_m) +
                           " (a blocked run bounds the search; --max-distance sets it)");
    }
    const double halo = horizon::halo_texels(plan.max_distance_m, smallest_spacing_m);
    if (halo > 1 << 20)
      throw std::invalid_argument("--max-distance " + metres(plan.max_distance_m) + " is over a million texels");
    plan.halo = static_cast<int>(halo);
  }
  plan.core = requested ? *requested : side - 2 * plan.halo;
  if (gpu_side && plan.core + 2 * plan.halo > *gpu_side)
    throw std::invalid_argument("blocks of " + std::to_string(plan.core) + " texels with a halo of " +
                                std::to_string(plan.halo) + " (--max-distance " + metres(plan.max_distance_m) +
                                ") are over the largest GPU frame on this driver (" +
                                size_text(*gpu_side, *gpu_side) + "): give --block-size at most " +
                                std::to_string(*gpu_side - 2 * plan.halo) + " or a smaller --max-distance");
  if (!requested && plan.core < std::max(kMinBlockCore, plan.halo))
    throw std::invalid_argument("--max-distance " + metres(plan.max_distance_m) + " needs a halo of " +
                                std::to_string(plan.halo) + " texels, too wide for blocks of " +
                                std::to_string(side) + " texels: give a smaller --max-distance");
  plan.blocks = terrain::block_grid(dem.width, dem.height, plan.core, plan.halo);
  return plan;
}

void run_blocked_shade(const BlockedShade& job, const BlockPlan& plan, const terrain::DemInfo& dem,
                       shading::Renderer& renderer) {
  const auto& gt = dem.georef.geotransform;
  if (dem.georef.has_geotransform && (gt[1] < 0.0 || gt[5] > 0.0))
    throw std::invalid_argument("blocks need a north-up DEM with columns growing east: warp it first "
                                "(gdalwarp DEM north_up.tif)");
  terrain::cap_gdal_cache_for_streaming();
  if (!job.quiet)
    std::cerr << "skylit: " << plan.blocks.size() << " block" << (plan.blocks.size() > 1 ? "s" : "") << " of up to "
              << plan.core << "×" << plan.core << " texels with a halo of " << plan.halo << "\n";
  shading::ProductOptions options = job.options;
  options.march.max_distance_m = plan.max_distance_m;
  renderer.set_options(options);
  renderer.expect_frames(1);

  std::unique_ptr<terrain::BlockRasterWriter> writer;
  std::vector<terrain::PixelRect> void_cores;  // written once the band count is known
  int band_count = 0;
  std::set<std::string> warned;
  const double total = static_cast<double>(dem.width) * dem.height;
  double done = 0.0;
  ProgressBar bar(std::string(shading::product_name(job.product)), job.quiet);
  std::unique_ptr<ProgressBar> copy_bar;  // made at the copy's first progress, so it times the copy
  auto write_core = [&](const terrain::PixelRect& core, const std::vector<float>& values) {
    if (job.out.eight_bit) writer->write(core, std::span<const std::uint8_t>(byte_samples(values)));
    else writer->write(core, std::span<const float>(float_samples(values)));
  };
  for (const terrain::RasterBlock& block : plan.blocks) {
    terrain::DemReadOptions read = job.read;
    read.window = block.read;
    read.allow_all_nodata = true;
    terrain::DemReadResult dem_block = terrain::read_dem(job.inputs, read);
    for (const std::string& w : dem_block.warnings)
      if (!job.quiet && warned.insert(w).second) std::cerr << "skylit: warning: " << w << "\n";
    const double block_texels = static_cast<double>(block.core.width) * block.core.height;
    if (dem_block.nodata_count == dem_block.field.size()) {
      void_cores.push_back(block.core);
    } else {
      const terrain::HeightField& field = dem_block.field;
      // Horizons only for the core: the halo around it holds blockers.
      options.march.region = {block.core.x0 - block.read.x0, block.core.y0 - block.read.y0, block.core.width,
                              block.core.height};
      renderer.set_options(options);
      renderer.set_field(field);
      const shading::FrameInputs inputs{job.lighting, to_field_frame(field, job.crs_spheres), std::nullopt};
      shading::ProductBands bands = renderer.frame(job.product, inputs,
                                                   [&](double f) { bar.update((done + f * block_texels) / total); });
      if (job.tint) bands = tint(bands, field, *job.tint);
      if (!writer) {
        band_count = bands.bands;
        terrain::RasterWriteOptions o;
        o.format = job.out.format;
        o.creation_options = job.out.creation_options;
        o.band_descriptions = bands.band_names;
        o.overwrite = job.out.overwrite;
        o.nodata = job.out.eight_bit ? kByteNodata : kFloatNodata;
        o.progress = [&copy_bar, &job](double f) {  // copy-only formats (COG: overviews) at finish()
          if (!copy_bar) copy_bar = std::make_unique<ProgressBar>("writing " + job.out.format, job.quiet);
          copy_bar->update(f);
          return true;
        };
        writer = std::make_unique<terrain::BlockRasterWriter>(
            job.out.path, dem.georef, dem.width, dem.height, bands.bands,
            job.out.eight_bit ? terrain::BlockRasterWriter::Sample::Byte : terrain::BlockRasterWriter::Sample::Float32,
            o);
      }
      write_core(block.core, core_of(bands, block));
    }
    done += block_texels;
    bar.update(done / total);
  }
  bar.finish();
  if (!writer) throw std::invalid_argument("the DEM holds no valid height: every pixel is nodata");
  for (const terrain::PixelRect& core : void_cores)
    write_core(core, std::vector<float>(static_cast<std::size_t>(core.width) * core.height * band_count,
                                        std::numeric_limits<float>::quiet_NaN()));
  writer->finish();
  if (copy_bar) copy_bar->finish();
}

}  // namespace skylit::app::shade
