#include "app/tiles/tile_progress.h"

#include <cstdio>

namespace skylit::app::tiles {

TileProgress::TileProgress(long long total, bool quiet)
    : total_(total), quiet_(quiet), start_(std::chrono::steady_clock::now()), last_(start_) {}

void TileProgress::update(long long done) {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(1)) return;
  last_ = now;
  print(done);
}

void TileProgress::finish(long long done) {
  if (done != printed_) print(done);
}

void TileProgress::print(long long done) {
  if (quiet_) return;
  printed_ = done;
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = s > 0 ? done / s : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
  std::fprintf(stderr, "skylit: tiles %lld/%lld (%.0f%%), %.1f tiles/s, ETA %.0f s\n", done, total_,
               total_ > 0 ? 100.0 * done / total_ : 100.0, rate, eta);
}

}  // namespace skylit::app::tiles
