#include "stage_progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace pneumachaos::cli {
namespace {

// Work shorter than this shows nothing: a progress line that flashes past is noise.
constexpr std::chrono::seconds kQuietFor{2};
constexpr std::chrono::seconds kEvery{1};

}  // namespace

StageProgress::StageProgress(std::string command, bool show) : command_(std::move(command)) {
  if (show && ::isatty(STDERR_FILENO) != 0) ticker_ = std::thread([this] { tick(); });
}

StageProgress::~StageProgress() {
  if (!ticker_.joinable()) return;
  {
    std::lock_guard lock(m_);
    stop_ = true;
  }
  cv_.notify_all();
  ticker_.join();
  if (shown_) std::fputs("\r\033[K", stderr);  // the result follows on a clean line
}

void StageProgress::stage(const char* what) {
  std::lock_guard lock(m_);
  stage_ = what;
}

void StageProgress::tick() {
  std::unique_lock lock(m_);
  cv_.wait_for(lock, kQuietFor, [this] { return stop_; });
  while (!stop_) {
    const auto s =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start_);
    fmt::print(stderr, "\r{}: {} ({} s)\033[K", command_, stage_, s.count());
    std::fflush(stderr);
    shown_ = true;
    cv_.wait_for(lock, kEvery, [this] { return stop_; });
  }
}

}  // namespace pneumachaos::cli
