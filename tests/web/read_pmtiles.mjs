// Reads a .pmtiles archive with npm's `pmtiles` package (protomaps' own reader, not
// skylit's): prints one JSON object with the header, the metadata and the SHA-256 of
// every tile of every zoom within the header's bounds, for tests/cli_tiles_web_test.cpp.
// Usage: node read_pmtiles.mjs ARCHIVE.pmtiles
import { PMTiles } from "pmtiles";
import { createHash } from "node:crypto";
import { open } from "node:fs/promises";

class FileSource {
  constructor(path, handle) {
    this.path = path;
    this.handle = handle;
  }
  getKey() {
    return this.path;
  }
  async getBytes(offset, length) {
    const buffer = Buffer.alloc(length);
    const { bytesRead } = await this.handle.read(buffer, 0, length, offset);
    const data = buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + bytesRead);
    return { data };
  }
}

const path = process.argv[2];
const handle = await open(path, "r");
const archive = new PMTiles(new FileSource(path, handle));
const header = await archive.getHeader();
const metadata = await archive.getMetadata();

// Tiles of zoom z covering the header's bounds (XYZ rows, north first).
function range(z, h) {
  const n = 2 ** z;
  const x = (lon) => Math.min(n - 1, Math.max(0, Math.floor(((lon + 180) / 360) * n)));
  const y = (lat) => {
    const r = (lat * Math.PI) / 180;
    const t = (1 - Math.log(Math.tan(r) + 1 / Math.cos(r)) / Math.PI) / 2;
    return Math.min(n - 1, Math.max(0, Math.floor(t * n)));
  };
  return { x0: x(h.minLon), x1: x(h.maxLon), y0: y(h.maxLat), y1: y(h.minLat) };
}

const tiles = {};
for (let z = header.minZoom; z <= header.maxZoom; ++z) {
  const r = range(z, header);
  for (let x = r.x0; x <= r.x1; ++x)
    for (let y = r.y0; y <= r.y1; ++y) {
      const t = await archive.getZxy(z, x, y);
      if (t) tiles[`${z}/${x}/${y}`] = createHash("sha256").update(Buffer.from(t.data)).digest("hex");
    }
}
await handle.close();
const { minZoom, maxZoom, tileType, clustered, numAddressedTiles, numTileEntries, numTileContents, specVersion } =
  header;
console.log(
  JSON.stringify({
    header: { specVersion, minZoom, maxZoom, tileType, clustered, numAddressedTiles, numTileEntries, numTileContents },
    metadata,
    tiles,
  }),
);
