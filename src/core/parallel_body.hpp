#pragma once
// The body of parallel_indices's parallel_for (parallel_indices.hpp): runs `one` for each index
// of a range between the ThreadSanitizer hand-over marks (tsan_annotations.hpp). It lives in its
// own file because scripts/tsan.supp names this file: the body's own accesses are only the
// reads of its members, which oneTBB copies into task objects that its uninstrumented library
// recycles between threads unseen by TSan. Whatever `one` does is outside this file and
// stays fully checked.
#include <tbb/blocked_range.h>

#include <cstddef>

#include "tsan_annotations.hpp"

namespace pneumachaos::detail {

template <typename One>
struct ParallelBody {
  One* one;
  char* handed_out;   ///< released before parallel_for: acquired by each task
  char* handed_back;  ///< released by each task: acquired after parallel_for returns
  void operator()(const tbb::blocked_range<std::size_t>& range) const {
    tsan_acquire(handed_out);
    for (std::size_t k = range.begin(); k != range.end(); ++k) (*one)(k);
    tsan_release(handed_back);
  }
};

}  // namespace pneumachaos::detail
