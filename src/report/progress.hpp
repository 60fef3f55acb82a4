#pragma once
// reproduce's progress: on a terminal one line per stage; otherwise (a log, CI) a plain line
// at most every 10 s with the stage, the sweep runs done and an estimate of the time left,
// so a redirected run is never silent for long and never floods its log (docs/report.md).

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace pneumachaos {

class ReproduceProgress {
 public:
  /// Called with the runs done and total_runs whenever the count moves.
  using Callback = std::function<void(std::size_t done, std::size_t total)>;
  /// total_runs: the sweep runs of the whole report (the bulk of its time). every: the plain
  /// line's interval (10 s; a test shortens it).
  ReproduceProgress(bool show, int stages, std::size_t total_runs, Callback on_runs = {},
                    std::chrono::milliseconds every = std::chrono::seconds(10));
  ~ReproduceProgress();
  ReproduceProgress(const ReproduceProgress&) = delete;
  ReproduceProgress& operator=(const ReproduceProgress&) = delete;

  void stage(const std::string& what);
  void runs_done(std::size_t runs);  ///< add the runs of a finished sweep
  /// The runs of the sweep under way finished so far (the sweep's progress callback).
  void sweep_runs(std::size_t done_in_sweep);

 private:
  void tick();
  [[nodiscard]] std::string line_locked() const;
  [[nodiscard]] std::size_t done_locked() const;
  void report(std::size_t done) const;

  bool terminal_ = false, plain_ = false;
  int stages_, done_ = 0;
  std::size_t total_runs_, runs_ = 0, current_ = 0;
  std::string what_;
  Callback on_runs_;
  std::chrono::milliseconds every_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread ticker_;
};

}  // namespace pneumachaos
