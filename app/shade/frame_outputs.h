// Where the frames of a time series go (`shade --time START/END/STEP`, a list, a date):
// one file per frame when OUTPUT holds a %d-style pattern (frames/shadow_%04d.png,
// frame numbers from 0 as ffmpeg reads them), else one multi-band GeoTIFF with one band
// per time (its ISO time as the band description). Every check is made before the first
// frame renders (after the DEM is read: a date's frames depend on its place).
#pragma once

#include "app/common/frame_pattern.h"
#include "app/shade/shade_output.h"
#include "shading/products.h"
#include "shading/sky/time_utc.h"

#include <optional>
#include <string>
#include <vector>

namespace skylit::app::shade {

struct FrameOutputs {
  std::vector<OutputSpec> files;  // one per frame (pattern), or one multi-band file
  bool per_frame = false;
};

// Throws std::invalid_argument (one line): several frames without a pattern in a
// format other than GTiff/COG; a multi-band file larger than `max_bytes`; any check of
// resolve_output on any frame's file.
FrameOutputs resolve_frame_outputs(const std::string& path, const std::string& format, shading::Product product,
                                   const std::vector<std::string>& creation_options, bool overwrite, int frames,
                                   std::size_t bytes_per_frame, std::size_t max_bytes);

// The bands of frame k named for the multi-band file: "2026-06-21T09:30:00Z" (grey) or
// "2026-06-21T09:30:00Z red" (colour).
std::vector<std::string> frame_band_names(const shading::ProductBands& frame, sky::UtcTime t);

}  // namespace skylit::app::shade
