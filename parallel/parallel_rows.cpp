#include "parallel/parallel_rows.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace skylit::parallel {

void parallel_rows(int rows, unsigned threads, const std::function<void(int)>& body,
                   const ProgressCallback& progress) {
  if (rows <= 0) return;
  unsigned n = threads ? threads : std::max(1u, std::thread::hardware_concurrency());
  n = std::min<unsigned>(n, static_cast<unsigned>(rows));
  std::atomic<int> next{0};
  int done = 0;
  std::mutex mutex;  // guards done, error and the progress callback
  std::exception_ptr error;
  auto worker = [&] {
    for (int row; (row = next.fetch_add(1)) < rows;) {
      try {
        body(row);
        std::lock_guard lock(mutex);
        ++done;
        if (progress && !error) progress(static_cast<double>(done) / rows);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = rows;
        return;
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < n; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace skylit::parallel
