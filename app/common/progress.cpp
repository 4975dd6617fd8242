#include "app/common/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace skylit::app {

ProgressBar::ProgressBar(std::string label, bool quiet)
    : label_(std::move(label)), quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  if (tty_ && !quiet_ && last_percent_ >= 0 && !finished_) std::fputc('\n', stderr);
}

void ProgressBar::update(double fraction) {
  if (quiet_ || finished_) return;
  const int percent = static_cast<int>(std::clamp(fraction, 0.0, 1.0) * 100.0);
  // Without a terminal, print only every 10% so logs stay short.
  if (percent == last_percent_ || (!tty_ && percent / 10 == last_percent_ / 10 && last_percent_ >= 0)) return;
  last_percent_ = percent;
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (tty_) {
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r%s [%.*s%*s] %3d%% %6.1fs", label_.c_str(), filled, "##############################",
                 kWidth - filled, "", percent, secs);
  } else {
    std::fprintf(stderr, "%s: %d%% (%.1fs)\n", label_.c_str(), percent, secs);
  }
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (quiet_ || finished_) return;
  update(1.0);
  finished_ = true;
  if (tty_) std::fputc('\n', stderr);
}

}  // namespace skylit::app
