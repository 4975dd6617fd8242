// `skylit shade --time` with many instants (an interval START/END/STEP, a list, a date):
// one renderer, the DEM read and the horizons computed once, a frame per instant with
// its own sun and sky; frames written as app/shade/frame_outputs.h says, or summed into
// insolation or sun hours (shading/summed_products.h).
#pragma once

#include "app/shade/frame_outputs.h"
#include "shading/lighting.h"
#include "shading/renderer.h"
#include "shading/summed_products.h"
#include "terrain/height_field.h"

#include <functional>
#include <optional>
#include <vector>

namespace skylit::app::shade {

struct SeriesJob {
  shading::Product product = shading::Product::Shadow;  // rendered per frame
  std::optional<shading::SummedProduct> summed;         // set: the frames are summed
  std::vector<sky::UtcTime> instants;
  shading::LightingRequest request;  // everything but the time, which each frame sets
  std::optional<sky::Observer> place;
  // The sphere blockers of a frame at a time (UTC seconds); empty: none.
  std::function<std::vector<blockers::Sphere>(double unix_seconds)> spheres_at;
  FrameOutputs outputs;              // summed: one file
  bool quiet = false;
  bool timings = false;
};

// Renders and writes. On failure no file of this run is left behind.
void run_series(shading::Renderer& renderer, const terrain::HeightField& field, const SeriesJob& job);

}  // namespace skylit::app::shade
