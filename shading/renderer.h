// The renderer every front end drives (DESIGN.md "The renderer"): a resident height
// field, horizons computed when the field or the options change and not per frame, and
// many cheap frames, each with its own sun, sky, blockers and exposure. Implemented by
// the CPU reference (shading/reference_renderer.h) and the GPU (gpu/gpu_renderer.h);
// gpu/renderer_factory.h picks one, with the auto fallback.
//
// A frame's products are those of compute_product (products.h) with the options set by
// set_options() and the frame's lighting: a renderer gives the same bands as
// compute_product would for that field, product, options and lighting.
#pragma once

#include "shading/blockers/sphere_blocker.h"
#include "shading/lighting.h"
#include "shading/products.h"
#include "terrain/height_field.h"

#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace skylit::shading {

struct FrameInputs {
  // The sun and sky. shadow and irradiance need one; `shaded` without one is the
  // uniform-sky relief; horizon, svf and skyview ignore it.
  std::optional<Lighting> lighting;
  // Blockers (aircraft), in the field's frame: x east and y north in metres from the
  // centre of texel (0, 0) (texel (i, j) is at (i·dx, −j·dy)), z a height in the DEM's
  // vertical datum. They darken the products whose traits say `blocked` (skyview,
  // shaded, shadow, irradiance; blocker_frame.h); horizon and svf stay the terrain's.
  std::vector<blockers::Sphere> spheres;
  // Replaces ProductOptions::shaded.exposure for this frame (`shaded` only).
  std::optional<double> exposure;
};

// Throws std::invalid_argument (one line) for a non-finite or non-positive sphere.
void validate(const FrameInputs& inputs);

// Whether the frame's spheres darken this product (its traits say `blocked` and there
// are spheres).
inline bool blocked_frame(Product product, const FrameInputs& inputs) {
  return traits(product).blocked && !inputs.spheres.empty();
}

// Where a frame's time went (milliseconds; wall clock unless marked).
struct FrameTimings {
  double upload_ms = 0.0;        // the height field to the GPU (its edited rows only, or nothing)
  std::size_t uploaded_bytes = 0;
  double pyramid_ms = 0.0;       // GPU pyramid build (0 without one)
  double sweep_ms = 0.0;         // the sweep's far field (0 without it, or reused)
  double sun_ms = 0.0;           // GPU timer: the sun's shadow pass and its sweep
  double march_ms = 0.0;         // GPU timer, the sweep included (Mesa llvmpipe reports ~0 for compute)
  double products_ms = 0.0;      // GPU timer
  double context_ms = 0.0;       // creating the GPU context (the renderer's first frame)
  double compile_ms = 0.0;       // kernels compiled for this frame (0 when cached)
  double frame_ms = 0.0;         // the whole frame, read-back included
  bool horizons_reused = false;  // the horizons (or the visibility built from them) were kept
  // Texels whose horizons (and visibility) this frame computed: all, none (kept), or after
  // an edit only those an incremental refresh reached (Renderer::set_refresh_budget).
  std::size_t refreshed_texels = 0;
  // Texels whose kept visibility is still that of the field before its last edit.
  std::size_t stale_texels = 0;
  // The sun's horizon was an earlier frame's (GpuRenderer::set_sun_heading_tolerance).
  bool sun_far_reused = false;
  // Texels the sun's disc pass ran for: all, or in a frame that kept the sun's horizon
  // only those whose result a sun moved this far may change (the rest copied).
  std::size_t sun_texels = 0;
  // The sky irradiance of the texels no sphere reaches was an earlier frame's
  // (GpuRenderer::keep_sky_irradiance).
  bool sky_reused = false;
  // The sun, sky and field were the last frame's: only the texels the spheres reach, the
  // last frame's and this one's, were shaded again (gpu::GpuProductPipeline::set_partial_frames).
  bool shading_kept = false;
};

class Renderer {
 public:
  virtual ~Renderer() = default;

  // "gpu (llvmpipe (LLVM 15.0.6, 256 bits), EGL surfaceless)", "reference (CPU)", …
  // for the last frame (an auto renderer may change backend between frames).
  virtual std::string description() const = 0;
  virtual bool on_gpu() const = 0;

  // The field stays resident: the renderer keeps a reference, which must outlive it or
  // the next set_field(). Edits through terrain/editing.h (mark_dirty) are seen at the
  // next frame: the GPU re-uploads only the edited rows, and horizons are recomputed.
  virtual void set_field(const terrain::HeightField& field) = 0;
  // Horizon, shading and quality options; their `lighting` is ignored (it is per frame).
  // Horizons are kept while options that change them stay the same.
  virtual void set_options(const ProductOptions& options) = 0;
  // How many frames the caller expects to render on this field and these options: with
  // more than one, the first frame keeps what later frames reuse (GPU: the visibility,
  // 4·n² bytes per texel). Without it the second frame starts keeping.
  virtual void expect_frames(int frames) = 0;
  // Whether the frames may carry blockers (a replay's aircraft): a frame without any (a
  // track's gap, before take-off) then takes the same kernels as the frames with them,
  // so what they keep (the GPU's visibility and horizons) survives it, rather than a
  // frame of other kernels computing the horizons again. This default, the reference's,
  // keeps nothing of blocked frames whatever the hint.
  virtual void expect_blockers(bool /*expected*/) {}
  // Forgets the kept horizons and visibility (the kernels stay compiled): the next
  // frame does all its work, as a benchmark of one whole frame needs.
  virtual void drop_horizons() = 0;
  // After an edit, recompute the edited area at once and about `texels_per_frame` more
  // texels each frame, nearest first, until the whole field is current (the GPU:
  // gpu/visibility_refresh.h); 0, the default, recomputes the whole field at the edit.
  // This default, the reference's, recomputes whole fields whatever the budget.
  virtual void set_refresh_budget(std::size_t /*texels_per_frame*/) {}
  // Many frames a little apart in time (a replay, the viewer): keep the sun's swept
  // horizon while its heading stays within `radians` of the heading it was swept along
  // (the GPU: GpuProductPipeline::set_sun_heading_tolerance; docs/accuracy.md, "Frame
  // reuse"). 0, the default, sweeps every frame. This default, the reference's, marches
  // the sun exactly every frame whatever the tolerance.
  virtual void set_sun_heading_tolerance(double /*radians*/) {}

