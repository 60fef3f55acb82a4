#include "pair_distances.hpp"

#include <algorithm>

namespace pneumachaos {

// Two clones, chosen once at load time, as in log_array.cpp: coordinate by coordinate over all
// steps, so the loads are contiguous and the loop vectorises four steps at a time with AVX2.
__attribute__((target_clones("avx2", "default"))) void squared_pair_distances(
    const double* a, const double* b, std::size_t dimension, std::size_t delay,
    std::span<double> d2) {
  double* __restrict out = d2.data();
  const std::size_t n = d2.size();
  std::fill(out, out + n, 0.0);
  for (std::size_t c = 0; c < dimension; ++c) {
    const double* __restrict p = a + c * delay;
    const double* __restrict q = b + c * delay;
    for (std::size_t k = 0; k < n; ++k) out[k] += (p[k] - q[k]) * (p[k] - q[k]);
  }
}

}  // namespace pneumachaos
