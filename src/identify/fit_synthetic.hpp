#pragma once
// Synthetic "measured" records: a simulation of our own model degraded as an A/D rig
// degrades its signals (docs/notes/model_fit.md, "Accuracy reached"). For tests, benchmarks and trying `fit`.

#include <cstdint>

#include "pneumachaos/identify/measured_record.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos::identify {

struct RigDegradation {
  double pressure_noise_Pa = 300.0;        ///< sd of white noise on P1, P2
  double pressure_full_scale_Pa = 1.0e6;   ///< transducer range 0..this (absolute)
  double velocity_noise_m_per_s = 0.5e-3;  ///< sd of white noise on v
  double velocity_full_scale_m_per_s = 0.5;  ///< velocity channel range -this..+this
  int adc_bits = 12;                       ///< quantisation of every channel (0: none)
  bool keep_position = false;              ///< also record x (quantised like v's range / stroke)
};

/// Simulates `scenario` from the start of a run for duration_s at sample_rate_Hz (or until the
/// end of the stroke) and degrades P1, P2, v as `rig` says. Throws RunError if the
/// simulation fails.
MeasuredRecord synthetic_record(const Scenario& scenario, double duration_s,
                                const RigDegradation& rig = {}, std::uint64_t seed = 1,
                                double sample_rate_Hz = 1000.0);

}  // namespace pneumachaos::identify
