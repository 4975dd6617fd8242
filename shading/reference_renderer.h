// The CPU reference renderer (renderer.h): double precision per texel, rows over worker
// threads; compute_product (products.h) is one frame of it. It keeps, between frames on
// the same field revision and horizon options, the visibility of `shaded` and
// `irradiance` (n² doubles per texel) and the bands of horizon, svf and skyview, so a
// time series pays only the sun and the shading per frame.
#pragma once

#include "shading/renderer.h"

#include <cstdint>
#include <span>
#include <vector>

namespace skylit::shading {

class ReferenceRenderer final : public Renderer {
 public:
  std::string description() const override { return "reference (CPU)"; }
  bool on_gpu() const override { return false; }
  void set_field(const terrain::HeightField& field) override { field_ = &field; }
  void set_options(const ProductOptions& options) override;
  void expect_frames(int frames) override { keep_ = frames > 1; }
  void drop_horizons() override;
  std::optional<std::string> lacks_blockers(Product, const ProductOptions&) const override { return std::nullopt; }
  std::optional<std::string> lacks(Product, const ProductOptions&) const override { return std::nullopt; }
  bool fits_field(int, int, Product, const ProductOptions&) override { return true; }
  ProductBands frame(Product product, const FrameInputs& inputs, const ProgressCallback& progress = {}) override;
  const FrameTimings& last_timings() const override { return timings_; }

 private:
  // The SH visibility (or log-visibility) of every texel: [texel·rows + r].
  struct Visibility {
    std::uint64_t field_id = 0, revision = 0;
    ProductOptions options;
    int rows = 0;
    std::vector<double> values;
  };
  // `spheres`: those that darken this product (blocked_frame), else empty.
  ProductBands render(Product product, const ProductOptions& options, std::span<const blockers::Sphere> spheres,
                      const ProgressCallback& progress);

  const terrain::HeightField* field_ = nullptr;
  ProductOptions options_;
  bool keep_ = false;
  int frames_ = 0;  // frames rendered since the options or horizons were last dropped
  Visibility visibility_;
  FrameIndependentCache outputs_;
  FrameTimings timings_;
};

}  // namespace skylit::shading
