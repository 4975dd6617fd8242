// Merging shard archives (one `--shard i/N` run each) into one archive of any kind.
#pragma once

#include <string>
#include <vector>

#include "tiles/archive.h"

namespace skylit::tiles {

// Writes every tile of `inputs` (finished archives of any kinds) into the archive at
// `output`, opened with `options` (whose format is replaced by the inputs'). A tile in
// several inputs must have the same bytes in each: different bytes throw
// TileArchiveError before the output is opened, as do mixed formats and inputs made
// with different options (their fingerprints, tiles/fingerprint.h). The metadata is
// the first input's with zooms and bounds widened to cover every input.
void merge(const std::vector<std::string>& inputs, const std::string& output,
           const ArchiveOptions& options = {});

}  // namespace skylit::tiles
