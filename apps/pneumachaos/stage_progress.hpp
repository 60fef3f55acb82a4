#pragma once
// Progress of one long computation reported by stages (analyze on a long record): on a
// terminal, once the work has run 2 s, one line on standard error naming the stage and the
// time so far, rewritten at most once a second and cleared at the end; nothing when standard
// error is not a terminal or with --quiet, so logs and pipes stay clean.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace pneumachaos::cli {

class StageProgress {
 public:
  /// command: the line's prefix ("analyze"); show: false for --quiet.
  StageProgress(std::string command, bool show);
  ~StageProgress();
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

  /// The stage now under way (thread-safe; cheap: the ticker prints it).
  void stage(const char* what);

 private:
  void tick();

  std::string command_, stage_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  bool shown_ = false;  ///< a line is on the terminal, to be cleared
  std::mutex m_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread ticker_;
};

/// f() with a progress line for one stage: `command: stage (N s)`.
template <class F>
auto with_progress(const char* command, const char* stage, bool show, F&& f) {
  StageProgress progress(command, show);
  progress.stage(stage);
  return f();
}

}  // namespace pneumachaos::cli
