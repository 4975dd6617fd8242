// Opens a `skylit tiles -w leaflet` page in Debian's headless chromium (puppeteer-core)
// through a small static server that answers Range requests, waits until every visible
// tile has loaded, saves a screenshot, and compares the screenshot with the tiles the
// page shows: every opaque tile pixel must appear on screen as the PNG holds it.
// Prints one JSON line; exit status 0 when at least one tile showed and fewer than 0.1 %
// of the compared pixels differ by more than 2 codes.
// Usage: node viewer_test.mjs ROOT PAGE SCREENSHOT.png [WIDTH HEIGHT]
import { createServer } from "node:http";
import { readFile, stat, writeFile } from "node:fs/promises";
import { extname, join, normalize } from "node:path";
import puppeteer from "puppeteer-core";

const [root, pageName, screenshotPath, width = "768", height = "512"] = process.argv.slice(2);
const types = { ".html": "text/html", ".png": "image/png", ".pmtiles": "application/vnd.pmtiles", ".json": "application/json" };
let rangeRequests = 0;

const server = createServer(async (req, res) => {
  try {
    const path = normalize(join(root, decodeURIComponent(new URL(req.url, "http://x").pathname)));
    if (!path.startsWith(normalize(root))) throw new Error("outside the root");
    const info = await stat(path);
    const body = await readFile(path);
    const headers = { "Content-Type": types[extname(path)] ?? "application/octet-stream", "Accept-Ranges": "bytes" };
    const range = /^bytes=(\d+)-(\d*)$/.exec(req.headers.range ?? "");
    if (range) {
      ++rangeRequests;
      const start = Number(range[1]), end = Math.min(range[2] ? Number(range[2]) : info.size - 1, info.size - 1);
      res.writeHead(206, { ...headers, "Content-Range": `bytes ${start}-${end}/${info.size}`, "Content-Length": end - start + 1 });
      res.end(body.subarray(start, end + 1));
    } else {
      res.writeHead(200, { ...headers, "Content-Length": info.size });
      res.end(body);
    }
  } catch {
    res.writeHead(404);
    res.end();
  }
});
await new Promise((ok) => server.listen(0, "127.0.0.1", ok));
const port = server.address().port;

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM ?? "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
  defaultViewport: { width: Number(width), height: Number(height), deviceScaleFactor: 1 },
});
let result = {};
try {
  const page = await browser.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(String(e)));
  await page.goto(`http://127.0.0.1:${port}/${pageName}`);
  await page.waitForFunction(() => window.skylitTilesLoaded === true, { timeout: 60000 });
  await new Promise((ok) => setTimeout(ok, 300));  // let the last tiles paint
  const png = await page.screenshot({ type: "png" });
  await writeFile(screenshotPath, png);
  result = await page.evaluate(async (shot) => {
    const load = (src) => new Promise((ok, fail) => { const i = new Image(); i.onload = () => ok(i); i.onerror = fail; i.src = src; });
    const screen = await load("data:image/png;base64," + shot);
    const sc = document.createElement("canvas");
    sc.width = screen.width, sc.height = screen.height;
    const sctx = sc.getContext("2d");
    sctx.drawImage(screen, 0, 0);
    const shown = sctx.getImageData(0, 0, sc.width, sc.height).data;
    let tiles = 0, compared = 0, mismatched = 0;
    const keys = [];
    for (const t of Object.values(window.skylitLayer._tiles)) {
      const img = t.el;
      if (!img.complete || !img.naturalWidth) continue;
      const r = img.getBoundingClientRect();
      if (r.width !== img.naturalWidth || r.height !== img.naturalHeight) continue;  // scaled: not comparable
      const tc = document.createElement("canvas");
      tc.width = img.naturalWidth, tc.height = img.naturalHeight;
      const tctx = tc.getContext("2d");
      tctx.drawImage(img, 0, 0);
      const px = tctx.getImageData(0, 0, tc.width, tc.height).data;
      let any = false;
      for (let y = 0; y < tc.height; ++y)
        for (let x = 0; x < tc.width; ++x) {
          const sx = Math.round(r.left) + x, sy = Math.round(r.top) + y;
          if (sx < 0 || sy < 0 || sx >= sc.width || sy >= sc.height) continue;
          const k = 4 * (y * tc.width + x), s = 4 * (sy * sc.width + sx);
          if (px[k + 3] !== 255) continue;
          any = true, ++compared;
          if (Math.max(Math.abs(px[k] - shown[s]), Math.abs(px[k + 1] - shown[s + 1]), Math.abs(px[k + 2] - shown[s + 2])) > 2) ++mismatched;
        }
      if (any) ++tiles, keys.push(`${t.coords.z}/${t.coords.x}/${t.coords.y}`);
    }
    return { tiles, compared, mismatched, keys, zoom: window.skylitMap.getZoom() };
  }, Buffer.from(png).toString("base64"));
  result.errors = errors;
} finally {
  await browser.close();
  server.close();
}
result.range_requests = rangeRequests;
console.log(JSON.stringify(result));
process.exit(result.tiles > 0 && result.mismatched <= 0.001 * result.compared && result.errors.length === 0 ? 0 : 1);
