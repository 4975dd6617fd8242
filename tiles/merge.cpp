// Shards of one run hold disjoint tile sets (or equal copies of border tiles), so a
// merge is a union; every conflict is found before the output is opened, so a failed
// merge leaves no output behind.
#include "tiles/merge.h"

#include <algorithm>
#include <map>

#include "tiles/fingerprint.h"
#include "tiles/reader.h"

namespace skylit::tiles {

void merge(const std::vector<std::string>& inputs, const std::string& output,
           const ArchiveOptions& options) {
  if (inputs.empty()) throw TileArchiveError("'" + output + "': merge of no inputs");
  std::vector<std::unique_ptr<TileReader>> readers;
  for (const auto& in : inputs) readers.push_back(open_reader(in));

  TileMetadata m = readers.front()->metadata();
  std::map<TileId, std::size_t> source;  // tile → the first input holding it
  for (std::size_t i = 0; i < readers.size(); ++i) {
    const TileMetadata& mi = readers[i]->metadata();
    if (mi.format != m.format)
      throw TileArchiveError("'" + inputs[i] + "': format " + std::string(format_name(mi.format)) +
                             " differs from '" + inputs[0] + "' (" + std::string(format_name(m.format)) + ")");
    // Tiles made with other options (zooms, light, DEM, …) must not be mixed; shards of
    // one run record the same options (the shard is not among them).
    if (mi.fingerprint != m.fingerprint)
      throw TileArchiveError("'" + inputs[i] + "': made with other options than '" + inputs[0] + "': " +
                             fingerprint_difference(m.fingerprint.value_or(""), mi.fingerprint.value_or(""),
                                                    "'" + inputs[0] + "'", "'" + inputs[i] + "'")
                                 .value_or("one of them records no options"));
    m.minzoom = std::min(m.minzoom, mi.minzoom);
    m.maxzoom = std::max(m.maxzoom, mi.maxzoom);
    m.bounds = {std::min(m.bounds.west, mi.bounds.west), std::min(m.bounds.south, mi.bounds.south),
                std::max(m.bounds.east, mi.bounds.east), std::max(m.bounds.north, mi.bounds.north)};
    for (const auto& t : readers[i]->tiles()) {
      const auto [it, inserted] = source.emplace(t, i);
      if (!inserted && readers[it->second]->get(t) != readers[i]->get(t))
        throw TileArchiveError("'" + inputs[i] + "': tile " + to_string(t) + " differs from '" +
                               inputs[it->second] + "'s");
    }
  }

  ArchiveOptions out_options = options;
  out_options.format = m.format;
  out_options.fingerprint = m.fingerprint.value_or("");
  const auto out = open_archive(output, out_options);
  for (const auto& [t, i] : source) {
    if (out->has(t) && options.mode == OpenMode::Resume) continue;
    out->put(t, as_bytes(*readers[i]->get(t)));
  }
  out->finish(m);
}

}  // namespace skylit::tiles
