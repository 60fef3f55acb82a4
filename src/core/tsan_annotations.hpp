#pragma once
// The orderings oneTBB guarantees, stated for ThreadSanitizer. Debian's libtbb is not
// instrumented: the atomics with which it hands a task to a worker thread and reports its end
// are invisible to TSan, which then calls every read of the caller's data in a task a race
// with the main thread's writes before parallel_for. The TSan build (scripts/test-tsan.sh)
// marks the two edges parallel_for promises: what comes before it happens before every task,
// and every task before it returns. Tasks stay unordered among themselves, so a race between
// two workers is still reported. In every other build these are empty functions.
#if defined(__SANITIZE_THREAD__)
#define PNEUMACHAOS_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PNEUMACHAOS_TSAN 1
#endif
#endif

#ifdef PNEUMACHAOS_TSAN
#include <sanitizer/tsan_interface.h>
#endif

namespace pneumachaos::detail {

/// Everything this thread did so far happens before a later tsan_acquire(token).
inline void tsan_release([[maybe_unused]] void* token) {
#ifdef PNEUMACHAOS_TSAN
  __tsan_release(token);
#endif
}

/// Everything done before any earlier tsan_release(token) happens before what follows.
inline void tsan_acquire([[maybe_unused]] void* token) {
#ifdef PNEUMACHAOS_TSAN
  __tsan_acquire(token);
#endif
}

}  // namespace pneumachaos::detail