  // Why this renderer cannot shade sphere blockers in `product` with these options (one
  // line), or nothing. It refuses such frames with std::invalid_argument rather than
  // shading them without their spheres.
  virtual std::optional<std::string> lacks_blockers(Product product, const ProductOptions& options) const = 0;
  // Why this renderer cannot compute `product` with these options (one line), or nothing.
  virtual std::optional<std::string> lacks(Product product, const ProductOptions& options) const = 0;

  // Whether one frame of `product` with these options takes a width × height field: the
  // GPU's buffer and texture limits (gpu/field_limits.h); the reference is bounded by
  // memory alone. Front ends cut larger DEMs into blocks that fit (max_square_side).
  virtual bool fits_field(int width, int height, Product product, const ProductOptions& options) = 0;

  // One frame. Throws std::invalid_argument for bad options or inputs (a lit product
  // without a lighting, spheres), std::runtime_error when the backend cannot run it.
  virtual ProductBands frame(Product product, const FrameInputs& inputs, const ProgressCallback& progress = {}) = 0;
  virtual const FrameTimings& last_timings() const = 0;
};

// How far the sun may move before frames that reuse what depends on its position make it
// again (the viewer's frames, and a series' unless told otherwise): the swept far slopes
// of its heading, and the viewer's lighting and sky model. At 1× replay the sun moves
// 0.05° in 5–20 s of track time. The shadow's mean error against the exact march stays
// within 1.5× the sweep's own, the sky's irradiance within 1e-3 of the frame's
// brightest, and a kept lighting's mean within 1e-3 of it (tests/gpu_frame_reuse_test.cpp,
// tests/view_lighting_reuse_test.cpp; docs/accuracy.md).
inline constexpr double kFrameSunTolerance = 0.05 * std::numbers::pi / 180.0;

// The side of the largest square field renderer.fits_field takes, or nothing when it
// takes every side up to kMaxFieldSide (bounded by memory alone).
inline constexpr int kMaxFieldSide = 1 << 20;
std::optional<int> max_square_side(Renderer& renderer, Product product, const ProductOptions& options);

// The options of a frame: `options` with the frame's lighting and exposure.
ProductOptions frame_options(const ProductOptions& options, const FrameInputs& inputs);

// `shadow` while the sun's centre is below the horizon (time_integral.h's
// sun_above_horizon, where its DNI is 0): 0 on every valid texel, NaN on nodata. Rays
// that leave the grid see no terrain, so the sun march alone would let a sun below the
// horizontal light the edges. nullopt when the frame is not such a one.
std::optional<ProductBands> night_shadow(Product product, const FrameInputs& inputs, const terrain::HeightField& field);

// Whether two option sets give the same horizons, hence the same visibility: every
// field that reaches the march, the sweep or the visibility's SH (not the lighting,
// exposure, albedo or threads).
bool same_horizon_options(const ProductOptions& a, const ProductOptions& b);
// The same but for the wanted region (MarchOptions::region): what a GPU pipeline bakes
// into its kernels; the region only says which texels a frame computes.
bool same_baked_horizon_options(const ProductOptions& a, const ProductOptions& b);

// Keeps the last bands of products that depend on nothing per frame (horizon, svf,
// skyview), for the field revision and options they were computed for.
class FrameIndependentCache {
 public:
  static bool applies(Product product) { return !traits(product).lit; }
  // The bands kept for this product, field revision and options (reused: true), or
  // render()'s, kept for later frames when `keep`.
  template <class Render>
  ProductBands get(Product product, const terrain::HeightField& field, const ProductOptions& options, bool keep,
                   const ProgressCallback& progress, bool& reused, const Render& render) {
    if (const ProductBands* kept = find(product, field, options)) {
      reused = true;
      if (progress) progress(1.0);
      return *kept;
    }
    ProductBands out = render();
    if (keep) store(product, field, options, out);
    return out;
  }
  void clear() { entries_.clear(); }

 private:
  const ProductBands* find(Product product, const terrain::HeightField& field, const ProductOptions& options) const;
  void store(Product product, const terrain::HeightField& field, const ProductOptions& options, const ProductBands& bands);

  struct Entry {
    Product product;
    std::uint64_t field_id, revision;
    ProductOptions options;
    ProductBands bands;
  };
  std::vector<Entry> entries_;
};

}  // namespace skylit::shading
