// Helpers for the tile-archive tests: tile sets with known bytes, an archive's whole
// content as a map, and raw file bytes (the scratch directory is terrain's).
#pragma once

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "terrain_test_util.h"
#include "tiles/archive.h"
#include "tiles/reader.h"

namespace skylit::tiles::testing {

namespace fs = std::filesystem;

using terrain::testing::ScratchDir;

using Content = std::map<TileId, std::string>;

// A deterministic payload per tile (its address and a filler of varying length), so
// distinct tiles have distinct bytes and a mixed-up tile is caught.
inline std::string payload(const TileId& t, std::size_t filler = 0) {
  std::string s = "tile " + to_string(t) + ";";
  s.append(filler ? filler : 1 + (t.x * 7 + t.y * 13 + static_cast<unsigned>(t.z)) % 23, 'a' + t.z);
  return s;
}

// Every tile of zooms [z0, z1] (small zooms: 4^z tiles each).
inline Content pyramid(int z0, int z1) {
  Content c;
  for (int z = z0; z <= z1; ++z)
    for (int x = 0; x < (1 << z); ++x)
      for (int y = 0; y < (1 << z); ++y) c[{z, x, y}] = payload({z, x, y});
  return c;
}

inline TileMetadata sample_metadata(TileFormat f = TileFormat::Png) {
  TileMetadata m;
  m.name = "skylit test";
  m.format = f;
  m.bounds = {6.5, 45.75, 7.25, 46.5};
  m.center = {6.875, 46.125, 3};
  m.minzoom = 0;
  m.maxzoom = 3;
  m.description = "hillshade";
  m.attribution = "skylit";
  m.type = "overlay";
  return m;
}

inline void write_all(TileArchive& a, const Content& c) {
  for (const auto& [t, bytes] : c) a.put(t, as_bytes(bytes));
}

inline void write_archive(const std::string& path, const Content& c, ArchiveOptions o = {},
                          const TileMetadata& m = sample_metadata()) {
  auto a = open_archive(path, o);
  write_all(*a, c);
  a->finish(m);
}

inline Content read_content(const std::string& path) {
  const auto r = open_reader(path);
  Content c;
  for (const auto& t : r->tiles()) c[t] = r->get(t).value();
  return c;
}

inline std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return std::move(s).str();
}

// Runs a shell command, returns its stdout.
inline std::string shell(const std::string& cmd) {
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  ::pclose(p);
  return out;
}

inline std::uint64_t le(const std::string& bytes, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= std::uint64_t{static_cast<unsigned char>(bytes.at(at + i))} << (8 * i);
  return v;
}

}  // namespace skylit::tiles::testing
