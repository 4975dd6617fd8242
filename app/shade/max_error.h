// `skylit shade --max-error E`: the cheapest setting of the measured front
// (data/quality/front.csv, shading/quality_front.h) whose error meets E; quality knobs
// given explicitly win, with a note.
#pragma once

#include "shading/products.h"

#include "app/common/cli_fwd.h"

#include <optional>
#include <string>

namespace skylit::app::shade {

// The front file: $SKYLIT_QUALITY_FRONT, else data/quality/front.csv of the source tree.
std::string quality_front_path();

// Checks E and the product (svf, skyview, shaded) and applies the picked point to
// `options` before the caller's explicit knobs; returns the notes for stderr (the
// choice, and which explicit knobs win). Throws std::invalid_argument (one line).
std::string apply_max_error(double max_error, const std::string& product, const CLI::App& cmd,
                            shading::ProductOptions& options);

}  // namespace skylit::app::shade
