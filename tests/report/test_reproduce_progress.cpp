// reproduce's progress under several threads (src/report/progress.hpp): the sweeps' workers
// report their runs while the plain line's ticker writes; the tests labelled `parallel` run
// this under ThreadSanitizer (scripts/test-tsan.sh).
#include <gtest/gtest.h>

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "report/progress.hpp"

namespace pneumachaos {
namespace {

TEST(ReproduceProgress, WorkersReportWhileTheTickerWrites) {
  std::mutex m;
  std::vector<std::pair<std::size_t, std::size_t>> seen;
  ::testing::internal::CaptureStderr();  // not a terminal: the plain line, on its ticker
  {
    ReproduceProgress progress(true, 2, 100,
                               [&](std::size_t done, std::size_t total) {
                                 const std::lock_guard<std::mutex> lock(m);
                                 seen.emplace_back(done, total);
                               },
                               std::chrono::milliseconds(5));
    progress.stage("first map");
    std::vector<std::thread> workers;
    for (int w = 0; w < 2; ++w) {
      workers.emplace_back([&progress] {
        for (std::size_t k = 1; k <= 50; ++k) {
          progress.sweep_runs(k);
          std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
      });
    }
    for (auto& t : workers) t.join();
    progress.runs_done(50);
    progress.stage("second map");
    progress.runs_done(60);  // more than the total: the count stops at it
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // ticks at 5 ms
  }
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(seen.size(), 102u);
  for (const auto& [done, total] : seen) {
    EXPECT_LE(done, total);
    EXPECT_EQ(total, 100u);
  }
  EXPECT_EQ(seen[100].first, 50u);
  EXPECT_EQ(seen.back().first, 100u);
  EXPECT_NE(log.find("reproduce: stage 2/2 (second map), 100 sweep runs done (at most 100)"),
            std::string::npos)
      << log;
}

}  // namespace
}  // namespace pneumachaos
