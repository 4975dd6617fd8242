// A progress bar on stderr for long work: redrawn in place when stderr is a
// terminal, a few plain percentage lines otherwise; silent when quiet.
#pragma once

#include <chrono>
#include <string>

namespace skylit::app {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool quiet);
  ~ProgressBar();
  // fraction in [0, 1]; thread-safe enough to call from one worker at a time.
  void update(double fraction);
  void finish();

 private:
  std::string label_;
  bool quiet_;
  bool tty_;
  bool finished_ = false;
  int last_percent_ = -1;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace skylit::app
