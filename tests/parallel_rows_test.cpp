// parallel::parallel_rows: every row once on any number of threads, progress that rises
// to 1, and a body's exception stopping the rows not yet started and reaching the caller.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "parallel/parallel_rows.h"

namespace skylit::parallel {
namespace {

TEST(ParallelRows, EveryRowOnceAndProgressRisingToOne) {
  for (unsigned threads : {0u, 1u, 2u, 7u, 64u})
    for (int rows : {0, 1, 5, 1000}) {
      std::vector<std::atomic<int>> calls(static_cast<std::size_t>(rows));
      std::vector<double> reported;
      std::mutex mutex;
      parallel_rows(rows, threads, [&](int r) { ++calls[static_cast<std::size_t>(r)]; },
                    [&](double f) {
                      std::lock_guard lock(mutex);
                      reported.push_back(f);
                    });
      for (int r = 0; r < rows; ++r) EXPECT_EQ(calls[static_cast<std::size_t>(r)], 1) << threads << " " << r;
      ASSERT_EQ(reported.size(), static_cast<std::size_t>(rows));
      for (std::size_t k = 1; k < reported.size(); ++k) EXPECT_GT(reported[k], reported[k - 1]);
      if (rows > 0) {
        EXPECT_DOUBLE_EQ(reported.back(), 1.0);
      }
    }
}

TEST(ParallelRows, TheFirstExceptionStopsTheRestAndReachesTheCaller) {
  for (unsigned threads : {1u, 2u, 4u}) {
    std::atomic<int> ran{0};
    EXPECT_THROW(parallel_rows(100000, threads,
                               [&](int r) {
                                 ++ran;
                                 if (r == 10) throw std::runtime_error("row 10");
                               }),
                 std::runtime_error);
    EXPECT_LT(ran.load(), 100000) << "rows after the failure were not all run: " << threads;
  }
}

}  // namespace
}  // namespace skylit::parallel
