#include "app/tiles/tile_run.h"

#include <algorithm>
#include <stdexcept>

#include "app/tiles/tile_image.h"
#include "app/tiles/tile_progress.h"
#include "parallel/parallel_rows.h"

namespace skylit::app::tiles {
namespace {

const ZoomPlan& plan_of(const std::vector<ZoomPlan>& plans, int z) {
  const auto it = std::find_if(plans.begin(), plans.end(), [z](const ZoomPlan& p) { return p.z == z; });
  if (it == plans.end()) throw std::logic_error("tiles: no plan for zoom " + std::to_string(z));
  return *it;
}

// The halo a block's window needs: the horizons' (plan.halo) for products that search
// them; one pixel for the 3×3-window products (hillshade: gdaldem's kernel reads one
// neighbour each way, and a pixel's height is the same in every window, so its tiles
// are the same bytes as with the horizon halo, at up to half the warped pixels at
// z 13); none for the DEM encodings, which read no neighbours.
int window_halo(const TileJob& job, const ZoomPlan& plan) {
  constexpr int kLocalProductHalo = 1;
  if (!job.product) return 0;
  return shading::traits(*job.product).local ? kLocalProductHalo : plan.halo;
}

std::vector<terrain::TileId> tiles_of(const terrain::TileRange& r) {
  std::vector<terrain::TileId> out;
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x) out.push_back({r.z, x, y});
  return out;
}

}  // namespace

RunCounts render_blocks(const terrain::TileWindowSource& source, const std::vector<ZoomPlan>& plans,
                        const std::vector<Block>& blocks, const TileJob& job, shading::Renderer* renderer,
                        LazyArchive& archive) {
  long long total = 0;
  for (const Block& b : blocks) total += b.wanted.count();
  TileProgress progress(total, job.quiet);
  RunCounts n;
  const auto done = [&n] { return n.written + n.skipped + n.empty; };
  for (const Block& b : blocks) {
    const std::vector<terrain::TileId> tiles = tiles_of(b.wanted);
    std::vector<terrain::TileId> todo;
    // Columns past the world's east edge (a DEM across the antimeridian) are stored as
    // the tiles they wrap to.
    for (const auto& t : tiles)
      if (!archive.has(terrain::wrap_tile(t))) todo.push_back(t);
    n.skipped += static_cast<long long>(tiles.size() - todo.size());
    if (todo.empty()) {  // complete from an earlier run: no window to render
      progress.update(done());
      continue;
    }
    const ZoomPlan& plan = plan_of(plans, b.z);
    terrain::TileWindowOptions wo;
    wo.tile_size = job.tile_size;
    wo.halo = window_halo(job, plan);
    wo.resampling = job.resampling;
    // Outside the DEM (transparent in the tiles) only the heights next to its edge matter,
    // as near blockers: the nearest valid height, O(N), where the smooth Laplace fill took
    // 60 % of a hillshade run's time on its wide outside halos.
    wo.fill = terrain::VoidFill::Nearest;
    const terrain::TileWindow window = source.window(b.tiles, wo);
    // The pixels the tiles to do show: only their horizons are searched; the halo, the
    // outside of the DEM and the tiles done already are blockers at most.
    std::vector<terrain::PixelRect> valid(todo.size());
    terrain::PixelRect shown;
    for (std::size_t k = 0; k < todo.size(); ++k) {
      valid[k] = valid_bounds(window.field, window.tile_rect(todo[k]));
      shown = terrain::bounding_union(shown, valid[k]);
    }
    if (shown.empty()) {  // the tiles to do miss the DEM's valid pixels
      n.empty += static_cast<long long>(todo.size());
      progress.update(done());
      continue;
    }
    std::optional<shading::ProductBands> bands;
    if (job.product) {
      shading::ProductOptions opt = job.options;
      opt.march.max_distance_m = plan.max_distance_m;
      opt.march.region = shown;
      renderer->set_field(window.field);
      renderer->set_options(opt);
      bands = renderer->frame(*job.product, {opt.lighting, {}, std::nullopt});
    }
    // Cutting and compressing the tiles (zlib: a third of a hillshade run) in parallel;
    // the archive gets them in the block's order, as a serial run would.
    std::vector<std::optional<std::string>> encoded(todo.size());
    parallel::parallel_rows(static_cast<int>(todo.size()), job.threads, [&](int k) {
      if (valid[k].empty()) return;
      const terrain::PixelRect rect = window.tile_rect(todo[k]);
      std::vector<std::uint8_t> rgba(static_cast<std::size_t>(job.tile_size) * job.tile_size * 4);
      if (bands) rgba = product_tile_rgba(*job.product, *bands, window.field, rect);
      else terrain::encode_dem_tile(*job.encoding, window.field, rect, rgba);
      encoded[k] = encode_tile(job.format, job.tile_size, rgba, job.encoding ? kDemPngZlevel : kShadedPngZlevel);
    });
    for (std::size_t k = 0; k < todo.size(); ++k) {
      if (!encoded[k]) {
        ++n.empty;
        continue;
      }
      archive.put(terrain::wrap_tile(todo[k]), skylit::tiles::as_bytes(*encoded[k]));
      ++n.written;
    }
    progress.update(done());
  }
  progress.finish(done());
  return n;
}

}  // namespace skylit::app::tiles
