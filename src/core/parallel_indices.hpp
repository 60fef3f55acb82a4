#pragma once
// Runs a function for every index of [0, count) on oneTBB's worker threads, with the two
// orderings parallel_for guarantees stated for ThreadSanitizer (tsan_annotations.hpp). Inside a
// task_arena the threads are the arena's, so a caller that limits them (the sweep's --threads)
// limits work nested below it too. Private to the library's modules; they link oneTBB.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>

#include <cstddef>

#include "parallel_body.hpp"
#include "tsan_annotations.hpp"

namespace pneumachaos::detail {

/// one(k) for k = 0 .. count - 1, one index per task (grain 1), in no particular order; an
/// exception thrown by one(k) is rethrown here after the other tasks are cancelled.
template <typename One>
void parallel_indices(std::size_t count, One& one) {
  char handed_out = 0, handed_back = 0;
  tsan_release(&handed_out);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                    ParallelBody<One>{&one, &handed_out, &handed_back},
                    tbb::simple_partitioner());
  tsan_acquire(&handed_back);
}

}  // namespace pneumachaos::detail
