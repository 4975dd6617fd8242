// Progress of a tile run on stderr: tiles done of the run's total, tiles per second and
// the time left, at most once a second (and once at the end); silent when quiet.
#pragma once

#include <chrono>
#include <string>

namespace skylit::app::tiles {

class TileProgress {
 public:
  TileProgress(long long total, bool quiet);
  // `done` tiles of the total are settled (written, skipped as complete, or empty).
  void update(long long done);
  void finish(long long done);

 private:
  void print(long long done);
  long long total_, printed_ = -1;
  bool quiet_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace skylit::app::tiles
