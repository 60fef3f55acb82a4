#pragma once
// The model's own Lyapunov exponent as text and as JSON (`pneumachaos lyapunov`).

#include <string>

#include "pneumachaos/simulate/model_lyapunov.hpp"

namespace pneumachaos {

/// Three lines: the exponent with its uncertainty (1/s and bits/s), how it was measured, and
/// eight points of its running estimate.
std::string lyapunov_summary(const ModelLyapunovResult& r, const ModelLyapunovOptions& o);

/// Every number with its unit: lyapunov.{lambda,uncertainty,bits}, the measuring settings,
/// renormalizations, postponed, and the running estimate as arrays.
std::string lyapunov_json(const ModelLyapunovResult& r, const ModelLyapunovOptions& o);

}  // namespace pneumachaos
