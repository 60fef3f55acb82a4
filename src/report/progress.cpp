#include "progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <utility>

namespace pneumachaos {

ReproduceProgress::ReproduceProgress(bool show, int stages, std::size_t total_runs,
                                     Callback on_runs, std::chrono::milliseconds every)
    : stages_(stages), total_runs_(total_runs), on_runs_(std::move(on_runs)), every_(every) {
  terminal_ = show && ::isatty(STDERR_FILENO) != 0;
  plain_ = show && !terminal_;
  if (plain_) ticker_ = std::thread([this] { tick(); });
}

ReproduceProgress::~ReproduceProgress() {
  {
    std::lock_guard<std::mutex> lock(m_);
    stop_ = true;
  }
  cv_.notify_all();
  if (ticker_.joinable()) ticker_.join();
}

void ReproduceProgress::stage(const std::string& what) {
  std::lock_guard<std::mutex> lock(m_);
  ++done_;
  what_ = what;
  if (terminal_) fmt::print(stderr, "reproduce: [{}/{}] {}\n", done_, stages_, what);
}

void ReproduceProgress::runs_done(std::size_t runs) {
  std::size_t done = 0;
  {
    std::lock_guard<std::mutex> lock(m_);
    runs_ += runs;
    current_ = 0;
    done = done_locked();
  }
  report(done);
}

void ReproduceProgress::sweep_runs(std::size_t done_in_sweep) {
  std::size_t done = 0;
  {
    std::lock_guard<std::mutex> lock(m_);
    current_ = done_in_sweep;
    done = done_locked();
  }
  report(done);
}

std::size_t ReproduceProgress::done_locked() const {
  return std::min(total_runs_, runs_ + current_);
}

// Outside the lock: the callback may take its time (the Python module takes the GIL).
void ReproduceProgress::report(std::size_t done) const {
  if (on_runs_) on_runs_(done, total_runs_);
}

std::string ReproduceProgress::line_locked() const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  // The sweeps dominate the time: extrapolate from the runs finished so far.
  const std::size_t done = done_locked();
  // Adaptive maps run only part of their grid: the total and the time left are upper bounds.
  const std::string eta =
      done == 0 ? "time left unknown"
                : fmt::format("at most {:.0f} s left",
                              elapsed * double(total_runs_ - done) / double(done));
  return fmt::format("reproduce: stage {}/{} ({}), {} sweep runs done (at most {}), {:.0f} s "
                     "elapsed, {}",
                     done_, stages_, what_, done, total_runs_, elapsed, eta);
}

// One line every 10 s, never more often: a log gets a heartbeat, not a flood.
void ReproduceProgress::tick() {
  std::unique_lock<std::mutex> lock(m_);
  while (!cv_.wait_for(lock, every_, [this] { return stop_; })) {
    fmt::print(stderr, "{}\n", line_locked());
    std::fflush(stderr);
  }
}

}  // namespace pneumachaos
