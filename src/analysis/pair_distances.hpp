#pragma once
// Squared distances between two delay vectors at every step of a divergence curve: with the
// logarithms (log_array.hpp), the inner loop of the divergence exponent.

#include <cstddef>
#include <span>

namespace pneumachaos {

/// d2[k] = sum over c < dimension of (a[c delay + k] - b[c delay + k])^2 for every k of d2:
/// the squared distance, k steps on, between the delay vectors starting at a and at b. Each
/// d2[k] adds its coordinates in order, with no fused multiply-add, so the result is the same
/// bit for bit on every x86-64 machine although the loop is vectorised for the processor at
/// hand (AVX2 or the baseline).
void squared_pair_distances(const double* a, const double* b, std::size_t dimension,
                            std::size_t delay, std::span<double> d2);

}  // namespace pneumachaos
