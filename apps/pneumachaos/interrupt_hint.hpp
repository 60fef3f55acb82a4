#pragma once
// Ctrl-C (or a TERM) during long work that keeps what it finished (a sweep's journal, a report's
// sweeps): a message says how to continue, then the signal ends the process as it would have.
// Only write(2) in the handler; an ignored SIGINT (a background job of a script) stays ignored.

#include <signal.h>
#include <unistd.h>

#include <string>
#include <utility>
#include <vector>

namespace pneumachaos::cli {

class InterruptHint {
 public:
  explicit InterruptHint(std::string message) {
    text() = std::move(message);
    for (int sig : {SIGINT, SIGTERM}) {
      struct sigaction now {}, before {};
      sigaction(sig, nullptr, &before);
      if (before.sa_handler == SIG_IGN) continue;
      now.sa_handler = &InterruptHint::handle;
      sigemptyset(&now.sa_mask);
      now.sa_flags = SA_RESETHAND;  // the second signal, or the re-raise, acts as the default
      sigaction(sig, &now, nullptr);
      restore_.push_back({sig, before});
    }
  }
  ~InterruptHint() {
    for (const auto& [sig, action] : restore_) sigaction(sig, &action, nullptr);
  }
  InterruptHint(const InterruptHint&) = delete;
  InterruptHint& operator=(const InterruptHint&) = delete;

 private:
  static std::string& text() {
    static std::string m;
    return m;
  }
  static void handle(int sig) {
    const std::string& m = text();
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, m.data(), m.size());
    ::raise(sig);  // SA_RESETHAND: the default action now ends the process
  }
  std::vector<std::pair<int, struct sigaction>> restore_;
};

}  // namespace pneumachaos::cli
