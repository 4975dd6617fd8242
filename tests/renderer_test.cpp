// The CPU reference renderer (shading/reference_renderer.h): frames equal independent
// compute_product calls with the same lighting bit for bit, whether the visibility is
// kept from an earlier frame or not; an edit or other horizon options recompute it;
// frame-independent products come back unchanged; bad inputs get one clear line.
#include "lighting_test_util.h"
#include "terrain_test_util.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "shading/lighting.h"
#include "shading/products.h"
#include "shading/reference_renderer.h"
#include "terrain/editing.h"
#include "terrain/synthetic.h"

namespace skylit::shading {
namespace {

using ::skylit::testing::sun_at;  // lighting_test_util.h

terrain::HeightField small_field() {
  terrain::SyntheticOptions o;
  o.width = 40;
  o.height = 32;
  o.spacing = 30.0;
  o.seed = 3;
  return terrain::make_synthetic_terrain(o);
}

ProductOptions small_options() {
  ProductOptions o;
  o.march.azimuths = 8;
  o.threads = 2;
  return o;
}

// Heights + dh over `r`, through the editing API (one revision on, r dirty).
void raise(terrain::HeightField& f, const terrain::PixelRect& r, float dh) {
  std::vector<float> v;
  for (int j = r.y0; j < r.y1(); ++j)
    for (int i = r.x0; i < r.x1(); ++i) v.push_back(f.at(i, j) + dh);
  terrain::replace_heights(f, r, v);
}

bool bit_identical(const ProductBands& a, const ProductBands& b) {
  return a.width == b.width && a.height == b.height && a.bands == b.bands && a.band_names == b.band_names &&
         a.data.size() == b.data.size() && std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

ProductBands single(const terrain::HeightField& f, Product p, ProductOptions o, const Lighting& l) {
  o.lighting = l;
  return compute_product(f, p, o);
}

TEST(ReferenceRenderer, SeriesFramesEqualSingleComputesAndReuseTheVisibility) {
  const terrain::HeightField f = small_field();
  const ProductOptions o = small_options();
  ReferenceRenderer r;
  r.set_field(f);
  r.set_options(o);
  r.expect_frames(3);
  const Lighting suns[] = {sun_at(90, 10), sun_at(180, 50, "preetham"), sun_at(270, 25)};
  for (Product p : {Product::Irradiance, Product::Shaded}) {
    for (int k = 0; k < 3; ++k) {
      const ProductBands got = r.frame(p, {suns[k], {}, std::nullopt});
      EXPECT_EQ(r.last_timings().horizons_reused, k > 0 || p == Product::Shaded) << product_name(p) << " frame " << k;
      EXPECT_TRUE(bit_identical(got, single(f, p, o, suns[k]))) << product_name(p) << " frame " << k;
    }
  }
  const ProductBands shadow = r.frame(Product::Shadow, {suns[1], {}, std::nullopt});
  EXPECT_TRUE(bit_identical(shadow, single(f, Product::Shadow, o, suns[1])));
}

TEST(ReferenceRenderer, WithoutTheHintTheSecondFrameStartsKeeping) {
  const terrain::HeightField f = small_field();
  ReferenceRenderer r;
  r.set_field(f);
  r.set_options(small_options());
  const FrameInputs in{sun_at(120, 30), {}, std::nullopt};
  r.frame(Product::Irradiance, in);
  EXPECT_FALSE(r.last_timings().horizons_reused);
  r.frame(Product::Irradiance, in);
  EXPECT_FALSE(r.last_timings().horizons_reused);  // computed, and kept
  r.frame(Product::Irradiance, in);
  EXPECT_TRUE(r.last_timings().horizons_reused);
}

TEST(ReferenceRenderer, AnEditOrOtherHorizonOptionsRecompute) {
  terrain::HeightField f = small_field();
  ProductOptions o = small_options();
  ReferenceRenderer r;
  r.set_field(f);
  r.set_options(o);
  r.expect_frames(4);
  const FrameInputs in{sun_at(200, 20), {}, std::nullopt};
  r.frame(Product::Irradiance, in);
  raise(f, {5, 5, 8, 8}, 150.0f);
  const ProductBands edited = r.frame(Product::Irradiance, in);
  EXPECT_FALSE(r.last_timings().horizons_reused);
  EXPECT_TRUE(bit_identical(edited, single(f, Product::Irradiance, o, *in.lighting)));
  o.march.azimuths = 12;
  r.set_options(o);
  const ProductBands other = r.frame(Product::Irradiance, in);
  EXPECT_FALSE(r.last_timings().horizons_reused);
  EXPECT_TRUE(bit_identical(other, single(f, Product::Irradiance, o, *in.lighting)));
  // Exposure and albedo are per frame, not horizon options: the visibility stays.
  const ProductBands brighter = r.frame(Product::Shaded, {in.lighting, {}, 2.0});
  EXPECT_TRUE(r.last_timings().horizons_reused);
  ProductOptions bright = o;
  bright.shaded.exposure = 2.0;
  EXPECT_TRUE(bit_identical(brighter, single(f, Product::Shaded, bright, *in.lighting)));
}

TEST(ReferenceRenderer, FrameIndependentProductsComeBackUnchanged) {
  terrain::HeightField f = small_field();
  ReferenceRenderer r;
  r.set_field(f);
  r.set_options(small_options());
  r.expect_frames(2);
  const ProductBands first = r.frame(Product::Svf, {});
  const ProductBands again = r.frame(Product::Svf, {sun_at(10, 10), {}, std::nullopt});
  EXPECT_TRUE(r.last_timings().horizons_reused);
  EXPECT_TRUE(bit_identical(first, again));
  raise(f, {0, 0, 4, 4}, 300.0f);
  const ProductBands edited = r.frame(Product::Svf, {});
  EXPECT_FALSE(r.last_timings().horizons_reused);
  EXPECT_TRUE(bit_identical(edited, compute_product(f, Product::Svf, small_options())));
}

TEST(ReferenceRenderer, BadInputsGetOneClearLine) {
  const terrain::HeightField f = small_field();
  ReferenceRenderer r;
  EXPECT_THROW(r.frame(Product::Svf, {}), std::logic_error);  // no field yet
  r.set_field(f);
  r.set_options(small_options());
  auto message = [&](const FrameInputs& in, Product p) {
    try {
      r.frame(p, in);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  FrameInputs spheres{sun_at(90, 30), {{{100.0, -100.0, 2000.0}, 20.0}}, std::nullopt};
  EXPECT_EQ(message(spheres, Product::Shadow), "no error");
  spheres.spheres[0].radius = 0.0;
  EXPECT_NE(message(spheres, Product::Shadow).find("radius > 0"), std::string::npos);
  EXPECT_NE(message({sun_at(90, 30), {}, -1.0}, Product::Shaded).find("exposure"), std::string::npos);
  EXPECT_NE(message({}, Product::Shadow).find("needs a sun"), std::string::npos);
}

}  // namespace
}  // namespace skylit::shading
